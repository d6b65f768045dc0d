// SPDX-License-Identifier: Apache-2.0
// Synthetic gaze with known ground truth: fixations with Gaussian tracker noise and saccades
// whose duration follows the main sequence (gaze/main_sequence.hpp) with a smooth
// (raised-cosine) velocity profile.
#pragma once

#include "auxiliary/angles.hpp"
#include "gaze/gaze_sample.hpp"
#include "gaze/main_sequence.hpp"
#include "gaze/trace_reader.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace gazelod::gaze::testing {

struct Synth {
  double rate_hz = 250.0;
  double noise_deg = 0.1;  // RMS per axis
  std::mt19937_64 rng{1};
  std::vector<GazeSample> out;
  double yaw_deg = 0.0, pitch_deg = 0.0;
  std::int64_t t_ns = 1'000'000'000;

  void emit(double yaw, double pitch, bool valid = true) {
    std::normal_distribution<double> n(0.0, noise_deg);
    GazeSample s;
    s.t_ns = t_ns;
    s.direction = direction_from_yaw_pitch_deg(yaw + n(rng), pitch + n(rng));
    s.valid = valid;
    s.confidence = valid ? 1.0f : 0.0f;
    out.push_back(s);
    t_ns += static_cast<std::int64_t>(std::llround(1e9 / rate_hz));
  }
  void fixate(double seconds) {
    const auto n = static_cast<int>(std::lround(seconds * rate_hz));
    for (int i = 0; i < n; ++i) emit(yaw_deg, pitch_deg);
  }
  void blink(double seconds) {
    const auto n = static_cast<int>(std::lround(seconds * rate_hz));
    for (int i = 0; i < n; ++i) emit(yaw_deg, pitch_deg, false);
  }
  // Saccade of `amp` degrees in direction `angle_deg`, `slow` times the typical duration.
  void saccade(double amp, double angle_deg, double slow = 1.0) {
    const double dur = main_sequence::duration_s(amp) * slow;
    const auto n = static_cast<int>(std::ceil(dur * rate_hz));
    const double y0 = yaw_deg, p0 = pitch_deg;
    const double dy = amp * std::cos(angle_deg / aux::kDegPerRad), dp = amp * std::sin(angle_deg / aux::kDegPerRad);
    for (int i = 1; i <= n; ++i) {
      const double f = std::min(1.0, i / (dur * rate_hz));
      const double s = 0.5 * (1.0 - std::cos(std::numbers::pi * f));  // raised-cosine velocity
      emit(y0 + dy * s, p0 + dp * s);
    }
    yaw_deg = y0 + dy;
    pitch_deg = p0 + dp;
  }
};

}  // namespace gazelod::gaze::testing
