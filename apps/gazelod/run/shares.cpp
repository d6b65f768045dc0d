// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/shares.hpp"

namespace gazelod::cli {

ReductionShares reduction_shares(const SetTriangles& t) {
  ReductionShares s;
  const double reduction = t.none - t.all;
  if (!(reduction > 0.0)) return s;  // also NaN
  s.size = (t.none - t.size) / reduction;
  s.eccentricity = (t.size_velocity - t.all) / reduction;
  s.velocity = (t.size_eccentricity - t.all) / reduction;
  s.interaction = 1.0 - s.size - s.eccentricity - s.velocity;
  return s;
}

}  // namespace gazelod::cli
