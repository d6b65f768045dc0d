// SPDX-License-Identifier: Apache-2.0
// Multiple-choice knapsack (MCKP) instances and answers, the form the frame budget takes
// (Mason 1999 Def. 2.3, Funkhouser & Sequin 1993 sec. 6): exactly one item from every subset,
// maximise total profit (benefit) with total cost (render time) <= capacity. Plain data.
#pragma once

#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace gazelod::budget {

inline constexpr std::uint32_t kNoItem = std::numeric_limits<std::uint32_t>::max();

struct MckpItem {
  double profit = 0.0;  // predicted benefit
  double cost = 0.0;    // predicted render time (any unit, the same as capacity)
};

// Optional hierarchy for the hierarchical MCKP (Mason Ch. 4, 6): a group of subsets and/or
// other groups that may be drawn by shared impostors instead of its members.
struct MckpGroup {
  std::vector<std::uint32_t> subsets;  // member subsets (indices into MckpInstance subsets)
  std::vector<std::uint32_t> groups;   // member groups (indices into MckpInstance::groups)
  std::vector<MckpItem> impostors;     // shared impostors, coarsest first; may be empty
};

struct MckpInstance {
  double capacity = 0.0;
  std::vector<MckpItem> items;                   // all items, subset after subset
  std::vector<std::uint32_t> subset_offsets{0};  // subset k is items[offsets[k], offsets[k+1])
  std::vector<MckpGroup> groups;                 // empty: a plain MCKP

  std::size_t subset_count() const { return subset_offsets.size() - 1; }
  std::uint32_t subset_size(std::size_t k) const { return subset_offsets[k + 1] - subset_offsets[k]; }
  std::span<const MckpItem> subset(std::size_t k) const { return {items.data() + subset_offsets[k], subset_size(k)}; }
  void add_subset(std::span<const MckpItem> subset_items);
};

// One answer. choice[k] is the index within subset k (as given), kNoItem when the subset has
// nothing selected: covered by a group impostor, or left empty by a flawed solver.
struct MckpSolution {
  std::vector<std::uint32_t> choice;
  std::vector<std::uint32_t> group_choice;  // impostor index per group, kNoItem when none
  double profit = 0.0;
  double cost = 0.0;
  bool feasible = false;        // every leaf represented exactly once and cost <= capacity
  bool proven_optimal = false;  // set by the exact solver only
  // Mason's a-posteriori bound: optimum - profit <= error_bound (p_s - p_t for the critical
  // item s); negative when the solver gives no such bound.
  double error_bound = -1.0;
  std::uint64_t iterations = 0;  // increments + decrements (incremental solvers)
  // An incremental solver stopped at its limit (SolveLimits: the move limit, the optional
  // wall-clock limit, or the per-node safety stop) before converging. The answer is still a
  // complete level of detail, affordable whenever the lowest one is.
  bool truncated = false;
};

// How far an incremental solver may go (Mason 1999 sec. 9.3.5 truncation). The answer depends
// only on the inputs and `max_moves` unless `wall_clock_limit` is set.
struct SolveLimits {
  static constexpr std::uint64_t kNoMoveLimit = std::numeric_limits<std::uint64_t>::max();
  // Deterministic truncation: no increment is started once this many moves (increments +
  // decrements) have been made; the decrements that make the frame fit always run, so
  // `iterations` can exceed it by those of the last round. kNoMoveLimit: run to convergence
  // (or the solver's safety stop).
  std::uint64_t max_moves = kNoMoveLimit;
  // Optional outer limit on the wall time of one solve, off (nullopt) by default. When set, the
  // answer depends on timing (machine speed, load): the same input can give different answers on
  // different runs. Checked every 16 rounds.
  std::optional<std::chrono::nanoseconds> wall_clock_limit;
};

// IP-dominance (Mason sec. 3.1): item j is dropped when another item of its subset costs no
// more and profits no less, or when it cannot fit even with every other subset at its cheapest
// (the cheapest items always stay; only without groups). `kept` holds, per subset, the surviving within-subset indices
// in increasing cost (and so strictly increasing profit); offsets as in MckpInstance. Reuses the capacity of `kept` /
// `kept_offsets` (no allocation once they are large enough).
void reduce_ip_dominated(const MckpInstance& instance, std::vector<std::uint32_t>& kept,
                         std::vector<std::uint32_t>& kept_offsets);

// Relative value RV(j, i) = (p_j - p_i) / (w_j - w_i) (Mason Def. 3.1), guarded: a step that
// does not cost more ranks first when it loses no profit (a free gain, or an identical item:
// taking it costs nothing and may open free gains behind it), last when it loses profit;
// never NaN.
// (Inline: the incremental solver evaluates it for every object every frame.)
inline double relative_value(const MckpItem& from, const MckpItem& to) {
  const double dp = to.profit - from.profit;
  const double dw = to.cost - from.cost;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (dw > 0.0) return dp / dw;
  return dp >= 0.0 ? inf : -inf;
}
// Value p / w (Funkhouser & Sequin), guarded the same way.
inline double item_value(const MckpItem& item) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (item.cost > 0.0) return item.profit / item.cost;
  return item.profit > 0.0 ? inf : 0.0;
}

// Strict greedy order over candidate moves: higher key first, then the lower stable id.
inline bool precedes(double key_a, std::uint32_t id_a, double key_b, std::uint32_t id_b) {
  return key_a > key_b || (key_a == key_b && id_a < id_b);
}

// Sums profit and cost of `choice` (group impostors included) and sets `feasible`.
void evaluate(const MckpInstance& instance, MckpSolution& solution);

// Cost of taking the cheapest item everywhere (no groups): the lowest level of detail.
double lowest_cost(const MckpInstance& instance);

// Upper bound on the optimum from the linear relaxation (upper convex hull of each subset,
// filled greedily by slope, the last step fractional). Groups are ignored.
// -infinity when even the cheapest items do not fit.
double lp_upper_bound(const MckpInstance& instance);

}  // namespace gazelod::budget
