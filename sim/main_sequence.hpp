// SPDX-License-Identifier: Apache-2.0
// The saccadic main sequence (Bahill, Clark & Stark 1975; Carpenter 1988): duration grows
// linearly with amplitude, D = 2.2 ms/deg * A + 21 ms, and peak velocity saturates (~500 deg/s).
// Peak velocity here: Vp = Vsat tanh(1.875 (A / D) / Vsat), i.e. a minimum-jerk-like peak for
// small saccades (1.875 x mean velocity) that saturates for large ones. The velocity profile
// is a plateau with raised-cosine ramps whose width makes the profile integrate to A in D.
#pragma once

#include "gaze/main_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::sim {

constexpr double kSaccadeSaturationDegS = 550.0;

// The same duration law the gaze filters are set and tested with (gaze/main_sequence.hpp).
inline double saccade_duration_s(double amplitude_deg) {
  return gaze::main_sequence::duration_s(std::max(0.0, amplitude_deg));
}

inline double saccade_peak_velocity_deg_s(double amplitude_deg) {
  const double mean_deg_s = std::max(0.0, amplitude_deg) / saccade_duration_s(amplitude_deg);
  return kSaccadeSaturationDegS * std::tanh(1.875 * mean_deg_s / kSaccadeSaturationDegS);
}

// Fraction of the amplitude covered at normalised time tau in [0, 1] (0 -> 0, 1 -> 1).
// ratio = mean velocity / peak velocity, in [0.5, 1]; the ramps take 1 - ratio of the time each.
inline double saccade_progress(double tau, double ratio) {
  tau = std::clamp(tau, 0.0, 1.0);
  const double a = std::clamp(1.0 - ratio, 0.0, 0.5);
  const double r = 1.0 - a;
  if (a < 1e-9) return tau;    // constant velocity
  auto ramp = [a](double x) {  // integral of (1 - cos(pi x / a)) / 2 from 0 to x <= a
    return x / 2.0 - a / (2.0 * std::numbers::pi) * std::sin(std::numbers::pi * x / a);
  };
  double covered;
  if (tau < a)
    covered = ramp(tau);
  else if (tau <= 1.0 - a)
    covered = a / 2.0 + (tau - a);
  else
    covered = r - ramp(1.0 - tau);
  return std::clamp(covered / r, 0.0, 1.0);
}

// The mean/peak ratio of a saccade of this amplitude (0.5 for a null saccade).
inline double saccade_velocity_ratio(double amplitude_deg) {
  const double peak = saccade_peak_velocity_deg_s(amplitude_deg);
  if (!(peak > 1e-9)) return 0.5;
  return std::clamp(amplitude_deg / saccade_duration_s(amplitude_deg) / peak, 0.5, 1.0);
}

}  // namespace gazelod::sim
