#include "gaze/one_euro.hpp"

#include "gaze/angles.hpp"

#include <cmath>
#include <numbers>

namespace gazelod::gaze {
namespace {

// Exponential-smoothing factor for a cutoff frequency and a sample interval (Casiez 2012).
double alpha(double cutoff_hz, double dt_s) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoff_hz);
  return 1.0 / (1.0 + tau / dt_s);
}

}  // namespace

GazeSample FixationSmoother::filter(const GazeSample& raw, GazeLabel label) {
  if (!raw.valid || label == GazeLabel::saccade || label == GazeLabel::invalid) {
    state_.reset();
    return raw;
  }
  const glm::dvec3 d = glm::normalize(raw.direction);
  if (!state_ || raw.t_ns <= state_->last.t_ns) {
    state_ = State{raw, 0.0};
    state_->last.direction = d;
    return state_->last;
  }
  const double dt_s = static_cast<double>(raw.t_ns - state_->last.t_ns) * 1e-9;
  const double jump_deg = angle_between_rad(state_->last.direction, d) * kDegPerRad;
  // A jump far beyond tracker noise is a saccade starting (the per-sample speed of noise
  // alone, 0.1 deg per 4 ms = 25 deg/s, is too close to the I-VT threshold to use here).
  if (jump_deg > options_.saccade_jump_deg) {
    state_ = State{raw, 0.0};
    state_->last.direction = d;
    return raw;
  }
  const double raw_speed = jump_deg / dt_s;
  State& s = *state_;
  s.speed_deg_s += alpha(options_.d_cutoff_hz, dt_s) * (raw_speed - s.speed_deg_s);
  const double cutoff = options_.min_cutoff_hz + options_.beta * s.speed_deg_s;
  const double a = alpha(cutoff, dt_s);
  GazeSample out = raw;
  out.direction = slerp_direction(s.last.direction, d, a);
  s.last = out;
  return out;
}

}  // namespace gazelod::gaze
