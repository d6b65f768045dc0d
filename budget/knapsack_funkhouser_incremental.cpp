// SPDX-License-Identifier: Apache-2.0
// Funkhouser & Sequin's incremental algorithm (1993 sec. 6; Mason 1999 Fig. 14) as published:
// increment the object whose next level has the highest value p/w, decrement those whose
// current level has the lowest value until the frame fits, stop when an object goes up and
// down in the same round. Keyed by value, not relative value, so Mason's counterexample 2
// defeats it. Runs on the incremental engine of knapsack_mason_incremental.cpp.
#include "budget/knapsack.hpp"
#include "budget/knapsack_incremental.hpp"

namespace gazelod::budget {

MckpSolution solve_funkhouser_incremental(const MckpInstance& instance, const SolveLimits& limits) {
  MckpInstance flat = instance;
  flat.groups.clear();  // a flat algorithm: every object drawn by its own level
  IncrementalScheduler scheduler;
  IncrementalScheduler::Options options;
  options.key = MoveKey::value;
  options.drop_ip_dominated = false;  // as published: no preprocessing
  options.critical_check = false;
  scheduler.reset(flat, options);
  MckpSolution out;
  scheduler.step(flat, {}, {}, limits, out);
  out.error_bound = -1.0;  // no guarantee
  if (!instance.groups.empty()) out.group_choice.assign(instance.groups.size(), kNoItem);
  return out;
}

}  // namespace gazelod::budget
