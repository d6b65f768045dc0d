// SPDX-License-Identifier: Apache-2.0
// Where a space is in LOCAL at a time: reference spaces (LOCAL, STAGE, VIEW from the head
// script), the eye-gaze action space (the simulator's tracker sample, with the scenario's
// delivery quirk) and action spaces placed by XR_EXT_conformance_automation.
#pragma once

#include "sim/runtime/pose_math.hpp"
#include "sim/runtime/runtime_state.hpp"

namespace gazelod::xrrt {

// STAGE's origin (the floor) lies this far below LOCAL's.
inline constexpr double kStageFloorBelowLocalM = 1.6;

struct Located {
  bool valid = false;    // the pose is known (VALID bits)
  bool tracked = false;  // and tracked (TRACKED bits)
  Pose pose;             // in LOCAL
  bool has_velocity = false;
  glm::dvec3 linear_m_s{0.0}, angular_rad_s{0.0};  // of the space's origin, LOCAL frame
  bool is_gaze = false;
  XrTime gaze_sample_time = 0;  // what XrEyeGazeSampleTimeEXT reports
};

Located locate_in_local(Instance& inst, Session& session, const Space& space, XrTime time, int depth = 0);

}  // namespace gazelod::xrrt
