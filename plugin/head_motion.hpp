// SPDX-License-Identifier: Apache-2.0
// Head pose and angular velocity at a time from the runtime: XrSpaceVelocity when the
// runtime gives it, else differences of successive poses (robust to the q/-q sign flip and
// to tiny rotations: the angle comes from atan2, never acos).
#pragma once

#include "plugin/xr_dispatch.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <openxr/openxr.h>

#include <cstdint>
#include <optional>

namespace gazelod::plugin {

struct HeadMotion {
  bool valid = false;
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // head (VIEW) to base space
  glm::dvec3 position_m{0.0};
  glm::dvec3 angular_velocity_rad_s{0.0};  // base-space axes
  glm::dvec3 linear_velocity_m_s{0.0};
};

// Angular velocity (rad/s, axes of the frame both orientations are in) that turns q0 into
// q1 in dt_s seconds. Zero for dt_s <= 0 or non-finite input.
glm::dvec3 angular_velocity_from_poses(const glm::dquat& q0, const glm::dquat& q1, double dt_s);

class HeadTracker {
 public:
  // Without OpenXR (data mode): only from_pose.
  HeadTracker() = default;
  // Spaces are the application's (not owned); xr: the application's functions (outlives this).
  HeadTracker(const XrDispatch& xr, XrSpace view_space, XrSpace base_space)
      : xr_(&xr), view_(view_space), base_(base_space) {}
  // A new base space (recentring): velocities restart from the next pose.
  void set_base(XrSpace base_space) {
    base_ = base_space;
    have_previous_ = false;
  }
  // Velocities from two poses given by the application (data mode), as from two locates.
  HeadMotion from_pose(std::int64_t t_ns, const HeadMotion& given, bool angular_given, bool linear_given);
  // Locates the head at `time`. On failure returns an invalid HeadMotion (the previous
  // pose is kept for the next difference).
  HeadMotion locate(XrTime time);
  // The head's orientation at another time (an eye-tracker sample's), without touching the
  // velocity state; nullopt when the runtime cannot locate it then.
  std::optional<glm::dquat> orientation_at(XrTime time) const;

 private:
  HeadMotion finish(std::int64_t t_ns, HeadMotion m, bool angular_given, bool linear_given);

  const XrDispatch* xr_ = nullptr;
  XrSpace view_ = XR_NULL_HANDLE;
  XrSpace base_ = XR_NULL_HANDLE;
  bool have_previous_ = false;
  glm::dquat previous_orientation_{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 previous_position_{0.0};
  std::int64_t previous_time_ = 0;
};

}  // namespace gazelod::plugin
