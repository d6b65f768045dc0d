// SPDX-License-Identifier: Apache-2.0
// Helpers for the budget tests: instance builders, brute-force optima, random generators.
#pragma once

#include "budget/mckp.hpp"
#include "budget/mckp_hierarchy.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace gazelod::budget::test {

using Pairs = std::vector<std::vector<std::pair<double, double>>>;  // {profit, cost}

inline MckpInstance make_instance(double capacity, const Pairs& subsets) {
  MckpInstance inst;
  inst.capacity = capacity;
  for (const auto& s : subsets) {
    std::vector<MckpItem> items;
    for (auto [p, w] : s) items.push_back({p, w});
    inst.add_subset(items);
  }
  return inst;
}

struct Optimum {
  bool feasible = false;
  double profit = -std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> choice;
};

// Every combination (small instances only); groups ignored.
inline Optimum brute_force(const MckpInstance& inst) {
  Optimum best;
  const std::size_t r = inst.subset_count();
  std::vector<std::uint32_t> c(r, 0);
  for (;;) {
    double p = 0, w = 0;
    for (std::size_t k = 0; k < r; ++k) {
      p += inst.subset(k)[c[k]].profit;
      w += inst.subset(k)[c[k]].cost;
    }
    if (w <= inst.capacity && (!best.feasible || p > best.profit)) {
      best = {true, p, c};
    }
    std::size_t k = 0;
    while (k < r && ++c[k] == inst.subset_size(k)) c[k++] = 0;
    if (k == r) break;
  }
  return best;
}

// A convex instance (diminishing returns within every subset), items shuffled within subsets.
inline MckpInstance random_convex(std::mt19937& rng, int max_subsets = 6, int max_items = 5) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> nr(1, max_subsets), nm(1, max_items);
  MckpInstance inst;
  double lo = 0, hi = 0;
  const int r = nr(rng);
  for (int k = 0; k < r; ++k) {
    std::vector<MckpItem> items;
    double w = 5 * u(rng), p = 10 * u(rng), slope = 0.5 + 4.5 * u(rng);
    const int m = nm(rng);
    lo += w;
    for (int j = 0; j < m; ++j) {
      items.push_back({p, w});
      const double dw = 0.5 + 9.5 * u(rng);
      w += dw;
      p += slope * dw;
      slope *= 0.2 + 0.75 * u(rng);
    }
    hi += items.back().cost;
    std::shuffle(items.begin(), items.end(), rng);
    inst.add_subset(items);
  }
  inst.capacity = lo + u(rng) * (hi - lo);
  return inst;
}

// Any instance: profits and costs small integers (ties and dominated items on purpose).
inline MckpInstance random_general(std::mt19937& rng, int max_subsets = 6, int max_items = 5) {
  std::uniform_int_distribution<int> nr(1, max_subsets), nm(1, max_items), pv(0, 20), wv(0, 10);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MckpInstance inst;
  double lo = 0, hi = 0;
  const int r = nr(rng);
  for (int k = 0; k < r; ++k) {
    std::vector<MckpItem> items;
    const int m = nm(rng);
    double mn = 1e9, mx = 0;
    for (int j = 0; j < m; ++j) {
      items.push_back({double(pv(rng)), double(wv(rng))});
      mn = std::min(mn, items.back().cost);
      mx = std::max(mx, items.back().cost);
    }
    lo += mn;
    hi += mx;
    inst.add_subset(items);
  }
  inst.capacity = std::floor(lo + u(rng) * (hi - lo + 2));
  return inst;
}

// Item of a tree node (group impostors follow the subset items in `source` numbering).
inline MckpItem node_item(const MckpInstance& inst, const HmckpNode& n) {
  if (n.subset != kNoItem) return inst.subset(n.subset)[n.index];
  if (n.group != kNoItem) return inst.groups[n.group].impostors[n.index];
  return {};
}

// Every valid level of detail of a (small) tree, as selected-node lists.
inline std::vector<std::vector<std::uint32_t>> all_lods(const HmckpTree& t) {
  std::function<std::vector<std::vector<std::uint32_t>>(std::uint32_t)> expand = [&](std::uint32_t node) {
    std::vector<std::vector<std::uint32_t>> acc{{}};
    const HmckpNode& n = t.nodes[node];
    for (std::uint32_t a = n.first; a < n.first + n.count; ++a) {
      const std::uint32_t m = t.members[a];
      std::vector<std::vector<std::uint32_t>> opts{{m}};
      if (t.nodes[m].count > 0)
        for (auto& o : expand(m)) opts.push_back(o);
      std::vector<std::vector<std::uint32_t>> next;
      for (const auto& x : acc)
        for (const auto& o : opts) {
          auto y = x;
          y.insert(y.end(), o.begin(), o.end());
          next.push_back(std::move(y));
        }
      acc = std::move(next);
    }
    return acc;
  };
  return expand(0);
}

// A random hierarchy over small subsets whose values satisfy Mason's hierarchical convexity
// (every replacement set costs and profits more than what it replaces, with a lower relative
// value than the set containing it).
inline MckpInstance random_hierarchical(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> nr(2, 5), nm(1, 3), ng(1, 3), ni(0, 2);
  MckpInstance inst;
  const int r = nr(rng);
  for (int k = 0; k < r; ++k) {
    std::vector<MckpItem> items;
    const int m = nm(rng);
    for (int j = 0; j < m; ++j) items.push_back({0.0, double(j + 1)});  // placeholders
    inst.add_subset(items);
  }
  // Free units: (is_group, index). Merge random pairs into groups.
  std::vector<std::pair<bool, std::uint32_t>> free;
  for (int k = 0; k < r; ++k) free.push_back({false, std::uint32_t(k)});
  const int groups = ng(rng);
  for (int g = 0; g < groups && free.size() >= 2; ++g) {
    std::shuffle(free.begin(), free.end(), rng);
    MckpGroup grp;
    const std::size_t take = free.size() >= 3 && u(rng) < 0.3 ? 3 : 2;
    for (std::size_t a = 0; a < take; ++a) {
      auto [is_group, idx] = free.back();
      free.pop_back();
      (is_group ? grp.groups : grp.subsets).push_back(idx);
    }
    const int imps = ni(rng);
    for (int q = 0; q < imps; ++q) grp.impostors.push_back({0.0, double(q + 1)});
    inst.groups.push_back(grp);
    free.push_back({true, std::uint32_t(inst.groups.size() - 1)});
  }
  std::vector<std::uint32_t> order, offsets;
  cost_order(inst, order, offsets);
  HmckpTree t;
  build_hmckp_tree(inst, order, offsets, t);
  std::vector<MckpItem> val(t.nodes.size());
  std::vector<double> set_rv(t.nodes.size(), 0.0);  // RV of the set containing the node
  const HmckpNode& root = t.nodes[0];
  double sp = 0, sw = 0;
  for (std::uint32_t a = root.first; a < root.first + root.count; ++a) {
    const std::uint32_t m = t.members[a];
    val[m].cost = 1 + 2 * u(rng);
    val[m].profit = val[m].cost * (2 + u(rng));
    sp += val[m].profit;
    sw += val[m].cost;
  }
  for (std::uint32_t a = root.first; a < root.first + root.count; ++a) set_rv[t.members[a]] = sp / sw;
  // Nodes are created parents before children only for chains; walk breadth-first instead.
  std::vector<std::uint32_t> queue;
  for (std::uint32_t a = root.first; a < root.first + root.count; ++a) queue.push_back(t.members[a]);
  for (std::size_t qi = 0; qi < queue.size(); ++qi) {
    const std::uint32_t i = queue[qi];
    const HmckpNode& n = t.nodes[i];
    if (n.count == 0) continue;
    const double rho = set_rv[i] * (0.3 + 0.6 * u(rng));
    const double total_w = val[i].cost * (1.3 + 1.2 * u(rng));
    const double total_p = val[i].profit + rho * (total_w - val[i].cost);
    std::vector<double> share(n.count);
    double s = 0;
    for (double& x : share) s += (x = 0.5 + u(rng));
    for (std::uint32_t a = 0; a < n.count; ++a) {
      const std::uint32_t m = t.members[n.first + a];
      val[m].cost = total_w * share[a] / s;
      val[m].profit = total_p * share[a] / s;
      set_rv[m] = rho;
      queue.push_back(m);
    }
  }
  for (std::size_t i = 1; i < t.nodes.size(); ++i) {
    const HmckpNode& n = t.nodes[i];
    if (n.subset != kNoItem)
      inst.items[inst.subset_offsets[n.subset] + n.index] = val[i];
    else
      inst.groups[n.group].impostors[n.index] = val[i];
  }
  // Capacity between the lowest and the highest level.
  double lo = 0;
  for (std::uint32_t a = root.first; a < root.first + root.count; ++a) lo += val[t.members[a]].cost;
  double hi = lo;
  for (const auto& l : all_lods(t)) {
    double w = 0;
    for (std::uint32_t m : l) w += val[m].cost;
    hi = std::max(hi, w);
  }
  inst.capacity = lo + u(rng) * (hi - lo);
  return inst;
}

}  // namespace gazelod::budget::test
