// SPDX-License-Identifier: Apache-2.0
// Eye and head angles used by the effects. One convention throughout sim/: yaw is a rotation
// about +Y (positive turns left), pitch about +X (positive looks up), applied as
// R = Ry(yaw) * Rx(pitch) to the forward direction (0, 0, -1) (OpenXR axes).
#pragma once

#include "lod/angles.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace gazelod::sim {

using lod::angle_between_rad;
using lod::kDegPerRad;
using lod::kRadPerDeg;

struct YawPitch {
  double yaw_rad = 0.0;
  double pitch_rad = 0.0;
};

inline glm::dvec3 direction_from(YawPitch a) {
  const double cp = std::cos(a.pitch_rad);
  return {-std::sin(a.yaw_rad) * cp, std::sin(a.pitch_rad), -std::cos(a.yaw_rad) * cp};
}

inline YawPitch yaw_pitch_of(const glm::dvec3& d) {
  return {std::atan2(-d.x, -d.z), std::atan2(d.y, std::hypot(d.x, d.z))};
}

inline glm::dquat rotation_from(YawPitch a) {
  return glm::angleAxis(a.yaw_rad, glm::dvec3(0, 1, 0)) * glm::angleAxis(a.pitch_rad, glm::dvec3(1, 0, 0));
}

// Great-circle interpolation between unit vectors a and b at fraction p in [0, 1].
inline glm::dvec3 slerp_dir(const glm::dvec3& a, const glm::dvec3& b, double p) {
  const double omega = angle_between_rad(a, b);
  const double s = std::sin(omega);
  if (s < 1e-12) return glm::normalize(a + p * (b - a));
  return (std::sin((1.0 - p) * omega) / s) * a + (std::sin(p * omega) / s) * b;
}

}  // namespace gazelod::sim
