// SPDX-License-Identifier: Apache-2.0
// Angles and their units, for every layer (gaze/ and sim/ build their own helpers on these).
// atan2 throughout: no acos of a dot product, which loses all precision for the tiny angles
// between successive gaze samples.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace gazelod::lod {

inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Angle between two vectors (need not be unit) in [0, pi] as atan2(|a x b|, a . b); 0 if
// either is zero.
inline double angle_between_rad(const glm::dvec3& a, const glm::dvec3& b) {
  const double s = glm::length(glm::cross(a, b));
  const double c = glm::dot(a, b);
  if (s == 0.0 && c == 0.0) return 0.0;
  return std::atan2(s, c);
}

}  // namespace gazelod::lod
