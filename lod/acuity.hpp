// SPDX-License-Identifier: Apache-2.0
// Reddy's spatiotemporal acuity model (Reddy 1998, section 3.4, equations 1-5): the highest
// spatial frequency (cycles/deg) a viewer resolves at retinal velocity v and eccentricity E,
// limited by the display (xi) and scaled by the fixed-frame-rate factor s (section 6).
//
// The raw formulas are repaired where they break physical sense (docs/perceptual-model.md, 1.2):
//   G(v) = clamp(-27.78 log10 v + 57.69, 0, 60) for v > 0.825, else 60. The clamp at 60 removes
//        the upward jump at the seam (raw G is 60.0109 just above 0.825), the clamp at 0 the
//        negative branch past v = 119.31 deg/s.
//   M(E) = min(1, 7.49 / (0.3 E + 1)^2) for E > 5.79, else 1 (raw M already steps down).
// Every function here is total: NaN, negative or denormal inputs never reach a log or a division.
// NaN or negative v / E count as 0 (the conservative choice: full acuity, keeps detail); use
// validate_acuity_inputs() at an API boundary to refuse them with a message instead.
#pragma once

#include <string>

namespace gazelod::lod {

inline constexpr double kAcuityMaxCpd = 60.0;         // G below the velocity seam
inline constexpr double kVelocitySeamDps = 0.825;     // G's seam as published
inline constexpr double kEccentricitySeamDeg = 5.79;  // M's seam
inline constexpr double kGSlope = 27.78;              // G = -kGSlope log10 v + kGIntercept
inline constexpr double kGIntercept = 57.69;
inline constexpr double kMNumerator = 7.49;  // M = kMNumerator / (kMSlope E + 1)^2
inline constexpr double kMSlope = 0.3;

// Velocity where the log branch reaches 0 (10^(57.69/27.78) = 119.31 deg/s): G is 0 beyond.
double velocity_zero_dps();
// Velocity where the log branch equals 60 (0.82575 deg/s): the repaired seam of G.
double velocity_seam_repaired_dps();

// G(v) in cycles/deg, in [0, 60], non-increasing in v.
double velocity_acuity_cpd(double vel_dps);
// M(E), dimensionless in (0, 1], non-increasing in E.
double eccentricity_factor(double ecc_deg);
// H(v, E) = G(v) M(E) in cycles/deg, in [0, 60].
double spatiotemporal_acuity_cpd(double vel_dps, double ecc_deg);
// s * min(H(v, E), xi): the highest frequency that is both displayable and visible.
// xi <= 0 or NaN is treated as "no display limit"; s outside (0, 1] is clamped into [0, 1]
// (NaN s counts as 1). Result in [0, 60].
double acuity_cpd(double vel_dps, double ecc_deg, double xi_cpd, double scale = 1.0);

// The largest eccentricity there is: the opposite direction.
inline constexpr double kMaxEccentricityDeg = 180.0;

// Inverses (Reddy 1998 Figures 2 and 3): the smallest eccentricity / velocity beyond which the
// viewer resolves less than freq_cpd, i.e. H first falls below freq_cpd.
//   0 when H is below freq_cpd already at 0; +inf when it never falls below (freq_cpd <= 0,
//   or for the eccentricity, not within kMaxEccentricityDeg).
// With freq_cpd = xi these are the thresholds where LOD can start to drop on that criterion.
double eccentricity_threshold_deg(double freq_cpd, double vel_dps = 0.0);
double velocity_threshold_dps(double freq_cpd, double ecc_deg = 0.0);

// Empty when the inputs are physically meaningful, else a message naming the bad value:
// velocity >= 0 (inf allowed: acuity 0), eccentricity in [0, 180], xi > 0 finite,
// scale in (0, 1].
[[nodiscard]] std::string validate_acuity_inputs(double vel_dps, double ecc_deg, double xi_cpd, double scale);

}  // namespace gazelod::lod
