// SPDX-License-Identifier: Apache-2.0
// Mason's full greedy for the MCKP (1999 Fig. 22, sec. 3.5): no convexity needed. From every
// object's cheapest item, repeatedly take the candidate with the highest relative value to its
// object's current item; a taken item implicitly drops the cheaper ones, a rejected one is
// removed and the first rejection is the critical item. Half-optimal for every MCKP. The
// thesis scans subset maxima (O(n(r+m))); here a heap over subsets gives O(n log r + n m).
#include "budget/knapsack.hpp"
#include "budget/knapsack_heap.hpp"

#include <stdexcept>
#include <string>

namespace gazelod::budget {

namespace {

// Past this many relative values (the sum over subsets of their candidates squared) the
// rescans take seconds: one subset of 100 000 items took 7 s, of 1 M over a minute. No LOD
// chain or list of cluster cuts comes near (16 levels: 256).
constexpr double kMaxRescanWork = 2e9;

}  // namespace

MckpSolution solve_mason_full(const MckpInstance& instance) {
  const std::size_t r = instance.subset_count();
  std::vector<std::uint32_t> kept, offsets;
  reduce_ip_dominated(instance, kept, offsets);
  double work = 0.0;
  std::size_t largest = 0;
  for (std::size_t k = 0; k < r; ++k) {
    const double m = static_cast<double>(offsets[k + 1] - offsets[k]);
    work += m * m;
    if (m > static_cast<double>(offsets[largest + 1] - offsets[largest])) largest = k;
  }
  if (work > kMaxRescanWork)
    throw std::invalid_argument(
        "mason-full: too many candidates per subset for its rescans, which are quadratic in "
        "them (subset " +
        std::to_string(largest) + " has " + std::to_string(offsets[largest + 1] - offsets[largest]) +
        " after dominated items are dropped); use mason-greedy or mason-incremental");

  MckpSolution out;
  out.group_choice.assign(instance.groups.size(), kNoItem);
  std::vector<std::uint32_t> pos(r, 0);
  std::vector<std::uint8_t> rejected(kept.size(), 0);
  double profit = 0.0, cost = 0.0;
  for (std::size_t k = 0; k < r; ++k) {
    const MckpItem& b = instance.subset(k)[kept[offsets[k]]];
    profit += b.profit;
    cost += b.cost;
  }
  const double base_profit = profit, base_cost = cost;
  auto finish = [&]() {
    out.choice.resize(r);
    for (std::size_t k = 0; k < r; ++k) out.choice[k] = kept[offsets[k] + pos[k]];
    MckpInstance flat = instance;
    flat.groups.clear();
    evaluate(flat, out);
  };
  if (base_cost > instance.capacity) {
    finish();
    return out;
  }

  // Per subset: its best candidate (position), key and stable id, kept in a max-heap.
  std::vector<double> key(r);
  std::vector<std::uint32_t> id(r), best(r);
  auto find_best = [&](std::uint32_t k) {
    const auto items = instance.subset(k);
    const MckpItem& cur = items[kept[offsets[k] + pos[k]]];
    best[k] = kNoItem;
    for (std::uint32_t q = pos[k] + 1; q < offsets[k + 1] - offsets[k]; ++q) {
      if (rejected[offsets[k] + q]) continue;
      const double rv = relative_value(cur, items[kept[offsets[k] + q]]);
      const std::uint32_t sid = instance.subset_offsets[k] + kept[offsets[k] + q];
      if (best[k] == kNoItem || precedes(rv, sid, key[k], id[k])) {
        best[k] = q;
        key[k] = rv;
        id[k] = sid;
      }
    }
    return best[k] != kNoItem;
  };
  KnapsackHeap heap(&key, &id, true);
  heap.reserve(r);
  for (std::uint32_t k = 0; k < r; ++k)
    if (find_best(k)) heap.append(k);
  heap.heapify();

  std::uint32_t crit_k = kNoItem, crit_q = 0;
  double crit_t_profit = 0.0;
  while (!heap.empty()) {
    const std::uint32_t k = heap.top();
    heap.erase(k);
    const auto items = instance.subset(k);
    const MckpItem& cur = items[kept[offsets[k] + pos[k]]];
    const MckpItem& nxt = items[kept[offsets[k] + best[k]]];
    if (cost - cur.cost + nxt.cost <= instance.capacity) {
      cost += nxt.cost - cur.cost;
      profit += nxt.profit - cur.profit;
      pos[k] = best[k];  // cheaper candidates are now implicitly selected (dropped)
    } else {
      rejected[offsets[k] + best[k]] = 1;
      if (crit_k == kNoItem) {
        crit_k = k;
        crit_q = best[k];
        crit_t_profit = cur.profit;
      }
    }
    if (find_best(k)) heap.push(k);
  }
  out.error_bound = 0.0;
  if (crit_k != kNoItem) {
    const auto items = instance.subset(crit_k);
    const MckpItem& s = items[kept[offsets[crit_k] + crit_q]];
    const MckpItem& b = items[kept[offsets[crit_k]]];
    out.error_bound = s.profit - crit_t_profit;
    if (base_profit - b.profit + s.profit > profit && base_cost - b.cost + s.cost <= instance.capacity) {
      std::fill(pos.begin(), pos.end(), 0u);
      pos[crit_k] = crit_q;
    }
  }
  finish();
  return out;
}

}  // namespace gazelod::budget
