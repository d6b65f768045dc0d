// SPDX-License-Identifier: Apache-2.0
// Yaw and pitch of a direction, in ONE convention for the whole project. OpenXR axes (+X right,
// +Y up, -Z forward):
//   yaw   is a rotation about +Y by the right-hand rule: POSITIVE TURNS LEFT (toward -X);
//   pitch is a rotation about +X: positive looks up;
// applied as R = Ry(yaw) * Rx(pitch) to the forward direction (0, 0, -1), so there is no roll.
// This is the convention of glm::angleAxis and of OpenXR's quaternions, so an angle and the
// rotation it names never differ in sign.
//
// Formats written for people say "positive yaw = right" instead (gazelod trace files'
// gaze_yaw_deg, the layer configuration's head_offset.rotation_deg, GazeBaseVR and Pupil Cloud
// exports). Their readers convert once, with yaw_pitch_from_yaw_right_deg, and the file keeps
// its meaning.
#pragma once

#include "auxiliary/angles.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace gazelod::aux {

struct YawPitch {
  double yaw_rad = 0.0;    // positive left
  double pitch_rad = 0.0;  // positive up
};

// The unit direction R * (0, 0, -1).
inline glm::dvec3 direction_from(YawPitch a) {
  const double cp = std::cos(a.pitch_rad);
  return {-std::sin(a.yaw_rad) * cp, std::sin(a.pitch_rad), -std::cos(a.yaw_rad) * cp};
}

// The inverse of direction_from for a direction of any length > 0: yaw in (-pi, pi], pitch in
// [-pi/2, pi/2], both by atan2.
inline YawPitch yaw_pitch_of(const glm::dvec3& d) {
  return {std::atan2(-d.x, -d.z), std::atan2(d.y, std::hypot(d.x, d.z))};
}

// The rotation R = Ry(yaw) * Rx(pitch) (unit to rounding; not renormalised).
inline glm::dquat rotation_from(YawPitch a) {
  return glm::angleAxis(a.yaw_rad, glm::dvec3(0, 1, 0)) * glm::angleAxis(a.pitch_rad, glm::dvec3(1, 0, 0));
}

// The orientation whose -Z axis points along `dir` (any length > 0) with +X level (no roll),
// as XR_EXT_eye_gaze_interaction poses are.
inline glm::dquat orientation_along(const glm::dvec3& dir) {
  return glm::normalize(rotation_from(yaw_pitch_of(dir)));
}

// A yaw and pitch in degrees as formats for people write them, "positive yaw = right",
// positive pitch = up, in this convention (the yaw negated). The one place that sign flips.
inline YawPitch yaw_pitch_from_yaw_right_deg(double yaw_right_deg, double pitch_up_deg) {
  return {-yaw_right_deg * kRadPerDeg, pitch_up_deg * kRadPerDeg};
}

}  // namespace gazelod::aux
