#include "gaze/head_velocity.hpp"

#include "gaze/angles.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace gazelod::gaze {

glm::dvec3 rotation_vector_between(const glm::dquat& a, const glm::dquat& b) {
  glm::dquat d = glm::normalize(b) * glm::conjugate(glm::normalize(a));
  if (d.w < 0.0) d = -d;  // q and -q are the same rotation: take the short way round
  const glm::dvec3 v(d.x, d.y, d.z);
  const double s = glm::length(v);
  // angle = 2 atan2(s, w); r = v * angle / s, whose limit for s -> 0 is v * 2 / w (w ~ 1).
  const double scale = s > 1e-12 ? 2.0 * std::atan2(s, d.w) / s : 2.0 / d.w;
  return v * scale;
}

std::optional<glm::dvec3> angular_velocity_rad_s(const HeadSample& a, const HeadSample& b) {
  const std::int64_t dt_ns = b.t_ns - a.t_ns;
  if (dt_ns <= 0) return std::nullopt;
  return rotation_vector_between(a.orientation, b.orientation) /
         (static_cast<double>(dt_ns) * 1e-9);
}

void HeadVelocityEstimator::push(const HeadSample& sample) {
  if (!sample.valid) return;
  const double n = std::sqrt(glm::dot(sample.orientation, sample.orientation));
  if (!(n > 0.5 && n < 2.0)) return;  // not a rotation; never trusted
  if (!samples_.empty() && sample.t_ns <= samples_.back().t_ns) return;
  samples_.push_back(sample);
  // Keep the newest sample and one at or beyond the window's start.
  while (samples_.size() > 2 && samples_.back().t_ns - samples_[1].t_ns >= window_ns_)
    samples_.pop_front();
}

std::optional<glm::dvec3> HeadVelocityEstimator::velocity_rad_s() const {
  if (samples_.size() < 2) return std::nullopt;
  return angular_velocity_rad_s(samples_.front(), samples_.back());
}

double HeadVelocityEstimator::speed_deg_s() const {
  const auto v = velocity_rad_s();
  return v ? glm::length(*v) * kDegPerRad : 0.0;
}

}  // namespace gazelod::gaze
