// SPDX-License-Identifier: Apache-2.0
// The one definition of how much of a triangle reduction each criterion earns, used by the
// run's report, `gazelod compare` and `gazelod eval` alike.
#pragma once

namespace gazelod::cli {

// Triangles of each criteria set over the same frames (summed or per frame: any unit, all alike).
// `all` is the set the reduction is measured to: the run's report uses the perceptual choice
// (before the switch policy and the budget); the Reddy 1998 tables use what was drawn.
struct SetTriangles {
  double none = 0.0;  // every object at level 0
  double size = 0.0;
  double size_eccentricity = 0.0;
  double size_velocity = 0.0;
  double all = 0.0;
};

// Shares of the reduction R = none - all owed to each criterion:
//   size         = (none - size) / R
//   eccentricity = (size+velocity - all) / R       (what adding eccentricity last removes)
//   velocity     = (size+eccentricity - all) / R   (what adding velocity last removes)
//   interaction  = 1 - the three (what only the criteria together remove)
// All zero when nothing was reduced (R <= 0), so no share is ever a division by zero.
struct ReductionShares {
  double size = 0.0;
  double eccentricity = 0.0;
  double velocity = 0.0;
  double interaction = 0.0;
};

ReductionShares reduction_shares(const SetTriangles& t);

}  // namespace gazelod::cli
