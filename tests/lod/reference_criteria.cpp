// SPDX-License-Identifier: Apache-2.0
// Exact per-object criteria (see criteria.hpp).
#include "tests/lod/reference_criteria.hpp"

#include "auxiliary/angles.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::lod {

double angular_radius_rad(double dist_m, double radius_m) {
  if (!(radius_m > 0.0)) return 0.0;
  if (!(dist_m > radius_m)) return std::numbers::pi / 2;
  // d^2 - r^2 as (d - r)(d + r): no cancellation when the eye is just outside the sphere.
  return std::atan2(radius_m, std::sqrt((dist_m - radius_m) * (dist_m + radius_m)));
}

double pixel_diameter_px(double angular_radius_deg, double px_per_deg) {
  return std::max(0.0, 2.0 * angular_radius_deg * px_per_deg);
}

double nearest_point_eccentricity_deg(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, const glm::dvec3& center_m,
                                      double radius_m) {
  const glm::dvec3 r = center_m - eye_m;
  const double d = glm::length(r);
  if (!(d > radius_m)) return 0.0;  // eye inside or on the sphere
  const double phi = aux::angle_between_rad(gaze_dir, r);
  return std::max(0.0, phi - angular_radius_rad(d, radius_m)) * aux::kDegPerRad;
}

double retinal_velocity_dps(const glm::dvec3& eye_m, const glm::dvec3& eye_velocity_m_s,
                            const glm::dvec3& gaze_angular_velocity_rad_s, const glm::dvec3& center_m,
                            const glm::dvec3& object_velocity_m_s) {
  const glm::dvec3 r = center_m - eye_m;
  const double d2 = glm::dot(r, r);
  if (!(d2 > 0.0)) return 0.0;
  const glm::dvec3 w_obj = glm::cross(r, object_velocity_m_s - eye_velocity_m_s) / d2;
  const glm::dvec3 w_rel = w_obj - gaze_angular_velocity_rad_s;
  return glm::length(glm::cross(w_rel, r)) / std::sqrt(d2) * aux::kDegPerRad;
}

}  // namespace gazelod::lod
