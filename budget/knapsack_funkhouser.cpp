// SPDX-License-Identifier: Apache-2.0
// Funkhouser & Sequin's greedy (1993 sec. 6; Mason 1999 Fig. 9) exactly as published: all
// items by value p/w, add an item that fits, replace an object's item by a more profitable one
// when the cost still fits. Kept for comparison with its three flaws (Mason sec. 2.6.1): the
// answer can leave an object empty (infeasible), has no critical-item check, and replaces by
// value, so it can be arbitrarily far from the optimum.
#include "budget/knapsack.hpp"

#include <algorithm>
#include <numeric>

namespace gazelod::budget {

MckpSolution solve_funkhouser(const MckpInstance& instance) {
  const std::size_t r = instance.subset_count();
  std::vector<std::uint32_t> order(instance.items.size());
  std::iota(order.begin(), order.end(), 0u);
  std::vector<double> value(instance.items.size());
  for (std::size_t j = 0; j < value.size(); ++j) value[j] = item_value(instance.items[j]);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return precedes(value[a], a, value[b], b); });
  std::vector<std::uint32_t> owner(instance.items.size());
  for (std::uint32_t k = 0; k < r; ++k)
    for (std::uint32_t j = instance.subset_offsets[k]; j < instance.subset_offsets[k + 1]; ++j) owner[j] = k;

  MckpSolution out;
  out.choice.assign(r, kNoItem);
  out.group_choice.assign(instance.groups.size(), kNoItem);
  double cost = 0.0;
  for (std::uint32_t j : order) {
    const std::uint32_t k = owner[j];
    const MckpItem& it = instance.items[j];
    const std::uint32_t local = j - instance.subset_offsets[k];
    if (out.choice[k] == kNoItem) {
      if (cost + it.cost <= instance.capacity) {
        out.choice[k] = local;
        cost += it.cost;
      }
      continue;
    }
    const MckpItem& cur = instance.subset(k)[out.choice[k]];
    if (it.profit > cur.profit && cost - cur.cost + it.cost <= instance.capacity) {
      cost += it.cost - cur.cost;
      out.choice[k] = local;
    }
  }
  MckpInstance flat = instance;  // groups play no part in this algorithm
  flat.groups.clear();
  evaluate(flat, out);
  out.group_choice.assign(instance.groups.size(), kNoItem);
  return out;
}

}  // namespace gazelod::budget
