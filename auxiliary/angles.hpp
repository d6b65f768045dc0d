// SPDX-License-Identifier: Apache-2.0
// Angles between directions, for every layer (the perceptual core, gaze input, the simulator):
// units, the angle between two vectors, angular offsets about a centre and the slerp of unit
// directions. atan2 throughout, never acos of a dot product: acos loses all precision for the
// tiny angles between successive gaze samples (near 1, a dot product's last bit is ~1e-8 rad).
// Yaw and pitch (a sign convention) are auxiliary/yaw_pitch.hpp.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace gazelod::aux {

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

// Two unit vectors perpendicular to unit `c` and to each other (any such pair, but always the
// same one for the same `c`; stable for every direction).
inline void tangent_basis(const glm::dvec3& c, glm::dvec3& e1, glm::dvec3& e2) {
  const glm::dvec3 helper = std::fabs(c.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  e1 = glm::normalize(glm::cross(helper, c));
  e2 = glm::cross(c, e1);
}

// Angular offset (radians, two components) of `d` from unit centre `c` in basis (e1, e2).
inline glm::dvec2 angular_offset_rad(const glm::dvec3& d, const glm::dvec3& c, const glm::dvec3& e1,
                                     const glm::dvec3& e2) {
  const double along = glm::dot(d, c);
  return {std::atan2(glm::dot(d, e1), along), std::atan2(glm::dot(d, e2), along)};
}

// Rotates unit `from` toward unit `to` by fraction f of the angle between them, along the great
// circle through both (slerp of directions; f outside [0, 1] extrapolates along it). The result
// is unit to rounding. Where the great circle is not defined, |from x to| < 1e-15:
//  - parallel (from . to > 0): `from` itself, for every f;
//  - antiparallel: a half turn about the axis tangent_basis(from) gives first, so that f = 0 is
//    `from`, f = 1 is `to` and the path is continuous (the same path for the same inputs).
inline glm::dvec3 slerp_direction(const glm::dvec3& from, const glm::dvec3& to, double f) {
  const glm::dvec3 axis = glm::cross(from, to);
  const double s = glm::length(axis);
  glm::dvec3 k;
  if (s < 1e-15) {
    if (glm::dot(from, to) >= 0.0) return from;
    glm::dvec3 unused;
    tangent_basis(from, k, unused);
  } else {
    k = axis / s;
  }
  const double angle = std::atan2(s, glm::dot(from, to)) * f;
  // Rodrigues' rotation of `from` about k (k is perpendicular to `from`).
  return from * std::cos(angle) + glm::cross(k, from) * std::sin(angle);
}

}  // namespace gazelod::aux
