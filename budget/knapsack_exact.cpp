// SPDX-License-Identifier: Apache-2.0
// Exact MCKP by depth-first branch and bound over objects, bounded by the linear relaxation
// of the remaining objects (the upper convex hull of each, filled by slope). For tests and
// small scenes: exponential in the worst case, so it stops at a node limit and then says the
// answer is not proven optimal.
#include "budget/knapsack.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gazelod::budget {
namespace {

struct Step {
  double slope, dp, dw;
};

class BranchAndBound {
 public:
  BranchAndBound(const MckpInstance& inst, std::uint64_t node_limit) : inst_(inst), limit_(node_limit) {
    reduce_ip_dominated(inst, kept_, offsets_);
    const std::size_t r = inst.subset_count();
    // Suffix relaxations: for objects k.., the hull steps sorted by slope with running sums.
    suffix_.resize(r + 1);
    base_p_.assign(r + 1, 0.0);
    base_w_.assign(r + 1, 0.0);
    std::size_t total = 0;
    for (std::size_t k = r; k-- > 0;) {
      std::vector<Step> own = hull_steps(k);
      total += own.size() * (r - k);
      if (total > 30'000'000) throw std::invalid_argument("exact: instance too large for branch and bound");
      std::vector<Step>& s = suffix_[k];
      s.resize(own.size() + suffix_[k + 1].size());
      std::merge(own.begin(), own.end(), suffix_[k + 1].begin(), suffix_[k + 1].end(), s.begin(),
                 [](const Step& a, const Step& b) { return a.slope > b.slope; });
      const MckpItem& b = inst.subset(k)[kept_[offsets_[k]]];
      base_p_[k] = base_p_[k + 1] + b.profit;
      base_w_[k] = base_w_[k + 1] + b.cost;
    }
    cum_w_.resize(r + 1);
    cum_p_.resize(r + 1);
    for (std::size_t k = 0; k <= r; ++k) {
      cum_w_[k].resize(suffix_[k].size() + 1, 0.0);
      cum_p_[k].resize(suffix_[k].size() + 1, 0.0);
      for (std::size_t a = 0; a < suffix_[k].size(); ++a) {
        cum_w_[k][a + 1] = cum_w_[k][a] + suffix_[k][a].dw;
        cum_p_[k][a + 1] = cum_p_[k][a] + suffix_[k][a].dp;
      }
    }
    current_.assign(r, 0);
    best_choice_.assign(r, 0);
  }

  void set_incumbent(const MckpSolution& s) {
    if (!s.feasible) return;
    best_ = s.profit;
    for (std::size_t k = 0; k < s.choice.size(); ++k) {
      for (std::uint32_t a = offsets_[k]; a < offsets_[k + 1]; ++a)
        if (kept_[a] == s.choice[k]) best_choice_[k] = a - offsets_[k];
    }
    have_ = true;
  }

  bool run() {
    if (base_w_[0] > inst_.capacity) return true;
    dfs(0, inst_.capacity, 0.0);
    return nodes_ <= limit_;
  }
  bool have() const { return have_; }
  std::uint64_t nodes() const { return nodes_; }
  std::uint32_t choice(std::size_t k) const { return kept_[offsets_[k] + best_choice_[k]]; }

 private:
  std::vector<Step> hull_steps(std::size_t k) const {
    const auto items = inst_.subset(k);
    std::vector<std::uint32_t> hull;
    for (std::uint32_t a = offsets_[k]; a < offsets_[k + 1]; ++a) {
      while (hull.size() >= 2 && relative_value(items[hull[hull.size() - 2]], items[hull.back()]) <=
                                     relative_value(items[hull.back()], items[kept_[a]]))
        hull.pop_back();
      hull.push_back(kept_[a]);
    }
    std::vector<Step> steps;
    for (std::size_t h = 1; h < hull.size(); ++h) {
      const MckpItem& a = items[hull[h - 1]];
      const MckpItem& b = items[hull[h]];
      steps.push_back({relative_value(a, b), b.profit - a.profit, b.cost - a.cost});
    }
    return steps;
  }

  // LP optimum of objects k.. with `room` capacity.
  double bound(std::size_t k, double room) const {
    room -= base_w_[k];
    if (room < 0.0) return -INFINITY;
    const auto& cw = cum_w_[k];
    const std::size_t a = static_cast<std::size_t>(std::upper_bound(cw.begin(), cw.end(), room) - cw.begin()) - 1;
    double p = base_p_[k] + cum_p_[k][a];
    if (a < suffix_[k].size() && suffix_[k][a].dw > 0.0) p += suffix_[k][a].dp * ((room - cw[a]) / suffix_[k][a].dw);
    return p;
  }

  void dfs(std::size_t k, double room, double profit) {
    if (++nodes_ > limit_) return;
    const std::size_t r = inst_.subset_count();
    if (k == r) {
      if (!have_ || profit > best_) {
        best_ = profit;
        best_choice_ = current_;
        have_ = true;
      }
      return;
    }
    const double ub = profit + bound(k, room);
    if (have_ && ub <= best_ + 1e-12 * std::max(1.0, std::fabs(best_))) return;
    const auto items = inst_.subset(k);
    for (std::uint32_t a = offsets_[k + 1]; a-- > offsets_[k];) {  // finest first
      const MckpItem& it = items[kept_[a]];
      if (room - it.cost < base_w_[k + 1]) continue;
      current_[k] = a - offsets_[k];
      dfs(k + 1, room - it.cost, profit + it.profit);
      if (nodes_ > limit_) return;
    }
  }

  const MckpInstance& inst_;
  std::uint64_t limit_;
  std::uint64_t nodes_ = 0;
  std::vector<std::uint32_t> kept_, offsets_;
  std::vector<std::vector<Step>> suffix_;
  std::vector<std::vector<double>> cum_w_, cum_p_;
  std::vector<double> base_p_, base_w_;
  std::vector<std::uint32_t> current_, best_choice_;
  double best_ = 0.0;
  bool have_ = false;
};

}  // namespace

MckpSolution solve_exact(const MckpInstance& instance, std::uint64_t node_limit) {
  MckpInstance flat = instance;
  flat.groups.clear();
  BranchAndBound bb(flat, node_limit);
  try {
    bb.set_incumbent(solve_mason_full(flat));  // the starting answer
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("exact: its starting answer: ") + e.what());
  }
  const bool finished = bb.run();
  MckpSolution out;
  out.choice.resize(flat.subset_count());
  for (std::size_t k = 0; k < out.choice.size(); ++k) out.choice[k] = bb.choice(k);
  evaluate(flat, out);
  out.group_choice.assign(instance.groups.size(), kNoItem);
  out.iterations = bb.nodes();
  out.proven_optimal = finished && out.feasible;
  out.error_bound = out.proven_optimal ? 0.0 : -1.0;
  return out;
}

}  // namespace gazelod::budget
