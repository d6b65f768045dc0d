// SPDX-License-Identifier: Apache-2.0
// The volumetric foveal cone of Reddy 1995 (sections 5-5.3): a cone from the eye along the
// gaze ray inside which the eye resolves its finest detail, widened by the gaze estimate's
// angular uncertainty. The plugin builds it every frame (its diagnostics carry it; `gazelod
// run` draws it); the selection applies the same widening per object (Viewer::tracker_error_deg).
#pragma once

#include <glm/vec3.hpp>

namespace gazelod::lod {

struct Cone {
  glm::dvec3 apex_m{0.0};
  glm::dvec3 axis{0.0, 0.0, -1.0};  // unit
  double half_angle_rad = 0.0;      // in [0, pi]
};

// A cone at the eye along the gaze, half-angle + tracker error (both degrees, clamped to
// [0, 180]). gaze_dir must be non-zero; NaN angles count as 180 (include everything).
Cone make_foveal_cone(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, double half_angle_deg,
                      double tracker_error_deg);

}  // namespace gazelod::lod
