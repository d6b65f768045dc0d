// SPDX-License-Identifier: Apache-2.0
// Reddy's acuity model with its seams repaired (see acuity.hpp for the why).
#include "lod/acuity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace gazelod::lod {

double velocity_zero_dps() {
  static const double v = std::pow(10.0, kGIntercept / kGSlope);
  return v;
}

double velocity_seam_repaired_dps() {
  static const double v = std::pow(10.0, (kGIntercept - kAcuityMaxCpd) / kGSlope);
  return v;
}

double velocity_acuity_cpd(double vel_dps) {
  // !(v > seam) also catches NaN, negatives and denormals: no log of them is ever taken.
  if (!(vel_dps > kVelocitySeamDps)) return kAcuityMaxCpd;
  if (vel_dps >= velocity_zero_dps()) return 0.0;  // includes +inf
  const double g = kGIntercept - kGSlope * std::log10(vel_dps);
  return std::clamp(g, 0.0, kAcuityMaxCpd);
}

double eccentricity_factor(double ecc_deg) {
  if (!(ecc_deg > kEccentricitySeamDeg)) return 1.0;  // NaN and negatives too
  const double q = kMSlope * ecc_deg + 1.0;           // > 2.7, no division by zero
  return std::min(1.0, kMNumerator / (q * q));        // q*q = inf gives 0
}

double spatiotemporal_acuity_cpd(double vel_dps, double ecc_deg) {
  return velocity_acuity_cpd(vel_dps) * eccentricity_factor(ecc_deg);
}

double acuity_cpd(double vel_dps, double ecc_deg, double xi_cpd, double scale) {
  double h = spatiotemporal_acuity_cpd(vel_dps, ecc_deg);
  if (xi_cpd > 0.0) h = std::min(h, xi_cpd);  // NaN or <= 0 xi: no display limit
  if (std::isnan(scale)) scale = 1.0;
  scale = std::clamp(scale, 0.0, 1.0);
  return h * scale;
}

double eccentricity_threshold_deg(double freq_cpd, double vel_dps) {
  if (!(freq_cpd > 0.0)) return std::numeric_limits<double>::infinity();
  const double g = velocity_acuity_cpd(vel_dps);
  if (freq_cpd > g) return 0.0;       // below freq_cpd already at the fovea
  const double ratio = freq_cpd / g;  // in (0, 1]
  // M(E) = ratio  <=>  (0.3 E + 1)^2 = 7.49 / ratio. Past 5.79 only: M is 1 before it.
  const double e = (std::sqrt(kMNumerator / ratio) - 1.0) / kMSlope;
  // Past 180 deg the formula has left the visual field: H never falls below freq_cpd in it
  // (a display coarser than the far periphery resolves; 1 px over 179 deg gave 1334 deg).
  if (!(e <= kMaxEccentricityDeg)) return std::numeric_limits<double>::infinity();
  return std::max(e, kEccentricitySeamDeg);
}

double velocity_threshold_dps(double freq_cpd, double ecc_deg) {
  if (!(freq_cpd > 0.0)) return std::numeric_limits<double>::infinity();
  const double m = eccentricity_factor(ecc_deg);
  if (!(m > 0.0)) return 0.0;
  const double g = freq_cpd / m;  // G(v) must fall below this
  if (g > kAcuityMaxCpd) return 0.0;
  const double v = std::pow(10.0, (kGIntercept - g) / kGSlope);
  return std::max(v, velocity_seam_repaired_dps());
}

std::string validate_acuity_inputs(double vel_dps, double ecc_deg, double xi_cpd, double scale) {
  std::ostringstream msg;
  if (std::isnan(vel_dps) || vel_dps < 0.0)
    msg << "velocity must be >= 0 deg/s, got " << vel_dps;
  else if (std::isnan(ecc_deg) || ecc_deg < 0.0 || ecc_deg > kMaxEccentricityDeg)
    msg << "eccentricity must be in [0, 180] deg, got " << ecc_deg;
  else if (!std::isfinite(xi_cpd) || xi_cpd <= 0.0)
    msg << "xi must be a finite number > 0 cycles/deg, got " << xi_cpd;
  else if (!(scale > 0.0 && scale <= 1.0))
    msg << "global scale s must be in (0, 1], got " << scale;
  return msg.str();
}

}  // namespace gazelod::lod
