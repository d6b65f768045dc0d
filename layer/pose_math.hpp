// Rigid poses in double precision and XrPosef conversion, and the eye-gaze pose of a gaze
// sample: orientation whose -Z is the gaze direction, yaw then pitch so the pose's +X stays
// level (no roll), as XR_EXT_eye_gaze_interaction poses are (+Y up, -Z forward).
#pragma once

#include "layer/xr_headers.hpp"

#include "gaze/gaze_sample.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <optional>

namespace gazelod::layer {

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
  out.position = {static_cast<float>(p.position.x), static_cast<float>(p.position.y),
                  static_cast<float>(p.position.z)};
  return out;
}

// A unit quaternion within the OpenXR specification's tolerance (XR_ERROR_POSE_INVALID otherwise).
inline bool is_unit_orientation(const XrPosef& p) {
  const double n = double(p.orientation.x) * p.orientation.x + double(p.orientation.y) * p.orientation.y +
                   double(p.orientation.z) * p.orientation.z + double(p.orientation.w) * p.orientation.w;
  return std::isfinite(n) && std::abs(n - 1.0) < 1e-2;
}

// Orientation whose -Z axis points along `dir` (any length > 0), no roll.
inline glm::dquat gaze_orientation(const glm::dvec3& dir) {
  const double yaw = std::atan2(-dir.x, -dir.z);
  const double pitch = std::atan2(dir.y, std::hypot(dir.x, dir.z));
  return glm::normalize(glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * glm::angleAxis(pitch, glm::dvec3(1, 0, 0)));
}

// The sample as a pose in the tracker's frame; nullopt for an invalid or degenerate sample
// (no NaN reaches a pose).
inline std::optional<Pose> eye_pose(const gaze::GazeSample& s) {
  const double len = glm::length(s.direction);
  if (!s.valid || !std::isfinite(len) || !(len > 1e-9)) return std::nullopt;
  if (!std::isfinite(s.origin_m.x) || !std::isfinite(s.origin_m.y) || !std::isfinite(s.origin_m.z))
    return std::nullopt;
  return Pose{gaze_orientation(s.direction / len), s.origin_m};
}

}  // namespace gazelod::layer
