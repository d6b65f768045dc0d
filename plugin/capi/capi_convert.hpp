// SPDX-License-Identifier: Apache-2.0
// Conversions between the C ABI's plain structs and the engine's types, each with the checks
// that name the field at fault (Refusal, plugin/capi/capi_errors.hpp).
#pragma once

#include "gazelod/gazelod.h"
#include "plugin/lod_core.hpp"
#include "plugin/lod_plugin.hpp"
#include "plugin/pushed_gaze.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace gazelod::capi {

template <typename Handle>
Handle from_handle(std::uint64_t h) {
  // XR handles are pointers on 64-bit platforms and uint64_t on 32-bit ones.
  if constexpr (sizeof(Handle) == sizeof(std::uint64_t) && !std::is_pointer_v<Handle>) {
    return static_cast<Handle>(h);
  } else {
    return reinterpret_cast<Handle>(static_cast<std::uintptr_t>(h));
  }
}
template <typename Handle>
std::uint64_t to_handle(Handle h) {
  if constexpr (std::is_pointer_v<Handle>) {
    return static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(h));
  } else {
    return static_cast<std::uint64_t>(h);
  }
}

PluginConfig to_plugin_config(const gzl_config* c);
OpenXrOptions to_openxr_options(const gzl_openxr_create_info& info);

// 1, 2 or 4 views with a valid FOV and resolution; returns the count. `optional`: a count of 0
// is allowed (keep the previous views).
std::uint32_t check_views(std::uint32_t count, const gzl_view* views, const char* what, bool optional);
plugin::ViewInput to_view_input(const gzl_view& v);
gzl_view to_gzl_view(const plugin::ViewInput& v);

// A finite vector / a finite, non-zero quaternion (normalised unless already unit), or a Refusal.
glm::dvec3 to_vec(const gzl_vec3& v, const char* what);
glm::dquat to_quat(const gzl_quat& q, const char* what);
gzl_vec3 to_gzl(const glm::dvec3& v);
gzl_quat to_gzl(const glm::dquat& q);

// An object's levels in the engine's terms; engine-style metrics are converted with the
// display's vertical resolution.
std::vector<lod::LodLevel> to_levels(const gzl_object_desc& d, int view_height_px);

plugin::PushedSample to_pushed(const gzl_gaze_sample& s);
gzl_gaze_sample to_gzl_sample(const plugin::GazeRead& g);
// Head pose flags -> the engine's HeadMotion (Refusal for NaN in a field the flags use).
plugin::HeadMotion to_head(const gzl_head_pose& h, bool& angular_given, bool& linear_given);
gzl_head_pose to_gzl_head(const plugin::HeadMotion& h);

}  // namespace gazelod::capi
