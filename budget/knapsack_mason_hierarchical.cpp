// SPDX-License-Identifier: Apache-2.0
// Mason's greedy for the hierarchical MCKP (1999 Fig. 39-40, sec. 6.3): from the lowest level
// of detail, replace selected nodes by their replacement sets in decreasing relative value of
// the set; the first set that does not fit is critical, and the answer is compared with the
// cheapest level holding it (Fig. 40). Half-optimal under hierarchical convexity.
#include "budget/knapsack.hpp"
#include "budget/knapsack_heap.hpp"
#include "budget/mckp_hierarchy.hpp"

namespace gazelod::budget {

MckpSolution solve_mason_hierarchical(const MckpInstance& instance, bool fill_after_critical) {
  std::vector<std::uint32_t> kept, offsets;
  reduce_ip_dominated(instance, kept, offsets);
  HmckpTree tree;
  build_hmckp_tree(instance, kept, offsets, tree);
  const std::size_t n = tree.nodes.size();
  std::vector<MckpItem> item(n);
  {
    std::vector<MckpItem> imps;
    for (const MckpGroup& g : instance.groups) imps.insert(imps.end(), g.impostors.begin(), g.impostors.end());
    for (std::size_t i = 1; i < n; ++i) {
      const std::uint32_t src = tree.nodes[i].source;
      item[i] = src < instance.items.size() ? instance.items[src] : imps[src - instance.items.size()];
    }
  }
  std::vector<MckpItem> set(n);  // summed replacement set per node
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t a = tree.nodes[i].first; a < tree.nodes[i].first + tree.nodes[i].count; ++a) {
      set[i].profit += item[tree.members[a]].profit;
      set[i].cost += item[tree.members[a]].cost;
    }
  std::vector<double> key(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) key[i] = relative_value(item[i], set[i]);

  std::vector<std::uint8_t> selected(n, 0);
  KnapsackHeap heap(&key, &tree.stable_id, true);
  heap.reserve(n);
  double profit = set[0].profit, cost = set[0].cost;
  const double low_profit = profit, low_cost = cost;
  auto select = [&](std::uint32_t m) {
    selected[m] = 1;
    if (tree.nodes[m].count > 0) heap.push(m);
  };
  for (std::uint32_t a = 0; a < tree.nodes[0].count; ++a) select(tree.members[tree.nodes[0].first + a]);

  MckpSolution out;
  std::uint32_t critical = kNoItem;
  if (low_cost <= instance.capacity) {
    while (!heap.empty()) {
      const std::uint32_t i = heap.top();
      heap.erase(i);
      if (cost - item[i].cost + set[i].cost <= instance.capacity) {
        selected[i] = 0;
        cost += set[i].cost - item[i].cost;
        profit += set[i].profit - item[i].profit;
        for (std::uint32_t a = 0; a < tree.nodes[i].count; ++a) select(tree.members[tree.nodes[i].first + a]);
        continue;
      }
      if (critical == kNoItem) critical = i;
      if (!fill_after_critical) break;
    }
    out.error_bound = 0.0;
    if (critical != kNoItem) {
      out.error_bound = set[critical].profit - item[critical].profit;
      // Fig. 40: the lowest level with the critical node and its ancestors refined.
      double hp = low_profit, hw = low_cost;
      for (std::uint32_t u = critical; u != 0; u = tree.nodes[u].parent) {
        hp += set[u].profit - item[u].profit;
        hw += set[u].cost - item[u].cost;
      }
      if (hp > profit && hw <= instance.capacity) {
        std::fill(selected.begin(), selected.end(), 0);
        for (std::uint32_t a = 0; a < tree.nodes[0].count; ++a) selected[tree.members[tree.nodes[0].first + a]] = 1;
        std::vector<std::uint32_t> path;
        for (std::uint32_t u = critical; u != 0; u = tree.nodes[u].parent) path.push_back(u);
        for (auto it = path.rbegin(); it != path.rend(); ++it) {
          selected[*it] = 0;
          for (std::uint32_t a = 0; a < tree.nodes[*it].count; ++a)
            selected[tree.members[tree.nodes[*it].first + a]] = 1;
        }
      }
    }
  }
  out.choice.assign(instance.subset_count(), kNoItem);
  out.group_choice.assign(instance.groups.size(), kNoItem);
  for (std::size_t i = 1; i < n; ++i) {
    if (!selected[i]) continue;
    if (tree.nodes[i].subset != kNoItem)
      out.choice[tree.nodes[i].subset] = tree.nodes[i].index;
    else
      out.group_choice[tree.nodes[i].group] = tree.nodes[i].index;
  }
  evaluate(instance, out);
  return out;
}

}  // namespace gazelod::budget
