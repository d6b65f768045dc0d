// SPDX-License-Identifier: Apache-2.0
// The saccadic main sequence: the gaze filters are set and tested with it, and the simulator's
// saccades follow it (one definition for both).
//  - Duration grows about linearly with amplitude: D ~= 2.2 ms/deg * A + 21 ms for A in
//    about 1..50 deg (Carpenter 1988, "Movements of the Eyes", 2nd ed.; Bahill, Clark & Stark
//    1975, "The main sequence, a tool for studying human eye movements", Math. Biosci. 24).
//  - Peak velocity grows with amplitude and saturates around 400-700 deg/s for large
//    saccades (Bahill et al. 1975; Baloh et al. 1975, Neurology 25, an exponential fit
//    Vp = Vmax (1 - exp(-A / C))). Even a 3 deg saccade peaks well above 100 deg/s. Here
//    Vp = Vsat tanh(1.875 (A / D) / Vsat): a minimum-jerk-like peak for small saccades
//    (1.875 x mean velocity) that saturates (~500 deg/s) for large ones.
//  - The velocity profile (simulated saccades) is a plateau with raised-cosine ramps whose
//    width makes it integrate to A in D.
//  - Fixational drift and tracker noise stay far below that, which is why a velocity
//    threshold of about 30 deg/s separates them (I-VT: Salvucci & Goldberg 2000, ETRA;
//    Olsen 2012, "The Tobii I-VT fixation filter", default 30 deg/s).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::gaze::main_sequence {

// I-VT threshold commonly used for 250 Hz-class trackers (Olsen 2012).
inline constexpr double kIvtThreshold_deg_s = 30.0;
// Vsat of the peak-velocity law above.
inline constexpr double kPeakVelocitySaturation_deg_s = 550.0;

// Typical saccade duration for an amplitude (Carpenter 1988), seconds; a negative amplitude
// counts as 0.
constexpr double duration_s(double amplitude_deg) {
  return 0.021 + 0.0022 * std::max(0.0, amplitude_deg);
}

inline double peak_velocity_deg_s(double amplitude_deg) {
  const double mean_deg_s = std::max(0.0, amplitude_deg) / duration_s(amplitude_deg);
  return kPeakVelocitySaturation_deg_s * std::tanh(1.875 * mean_deg_s / kPeakVelocitySaturation_deg_s);
}

// The mean/peak ratio of a saccade of this amplitude, in [0.5, 1] (0.5 for a null saccade).
inline double velocity_ratio(double amplitude_deg) {
  const double peak = peak_velocity_deg_s(amplitude_deg);
  if (!(peak > 1e-9)) return 0.5;
  return std::clamp(amplitude_deg / duration_s(amplitude_deg) / peak, 0.5, 1.0);
}

// Fraction of the amplitude covered at normalised time tau in [0, 1] (0 -> 0, 1 -> 1).
// ratio = mean velocity / peak velocity (velocity_ratio); the ramps take 1 - ratio of the time
// each.
inline double progress(double tau, double ratio) {
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

}  // namespace gazelod::gaze::main_sequence
