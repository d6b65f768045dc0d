// SPDX-License-Identifier: Apache-2.0
// Gaze-layer angle helpers on top of lod/angles.hpp (units, angle_between_rad): tangent bases,
// angular offsets and slerp of gaze directions. atan2 throughout, never acos.
#pragma once

#include "lod/angles.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace gazelod::gaze {

using lod::angle_between_rad;
using lod::kDegPerRad;
using lod::kRadPerDeg;

// Two unit vectors perpendicular to unit `c` (any; stable for every direction).
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

// Rotates unit `from` toward unit `to` by fraction f of the angle between them (slerp of
// directions); falls back to `from` when they are (anti)parallel.
inline glm::dvec3 slerp_direction(const glm::dvec3& from, const glm::dvec3& to, double f) {
  const glm::dvec3 axis = glm::cross(from, to);
  const double s = glm::length(axis);
  if (s < 1e-15) return from;
  const double angle = std::atan2(s, glm::dot(from, to)) * f;
  const glm::dvec3 k = axis / s;
  // Rodrigues' rotation of `from` about k (k is perpendicular to `from`).
  return from * std::cos(angle) + glm::cross(k, from) * std::sin(angle);
}

}  // namespace gazelod::gaze
