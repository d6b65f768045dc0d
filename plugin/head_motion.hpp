// Head pose and angular velocity at a time from the runtime: XrSpaceVelocity when the
// runtime gives it, else differences of successive poses (robust to the q/-q sign flip and
// to tiny rotations: the angle comes from atan2, never acos).
#pragma once

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
  glm::dvec3 angular_velocity_rad_s{0.0};       // base-space axes
  glm::dvec3 linear_velocity_m_s{0.0};
};

// Angular velocity (rad/s, axes of the frame both orientations are in) that turns q0 into
// q1 in dt_s seconds. Zero for dt_s <= 0 or non-finite input.
glm::dvec3 angular_velocity_from_poses(const glm::dquat& q0, const glm::dquat& q1, double dt_s);

class HeadTracker {
 public:
  HeadTracker(XrSpace view_space, XrSpace base_space) : view_(view_space), base_(base_space) {}
  // Locates the head at `time`. On failure returns an invalid HeadMotion (the previous
  // pose is kept for the next difference).
  HeadMotion locate(XrTime time);
  // The head's orientation at another time (an eye-tracker sample's), without touching the
  // velocity state; nullopt when the runtime cannot locate it then.
  std::optional<glm::dquat> orientation_at(XrTime time) const;

 private:
  XrSpace view_;
  XrSpace base_;
  bool have_previous_ = false;
  glm::dquat previous_orientation_{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 previous_position_{0.0};
  XrTime previous_time_ = 0;
};

}  // namespace gazelod::plugin
