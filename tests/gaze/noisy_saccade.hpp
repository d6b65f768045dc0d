// SPDX-License-Identifier: Apache-2.0
// Test input shared by the conditioner's saccade tests: one main-sequence saccade in yaw
// (gaze/main_sequence.hpp's profile) between two fixations, sampled with Gaussian noise.
#pragma once

#include "auxiliary/angles.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "gaze/gaze_sample.hpp"
#include "gaze/main_sequence.hpp"

#include <cmath>
#include <cstdint>
#include <random>

namespace gazelod::gaze::test {

class NoisySaccade {
 public:
  static constexpr std::int64_t kT0 = 1'000'000'000;  // the samples' clock starts here

  // noise_deg: RMS over both axes.
  NoisySaccade(double amplitude_deg, double onset_s, double noise_deg, unsigned seed)
      : amplitude_deg_(amplitude_deg),
        onset_s_(onset_s),
        duration_s_(main_sequence::duration_s(amplitude_deg)),
        ratio_(main_sequence::velocity_ratio(amplitude_deg)),
        rng_(seed),
        noise_(0.0, noise_deg / std::sqrt(2.0)) {}

  double end_s() const { return onset_s_ + duration_s_; }
  // The true yaw at t_s (seconds after kT0).
  double yaw_deg(double t_s) const {
    return amplitude_deg_ * main_sequence::progress((t_s - onset_s_) / duration_s_, ratio_);
  }
  // A valid sample at t_s, with fresh noise on both axes.
  GazeSample sample(double t_s) {
    GazeSample g;
    g.t_ns = at_ns(t_s);
    const double yaw = yaw_deg(t_s) + noise_(rng_), pitch = noise_(rng_);
    g.direction = aux::direction_from(aux::YawPitch{yaw * aux::kRadPerDeg, pitch * aux::kRadPerDeg});
    g.valid = true;
    return g;
  }
  static std::int64_t at_ns(double t_s) { return kT0 + static_cast<std::int64_t>(std::llround(t_s * 1e9)); }

 private:
  double amplitude_deg_, onset_s_, duration_s_, ratio_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
};

}  // namespace gazelod::gaze::test
