// SPDX-License-Identifier: Apache-2.0
// Foveal cone construction (see cone.hpp).
#include "lod/cone.hpp"

#include "auxiliary/angles.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace gazelod::lod {

Cone make_foveal_cone(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, double half_angle_deg,
                      double tracker_error_deg) {
  Cone c;
  c.apex_m = eye_m;
  c.axis = glm::normalize(gaze_dir);
  double a = half_angle_deg + tracker_error_deg;
  if (std::isnan(a)) a = 180.0;
  c.half_angle_rad = std::clamp(a, 0.0, 180.0) * aux::kRadPerDeg;
  return c;
}

}  // namespace gazelod::lod
