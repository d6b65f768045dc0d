// SPDX-License-Identifier: Apache-2.0
// The C ABI's one error policy: every entry point runs its body through guarded(), which turns
// a refusal into a result code plus a message ("gazelod: ..." with the remedy) on the plugin (or
// on the calling thread, for a failed create) and never lets an exception cross the boundary.
#pragma once

#include "gazelod/gazelod.h"
#include "plugin/capi/capi_plugin.hpp"

#include <cstdint>
#include <cstring>
#include <exception>
#include <mutex>
#include <new>
#include <string>

namespace gazelod::capi {

// A refusal with its result code; the message says what and where ("gazelod: <field>: ...").
struct Refusal {
  gzl_result result;
  std::string message;
};

// The calling thread's last create failure (gzl_get_last_error with a NULL plugin).
std::string& thread_error();

void set_error(gzl_plugin p, const std::string& message);
gzl_result fail(gzl_plugin p, gzl_result r, const std::string& message);

// Runs body() -> gzl_result; maps exceptions: Refusal -> its code, XrCallError ->
// GZL_ERROR_OPENXR_CALL, std::invalid_argument / out_of_range -> GZL_ERROR_INVALID_ARGUMENT,
// bad_alloc -> GZL_ERROR_OUT_OF_MEMORY, anything else -> GZL_ERROR_INTERNAL.
template <typename Body>
gzl_result guarded(gzl_plugin p, Body&& body) noexcept;

// "gazelod: " in front of a message that lacks it.
std::string prefixed(const std::string& message);

// An enum field as the integer the caller stored (a C caller may store any value; reading it
// as the C++ enum would be undefined outside the enum's range).
template <typename E>
std::int32_t enum_value(const E& e) {
  static_assert(sizeof(E) == sizeof(std::int32_t));
  std::int32_t v;
  std::memcpy(&v, &e, sizeof v);
  return v;
}

// Times gazelod takes: within +-2^62 ns (146 years), so that differences of two of them and a
// lead of seconds added to one never overflow.
inline constexpr std::int64_t kMaxTimeNs = std::int64_t{1} << 62;
inline void need_time(std::int64_t t_ns, const char* what) {
  if (t_ns < -kMaxTimeNs || t_ns > kMaxTimeNs)
    throw Refusal{GZL_ERROR_INVALID_ARGUMENT, std::string("gazelod: ") + what + " = " + std::to_string(t_ns) +
                                                  " ns is outside +-2^62 ns: pass times on the frame loop's clock"};
}

// The common checks of an entry point that takes a plugin and an input struct.
void need_plugin(gzl_plugin p);
void need_live(gzl_plugin p);  // need_plugin, and not shut down
// The plugin lock for a call that changes the plugin, with need_live checked again under it.
std::unique_lock<std::mutex> lock_live(gzl_plugin p);
template <typename T>
void need_struct(const T* s, gzl_structure_type type, const char* what) {
  if (s == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, std::string("gazelod: ") + what + " is NULL"};
  if (enum_value(s->type) != static_cast<std::int32_t>(type))
    throw Refusal{GZL_ERROR_STRUCT_TYPE, std::string("gazelod: ") + what + "->type is " +
                                             std::to_string(enum_value(s->type)) + ", expected " +
                                             std::to_string(type) + " (set it to its GZL_TYPE_ value)"};
}

}  // namespace gazelod::capi

#include "plugin/capi/capi_errors_inl.hpp"
