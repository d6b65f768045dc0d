// SPDX-License-Identifier: Apache-2.0
// Object handles of the C ABI (include/gazelod/gazelod.h, gzl_object): a slot map. A handle is
//   (plugin tag << 48) | (generation << 32) | (index + 1)
// The index picks a row of the per-handle tables; a removed object's row is reused by a later
// gzl_add_object with the next generation, so the tables are as long as the most objects ever
// live at once (not as the handles ever issued: a streaming world adds and removes forever).
// A handle value is still never issued twice: a row whose generation is spent is retired, not
// reused. The tag tells one plugin's handles from another's (handles from another plugin are
// refused, not taken for this plugin's rows). Plain data, no locking: the plugin's locks guard it
// (capi_plugin.hpp says which).
#pragma once

#include "gazelod/gazelod.h"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace gazelod::capi {

inline constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();
inline constexpr std::uint16_t kLastGeneration = std::numeric_limits<std::uint16_t>::max();
// Rows at most: index + 1 must fit the low 32 bits and stay clear of kNoSlot.
inline constexpr std::uint32_t kMaxRows = kNoSlot - 1;

struct HandleParts {
  std::uint16_t tag = 0;
  std::uint16_t generation = 0;
  std::uint32_t index = 0;  // kNoSlot for a handle whose low bits are 0 (never issued)
};

inline gzl_object make_handle(std::uint16_t tag, std::uint16_t generation, std::uint32_t index) {
  return (static_cast<gzl_object>(tag) << 48) | (static_cast<gzl_object>(generation) << 32) |
         (static_cast<gzl_object>(index) + 1);
}

inline HandleParts split_handle(gzl_object h) {
  const auto low = static_cast<std::uint32_t>(h & 0xffffffffu);
  return {static_cast<std::uint16_t>(h >> 48), static_cast<std::uint16_t>(h >> 32), low == 0 ? kNoSlot : low - 1};
}

// A tag for a new plugin: a process-wide counter, never 0.
std::uint16_t next_plugin_tag();

// The rows' state that readers of a published frame need too (under the publication lock).
struct HandleRows {
  std::vector<std::uint16_t> generation;  // the generation of the row's current (or last) handle
  std::vector<std::uint8_t> live;         // 1 while the row's handle names an object

  // Why `h` names no live object of the plugin tagged `tag` ("" when it does), for messages.
  std::string refuse(gzl_object h, std::uint16_t tag) const {
    const HandleParts k = split_handle(h);
    if (h == GZL_NULL_OBJECT || k.tag != tag || k.index >= live.size() || k.generation > generation[k.index])
      return "was never issued by this plugin";
    if (k.generation < generation[k.index] || !live[k.index]) return "was removed";
    return "";
  }
};

}  // namespace gazelod::capi
