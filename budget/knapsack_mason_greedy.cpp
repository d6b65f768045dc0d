// SPDX-License-Identifier: Apache-2.0
// Mason's simplified greedy for the MCKP (1999 Fig. 20, sec. 3.3-3.4): after IP-dominance
// preprocessing, start from every object's cheapest item and apply upgrades in decreasing
// relative value; the first upgrade that does not fit is the critical item s, and the answer
// is compared with the critical-item solution. Half-optimal under convexity, error <= p_s - p_t.
#include "budget/knapsack.hpp"

#include <algorithm>

namespace gazelod::budget {

MckpSolution solve_mason_greedy(const MckpInstance& instance, bool fill_after_critical) {
  const std::size_t r = instance.subset_count();
  std::vector<std::uint32_t> kept, offsets;
  reduce_ip_dominated(instance, kept, offsets);

  MckpSolution out;
  out.group_choice.assign(instance.groups.size(), kNoItem);
  std::vector<std::uint32_t> pos(r, 0);  // position in the kept chain
  double base_profit = 0.0, base_cost = 0.0;
  for (std::size_t k = 0; k < r; ++k) {
    const MckpItem& b = instance.subset(k)[kept[offsets[k]]];
    base_profit += b.profit;
    base_cost += b.cost;
  }
  auto finish = [&]() {
    out.choice.resize(r);
    for (std::size_t k = 0; k < r; ++k) out.choice[k] = kept[offsets[k] + pos[k]];
    MckpInstance flat = instance;
    flat.groups.clear();
    evaluate(flat, out);
  };
  if (base_cost > instance.capacity) {  // not even the lowest level fits
    finish();
    return out;
  }

  struct Move {
    double rv;
    std::uint32_t id;  // stable: the global index of the item moved to
    std::uint32_t subset, pos;
  };
  std::vector<Move> moves;
  for (std::uint32_t k = 0; k < r; ++k) {
    const auto items = instance.subset(k);
    for (std::uint32_t a = offsets[k] + 1; a < offsets[k + 1]; ++a)
      moves.push_back({relative_value(items[kept[a - 1]], items[kept[a]]), instance.subset_offsets[k] + kept[a], k,
                       a - offsets[k]});
  }
  std::sort(moves.begin(), moves.end(), [](const Move& a, const Move& b) { return precedes(a.rv, a.id, b.rv, b.id); });

  double profit = base_profit, cost = base_cost;
  std::vector<std::uint8_t> rejected(r, 0);
  const Move* critical = nullptr;
  double critical_t_profit = 0.0;
  for (const Move& m : moves) {
    if (rejected[m.subset] || m.pos <= pos[m.subset]) continue;  // never move down
    const auto items = instance.subset(m.subset);
    const MckpItem& cur = items[kept[offsets[m.subset] + pos[m.subset]]];
    const MckpItem& nxt = items[kept[offsets[m.subset] + m.pos]];
    if (cost - cur.cost + nxt.cost <= instance.capacity) {
      cost += nxt.cost - cur.cost;
      profit += nxt.profit - cur.profit;
      pos[m.subset] = m.pos;
      continue;
    }
    rejected[m.subset] = 1;
    if (!critical) {
      critical = &m;
      critical_t_profit = cur.profit;
    }
    if (!fill_after_critical) break;
  }
  out.error_bound = 0.0;
  if (critical) {
    const auto items = instance.subset(critical->subset);
    const MckpItem& s = items[kept[offsets[critical->subset] + critical->pos]];
    const MckpItem& b = items[kept[offsets[critical->subset]]];
    out.error_bound = s.profit - critical_t_profit;
    const double p = base_profit - b.profit + s.profit;
    const double w = base_cost - b.cost + s.cost;
    if (p > profit && w <= instance.capacity) {  // the critical-item solution is better
      std::fill(pos.begin(), pos.end(), 0u);
      pos[critical->subset] = critical->pos;
    }
  }
  finish();
  return out;
}

}  // namespace gazelod::budget
