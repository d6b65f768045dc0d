// Head angular velocity from a pose stream. Quaternion differences are made robust to:
//  - q / -q sign flips (the same rotation): the relative rotation is taken on the short path;
//  - tiny rotations: the angle is 2 atan2(|v|, w) and the axis scaling has a series limit, so
//    there is no acos of a dot product and no 0/0;
//  - uneven sample spacing: the rate is the rotation over the real elapsed time, and the
//    estimator spans a time window rather than a count of samples.
#pragma once

#include "gaze/gaze_sample.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <deque>
#include <optional>

namespace gazelod::gaze {

// Rotation vector (axis * angle, radians, world frame) taking orientation a to b on the
// shortest path: b = exp(r) * a.
glm::dvec3 rotation_vector_between(const glm::dquat& a, const glm::dquat& b);

// Angular velocity (rad/s, world frame) between two poses; nullopt when b is not later than a.
std::optional<glm::dvec3> angular_velocity_rad_s(const HeadSample& a, const HeadSample& b);

class HeadVelocityEstimator {
 public:
  // `window_ns`: the velocity spans the newest sample and the oldest one within this window.
  explicit HeadVelocityEstimator(std::int64_t window_ns = 20'000'000) : window_ns_(window_ns) {}
  // Adds a pose (invalid ones and ones not later than the newest are ignored).
  void push(const HeadSample& sample);
  // World-frame angular velocity, rad/s; nullopt until two usable poses are in the window.
  std::optional<glm::dvec3> velocity_rad_s() const;
  // |velocity| in deg/s (0 when unknown).
  double speed_deg_s() const;
  void reset() { samples_.clear(); }

 private:
  std::int64_t window_ns_;
  std::deque<HeadSample> samples_;
};

}  // namespace gazelod::gaze
