// SPDX-License-Identifier: Apache-2.0
#include "budget/mckp.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::budget {

void MckpInstance::add_subset(std::span<const MckpItem> subset_items) {
  items.insert(items.end(), subset_items.begin(), subset_items.end());
  subset_offsets.push_back(static_cast<std::uint32_t>(items.size()));
}

void reduce_ip_dominated(const MckpInstance& instance, std::vector<std::uint32_t>& kept,
                         std::vector<std::uint32_t>& kept_offsets) {
  kept.clear();
  kept_offsets.clear();
  kept_offsets.push_back(0);
  // An item that does not fit even with every other subset at its cheapest is in no feasible
  // answer (Mason drops these too; the half-optimality proof needs it).
  const double lowest = lowest_cost(instance);
  for (std::size_t k = 0; k < instance.subset_count(); ++k) {
    const auto items = instance.subset(k);
    const std::size_t begin = kept.size();
    double own_lowest = std::numeric_limits<double>::infinity();
    for (const MckpItem& it : items) own_lowest = std::min(own_lowest, it.cost);
    // (Flat instances only: with groups the lowest level is made of impostors.)
    const double room =
        instance.groups.empty() ? instance.capacity - (lowest - own_lowest) : std::numeric_limits<double>::infinity();
    for (std::uint32_t j = 0; j < items.size(); ++j)
      if (items[j].cost <= room || items[j].cost == own_lowest) kept.push_back(j);
    // By (cost asc, profit desc, index asc), a total order, so the result does not depend on
    // the sort. (An insertion sort here was quadratic: 53 s for one subset of 200k items.)
    std::sort(kept.begin() + static_cast<std::ptrdiff_t>(begin), kept.end(), [&](std::uint32_t x, std::uint32_t y) {
      if (items[x].cost != items[y].cost) return items[x].cost < items[y].cost;
      if (items[x].profit != items[y].profit) return items[x].profit > items[y].profit;
      return x < y;
    });
    // Keep only strictly increasing profit along increasing cost.
    std::size_t out = begin;
    for (std::size_t a = begin; a < kept.size(); ++a) {
      if (out == begin || items[kept[a]].profit > items[kept[out - 1]].profit) kept[out++] = kept[a];
    }
    kept.resize(out);
    kept_offsets.push_back(static_cast<std::uint32_t>(kept.size()));
  }
}

void evaluate(const MckpInstance& instance, MckpSolution& solution) {
  const std::size_t r = instance.subset_count();
  solution.profit = 0.0;
  solution.cost = 0.0;
  bool complete = solution.choice.size() == r;
  // How many representations cover each subset: its own item plus chosen ancestor impostors.
  std::vector<int> cover(r, 0);
  for (std::size_t k = 0; k < r && k < solution.choice.size(); ++k) {
    const std::uint32_t c = solution.choice[k];
    if (c == kNoItem) continue;
    if (c >= instance.subset_size(k)) {
      complete = false;
      continue;
    }
    const MckpItem& it = instance.subset(k)[c];
    solution.profit += it.profit;
    solution.cost += it.cost;
    cover[k] += 1;
  }
  if (!instance.groups.empty()) {
    if (solution.group_choice.size() != instance.groups.size()) complete = false;
    // Leaves under each group, by walking members (groups form a forest, checked on input).
    std::vector<std::uint32_t> stack;
    for (std::size_t g = 0; g < instance.groups.size() && g < solution.group_choice.size(); ++g) {
      const std::uint32_t c = solution.group_choice[g];
      if (c == kNoItem) continue;
      if (c >= instance.groups[g].impostors.size()) {
        complete = false;
        continue;
      }
      solution.profit += instance.groups[g].impostors[c].profit;
      solution.cost += instance.groups[g].impostors[c].cost;
      stack.assign(1, static_cast<std::uint32_t>(g));
      while (!stack.empty()) {
        const MckpGroup& grp = instance.groups[stack.back()];
        stack.pop_back();
        for (std::uint32_t s : grp.subsets) cover[s] += 1;
        for (std::uint32_t h : grp.groups) stack.push_back(h);
      }
    }
  }
  for (int c : cover) complete = complete && c == 1;
  solution.feasible = complete && solution.cost <= instance.capacity;
}

double lowest_cost(const MckpInstance& instance) {
  double total = 0.0;
  for (std::size_t k = 0; k < instance.subset_count(); ++k) {
    double lo = std::numeric_limits<double>::infinity();
    for (const MckpItem& it : instance.subset(k)) lo = std::min(lo, it.cost);
    total += lo;
  }
  return total;
}

double lp_upper_bound(const MckpInstance& instance) {
  std::vector<std::uint32_t> kept, offsets;
  reduce_ip_dominated(instance, kept, offsets);
  struct Step {
    double slope, dp, dw;
  };
  std::vector<Step> steps;
  std::vector<std::uint32_t> hull;
  double profit = 0.0, cost = 0.0;
  for (std::size_t k = 0; k < instance.subset_count(); ++k) {
    const auto items = instance.subset(k);
    hull.clear();
    for (std::uint32_t a = offsets[k]; a < offsets[k + 1]; ++a) {
      const MckpItem& c = items[kept[a]];
      // Upper hull: drop the last point while it lies on or below the chord to the new one.
      while (hull.size() >= 2) {
        const MckpItem& p0 = items[hull[hull.size() - 2]];
        const MckpItem& p1 = items[hull.back()];
        if (relative_value(p0, p1) <= relative_value(p1, c))
          hull.pop_back();
        else
          break;
      }
      hull.push_back(kept[a]);
    }
    profit += items[hull[0]].profit;
    cost += items[hull[0]].cost;
    for (std::size_t h = 1; h < hull.size(); ++h) {
      const MckpItem& p0 = items[hull[h - 1]];
      const MckpItem& p1 = items[hull[h]];
      steps.push_back({relative_value(p0, p1), p1.profit - p0.profit, p1.cost - p0.cost});
    }
  }
  if (cost > instance.capacity) return -std::numeric_limits<double>::infinity();
  std::sort(steps.begin(), steps.end(), [](const Step& a, const Step& b) { return a.slope > b.slope; });
  double room = instance.capacity - cost;
  for (const Step& s : steps) {
    if (s.dw <= room) {
      profit += s.dp;
      room -= s.dw;
    } else {
      if (s.dw > 0.0) profit += s.dp * (room / s.dw);
      break;
    }
  }
  return profit;
}

}  // namespace gazelod::budget
