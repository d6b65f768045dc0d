// SPDX-License-Identifier: Apache-2.0
// Geometric error -> removed detail, the stand-in for Reddy's rendered measure (Reddy 1998, 3.3).
// An error e on an object of diameter D removes features narrower than about 2e: one cycle
// needs two samples (a bright and a dark half, 000 section 3.4), so the finest detail left is
// about D / (2e) cycles per diameter. Coarser levels (larger e) remove lower frequencies.
#pragma once

#include <algorithm>
#include <cmath>

namespace gazelod::bake {

// Errors below this fraction of the diameter are float noise (or exactly 0 on flat parts):
// they are floored so the descriptor stays finite (at most 1 / (2 * 1e-6) = 500000 cycles).
inline constexpr double kMinErrorFraction = 1e-6;

// Cycles per object diameter removed by a level with geometric error `error_m` on an object of
// diameter `diameter_m` (same units). 0 for a degenerate (zero or non-finite) diameter.
inline double detail_cycles_per_diameter(double diameter_m, double error_m) {
  if (!(diameter_m > 0.0) || !std::isfinite(diameter_m)) return 0.0;
  const double e = std::isfinite(error_m) ? std::max(error_m, kMinErrorFraction * diameter_m) : diameter_m;
  return diameter_m / (2.0 * e);
}

}  // namespace gazelod::bake
