// SPDX-License-Identifier: Apache-2.0
#include "plugin/head_motion.hpp"

#include "auxiliary/time.hpp"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace gazelod::plugin {

glm::dvec3 angular_velocity_from_poses(const glm::dquat& q0, const glm::dquat& q1, double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return glm::dvec3(0.0);
  glm::dquat d = q1 * glm::conjugate(q0);  // rotation from q0 to q1, in the outer frame
  if (d.w < 0.0) d = -d;                   // q and -q are the same rotation: take the short way
  const glm::dvec3 axis_sin(d.x, d.y, d.z);
  const double s = glm::length(axis_sin);
  if (!std::isfinite(s) || !std::isfinite(d.w)) return glm::dvec3(0.0);
  // angle = 2 atan2(|v|, w); for tiny s, axis_sin / s * angle -> 2 axis_sin / w.
  const double angle = 2.0 * std::atan2(s, d.w);
  const glm::dvec3 rotvec = s > 1e-12 ? axis_sin * (angle / s) : axis_sin * (2.0 / d.w);
  return rotvec / dt_s;
}

std::optional<glm::dquat> HeadTracker::orientation_at(XrTime time) const {
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  if (xr_ == nullptr || XR_FAILED(xr_->locate_space(view_, base_, time, &loc))) return std::nullopt;
  if (!(loc.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT)) return std::nullopt;
  const auto& q = loc.pose.orientation;
  const glm::dquat r = glm::normalize(glm::dquat(q.w, q.x, q.y, q.z));
  if (!std::isfinite(r.w) || !std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z)) return std::nullopt;
  return r;
}

HeadMotion HeadTracker::locate(XrTime time) {
  XrSpaceVelocity velocity{XR_TYPE_SPACE_VELOCITY};
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  loc.next = &velocity;
  HeadMotion m;
  if (xr_ == nullptr || XR_FAILED(xr_->locate_space(view_, base_, time, &loc))) return m;
  const XrSpaceLocationFlags need = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT;
  if ((loc.locationFlags & need) != need) return m;
  const auto& q = loc.pose.orientation;
  m.orientation = glm::normalize(glm::dquat(q.w, q.x, q.y, q.z));
  m.position_m = {loc.pose.position.x, loc.pose.position.y, loc.pose.position.z};
  const bool angular = (velocity.velocityFlags & XR_SPACE_VELOCITY_ANGULAR_VALID_BIT) != 0;
  const bool linear = (velocity.velocityFlags & XR_SPACE_VELOCITY_LINEAR_VALID_BIT) != 0;
  if (angular)
    m.angular_velocity_rad_s = {velocity.angularVelocity.x, velocity.angularVelocity.y, velocity.angularVelocity.z};
  if (linear) m.linear_velocity_m_s = {velocity.linearVelocity.x, velocity.linearVelocity.y, velocity.linearVelocity.z};
  return finish(static_cast<std::int64_t>(time), m, angular, linear);
}

HeadMotion HeadTracker::from_pose(std::int64_t t_ns, const HeadMotion& given, bool angular_given, bool linear_given) {
  HeadMotion m = given;
  const double n = glm::length(glm::dvec4(m.orientation.x, m.orientation.y, m.orientation.z, m.orientation.w));
  if (!(n > 1e-6) || !std::isfinite(n)) return HeadMotion{};
  // Already unit (a recorded OpenXR pose) stays bit for bit what it was.
  if (std::abs(n - 1.0) > 1e-9) m.orientation = m.orientation / n;
  if (!angular_given) m.angular_velocity_rad_s = glm::dvec3(0.0);
  if (!linear_given) m.linear_velocity_m_s = glm::dvec3(0.0);
  return finish(t_ns, m, angular_given, linear_given);
}

// Validity, and the velocities the runtime (or application) did not give, from the previous pose.
HeadMotion HeadTracker::finish(std::int64_t time, HeadMotion m, bool angular_given, bool linear_given) {
  m.valid = std::isfinite(m.orientation.w) && std::isfinite(m.orientation.x) && std::isfinite(m.orientation.y) &&
            std::isfinite(m.orientation.z) && std::isfinite(m.position_m.x) && std::isfinite(m.position_m.y) &&
            std::isfinite(m.position_m.z);
  if (!m.valid) return HeadMotion{};

  const double dt_s = have_previous_ ? aux::seconds_from_ns(time - previous_time_) : 0.0;
  if (!angular_given && have_previous_)
    m.angular_velocity_rad_s = angular_velocity_from_poses(previous_orientation_, m.orientation, dt_s);
  if (!linear_given && have_previous_ && dt_s > 0.0) m.linear_velocity_m_s = (m.position_m - previous_position_) / dt_s;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(m.angular_velocity_rad_s[i])) m.angular_velocity_rad_s = glm::dvec3(0.0);
    if (!std::isfinite(m.linear_velocity_m_s[i])) m.linear_velocity_m_s = glm::dvec3(0.0);
  }
  have_previous_ = true;
  previous_orientation_ = m.orientation;
  previous_position_ = m.position_m;
  previous_time_ = time;
  return m;
}

}  // namespace gazelod::plugin
