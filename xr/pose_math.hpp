// SPDX-License-Identifier: Apache-2.0
// Rigid poses in double precision (glm) and their conversion to and from XrPosef, and the pose
// of a gaze ray (-Z along the gaze, +X level: no roll, as XR_EXT_eye_gaze_interaction poses
// are; the orientation is auxiliary/yaw_pitch.hpp's). Shared by the simulated runtime
// (sim/runtime/) and the eye-gaze API layer (layer/): one definition of each.
// Needs only <openxr/openxr.h>; include the caller's own OpenXR header set first when it enables
// platform types.
#pragma once

#include <openxr/openxr.h>

#include "auxiliary/yaw_pitch.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <optional>

namespace gazelod::xr {

struct Pose {
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 position{0.0};
};

// b expressed in a's frame, composed: a * b.
inline Pose compose(const Pose& a, const Pose& b) {
  return {glm::normalize(a.orientation * b.orientation), a.position + a.orientation * b.position};
}
inline Pose inverse(const Pose& a) {
  const glm::dquat inv = glm::conjugate(a.orientation);
  return {inv, -(inv * a.position)};
}
inline Pose from_xr(const XrPosef& p) {
  return {glm::normalize(glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z)),
          glm::dvec3(p.position.x, p.position.y, p.position.z)};
}
inline XrPosef to_xr(const Pose& p) {
  XrPosef out{};
  out.orientation = {static_cast<float>(p.orientation.x), static_cast<float>(p.orientation.y),
                     static_cast<float>(p.orientation.z), static_cast<float>(p.orientation.w)};
  out.position = {static_cast<float>(p.position.x), static_cast<float>(p.position.y), static_cast<float>(p.position.z)};
  return out;
}
inline XrVector3f to_xr(const glm::dvec3& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

// A unit quaternion within the OpenXR specification's tolerance (XR_ERROR_POSE_INVALID otherwise).
inline bool is_unit_orientation(const XrPosef& p) {
  const double n = double(p.orientation.x) * p.orientation.x + double(p.orientation.y) * p.orientation.y +
                   double(p.orientation.z) * p.orientation.z + double(p.orientation.w) * p.orientation.w;
  return std::isfinite(n) && std::abs(n - 1.0) < 1e-2;
}

// A gaze ray as a pose in its tracker's frame: at origin_m, -Z along `direction` (any length),
// no roll. nullopt for a direction that is NaN, infinite or shorter than 1e-9, or an origin
// that is not finite: no NaN reaches a pose.
inline std::optional<Pose> gaze_ray_pose(const glm::dvec3& direction, const glm::dvec3& origin_m) {
  const double len = glm::length(direction);
  if (!std::isfinite(len) || !(len > 1e-9)) return std::nullopt;
  if (!std::isfinite(origin_m.x) || !std::isfinite(origin_m.y) || !std::isfinite(origin_m.z)) return std::nullopt;
  return Pose{aux::orientation_along(direction / len), origin_m};
}

}  // namespace gazelod::xr
