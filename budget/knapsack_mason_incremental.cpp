// SPDX-License-Identifier: Apache-2.0
// Mason's incremental predictive algorithm (1999, Fig. 41) on the replacement-set tree, with
// two indexed heaps (sec. 7.3) and truncation (sec. 9.3.5) by a move limit, so that the answer
// depends only on the inputs; a wall-clock limit applies only when the caller sets one. The
// same engine runs Funkhouser & Sequin's incremental algorithm when keyed by value instead of RV.
#include "budget/knapsack.hpp"
#include "budget/knapsack_incremental.hpp"

#include <chrono>
#include <cmath>

namespace gazelod::budget {

void IncrementalScheduler::reset(const MckpInstance& structure, const Options& options) {
  options_ = options;
  std::vector<std::uint32_t> order, offsets;
  if (options.drop_ip_dominated)
    reduce_ip_dominated(structure, order, offsets);
  else
    cost_order(structure, order, offsets);
  build_hmckp_tree(structure, order, offsets, tree_);
  const std::size_t n = tree_.nodes.size();
  selected_.assign(n, 0);
  full_.assign(n, 0);
  keys_.assign(n, 0.0);
  stack_.clear();
  stack_.reserve(n);
  std::size_t impostors = 0;
  for (const MckpGroup& g : structure.groups) impostors += g.impostors.size();
  impostor_items_.assign(impostors, MckpItem{});
  inc_.reserve(n);
  dec_.reserve(n);
  flat_ = structure.groups.empty();
  flat_dirty_ = true;
  pos_.assign(structure.subset_count(), 0);
  src_.resize(n);
  for (std::size_t i = 0; i < n; ++i) src_[i] = tree_.nodes[i].source;
  flat_identity_ = flat_ && n == structure.items.size() + 1;
  for (std::size_t i = 1; flat_identity_ && i < n; ++i) flat_identity_ = src_[i] == i - 1;
  // Forget the previous scene's frame coherence too: after reset() the scheduler behaves as a
  // new one (the same frames give the same answers and move counts).
  critical_key_ = 0.0;
  band_ = 0.05;
  band_lo_ = band_hi_ = 0.0;
  all_loaded_ = true;
}

double IncrementalScheduler::key_of(std::uint32_t node) const {
  const HmckpNode& nd = tree_.nodes[node];
  MckpItem set;
  for (std::uint32_t a = nd.first; a < nd.first + nd.count; ++a) {
    const MckpItem& m = item(tree_.members[a]);
    set.profit += m.profit;
    set.cost += m.cost;
  }
  if (options_.key == MoveKey::value) return item_value(set);
  return relative_value(item(node), set);
}

// Rebuilds the selection from the previous answer (top-down, so the result is always a valid
// level of detail whatever the input), and loads both heaps.
void IncrementalScheduler::place(std::span<const std::uint32_t> prev_choice,
                                 std::span<const std::uint32_t> prev_group_choice) {
  std::fill(selected_.begin(), selected_.end(), 0);
  std::fill(full_.begin(), full_.end(), 0);
  inc_.clear();
  dec_.clear();
  cost_ = profit_ = 0.0;
  const bool lowest = prev_choice.empty() && prev_group_choice.empty();
  const MckpInstance& f = *frame_;
  stack_.clear();
  stack_.push_back(0);
  while (!stack_.empty()) {
    const std::uint32_t e = stack_.back();
    stack_.pop_back();
    const HmckpNode& en = tree_.nodes[e];
    for (std::uint32_t a = en.first; a < en.first + en.count; ++a) {
      const std::uint32_t m = tree_.members[a];
      const HmckpNode& mn = tree_.nodes[m];
      if (mn.subset != kNoItem) {
        // A subset chain, entered at its cheapest node: select the remembered level directly
        // (its chain nodes are contiguous) instead of walking down the chain.
        std::uint32_t target = 0;
        if (mn.subset < prev_choice.size() && prev_choice[mn.subset] < f.subset_size(mn.subset))
          target = tree_.chain_pos[f.subset_offsets[mn.subset] + prev_choice[mn.subset]];
        const std::uint32_t sel = m + target;
        selected_[sel] = 1;
        const MckpItem& it = item(sel);
        profit_ += it.profit;
        cost_ += it.cost;
        if (target == 0) {
          full_[e] += 1;
        } else {
          full_[sel - 1] = 1;
          consider_dec(sel - 1);
        }
        if (tree_.nodes[sel].count > 0) consider_inc(sel);
        continue;
      }
      bool expand;
      {
        std::uint32_t gc = mn.group < prev_group_choice.size() ? prev_group_choice[mn.group] : (lowest ? 0u : kNoItem);
        const auto n_imp = static_cast<std::uint32_t>(f.groups[mn.group].impostors.size());
        if (gc != kNoItem && gc >= n_imp) gc = n_imp - 1;  // past the last: the last
        expand = gc == kNoItem || mn.index < gc;
      }
      if (expand && mn.count > 0) {
        stack_.push_back(m);
      } else {
        selected_[m] = 1;
        full_[e] += 1;
        const MckpItem& it = item(m);
        profit_ += it.profit;
        cost_ += it.cost;
        if (mn.count > 0) consider_inc(m);
      }
    }
    if (e != 0 && full_[e] == en.count) consider_dec(e);
  }
  inc_.heapify();
  dec_.heapify();
}

void IncrementalScheduler::consider_inc(std::uint32_t node) {
  keys_[node] = key_of(node);
  if (all_loaded_ || keys_[node] >= band_lo_) inc_.append(node);
}

void IncrementalScheduler::consider_dec(std::uint32_t node) {
  keys_[node] = key_of(node);
  if (all_loaded_ || keys_[node] <= band_hi_) dec_.append(node);
}

// Loads every increment and decrement candidate of the current state (keys are this frame's).
void IncrementalScheduler::load_all() {
  all_loaded_ = true;
  inc_.clear();
  dec_.clear();
  stack_.clear();
  stack_.push_back(0);
  while (!stack_.empty()) {
    const std::uint32_t e = stack_.back();
    stack_.pop_back();
    const HmckpNode& en = tree_.nodes[e];
    if (e != 0 && full_[e] == en.count) {
      keys_[e] = key_of(e);
      dec_.append(e);
    }
    for (std::uint32_t a = en.first; a < en.first + en.count; ++a) {
      const std::uint32_t m = tree_.members[a];
      if (!selected_[m]) {
        stack_.push_back(m);
      } else if (tree_.nodes[m].count > 0) {
        keys_[m] = key_of(m);
        inc_.append(m);
      }
    }
  }
  inc_.heapify();
  dec_.heapify();
}

void IncrementalScheduler::increment(std::uint32_t i) {
  const HmckpNode& nd = tree_.nodes[i];
  inc_.erase(i);
  selected_[i] = 0;
  const std::uint32_t p = nd.parent;
  if (p != 0) dec_.erase(p);
  if (!flat_) full_[p] -= 1;
  profit_ -= item(i).profit;
  cost_ -= item(i).cost;
  for (std::uint32_t a = nd.first; a < nd.first + nd.count; ++a) {
    const std::uint32_t m = tree_.members[a];
    selected_[m] = 1;
    profit_ += item(m).profit;
    cost_ += item(m).cost;
    if (tree_.nodes[m].count > 0) {
      keys_[m] = key_of(m);
      inc_.push(m);
    }
  }
  if (!flat_) full_[i] = nd.count;
  dec_.push(i);  // keys_[i] is still the key of its set
  if (flat_) pos_[nd.subset] = i + 1 - tree_.subset_chain[nd.subset];
}

void IncrementalScheduler::decrement(std::uint32_t j) {
  const HmckpNode& nd = tree_.nodes[j];
  dec_.erase(j);
  for (std::uint32_t a = nd.first; a < nd.first + nd.count; ++a) {
    const std::uint32_t m = tree_.members[a];
    selected_[m] = 0;
    profit_ -= item(m).profit;
    cost_ -= item(m).cost;
    inc_.erase(m);
  }
  if (!flat_) full_[j] = 0;
  selected_[j] = 1;
  profit_ += item(j).profit;
  cost_ += item(j).cost;
  inc_.push(j);
  if (flat_) pos_[nd.subset] = j - tree_.subset_chain[nd.subset];
  const std::uint32_t p = nd.parent;
  if (!flat_) full_[p] += 1;
  if (p != 0 && (flat_ || full_[p] == tree_.nodes[p].count)) {  // flat: sets of one
    keys_[p] = key_of(p);
    dec_.push(p);
  }
}

// Mason Fig. 40: the cheapest level of detail holding the critical set's replacement, i.e. the
// lowest level with the critical node and its ancestors refined.
void IncrementalScheduler::critical_solution(std::uint32_t critical, const MckpInstance& frame) {
  MckpItem h = lowest_;
  const HmckpNode& root = tree_.nodes[0];
  for (std::uint32_t u = critical; u != 0; u = tree_.nodes[u].parent) {
    const HmckpNode& nd = tree_.nodes[u];
    h.profit -= item(u).profit;
    h.cost -= item(u).cost;
    for (std::uint32_t a = nd.first; a < nd.first + nd.count; ++a) {
      h.profit += item(tree_.members[a]).profit;
      h.cost += item(tree_.members[a]).cost;
    }
  }
  if (!(h.cost <= frame.capacity && h.profit > profit_)) return;
  std::fill(selected_.begin(), selected_.end(), 0);
  for (std::uint32_t a = root.first; a < root.first + root.count; ++a) selected_[tree_.members[a]] = 1;
  stack_.clear();
  for (std::uint32_t u = critical; u != 0; u = tree_.nodes[u].parent) stack_.push_back(u);
  for (auto it = stack_.rbegin(); it != stack_.rend(); ++it) {  // top-down
    const HmckpNode& nd = tree_.nodes[*it];
    selected_[*it] = 0;
    for (std::uint32_t a = nd.first; a < nd.first + nd.count; ++a) selected_[tree_.members[a]] = 1;
  }
  profit_ = h.profit;
  cost_ = h.cost;
  if (flat_) {  // the critical node's object one level up, every other object at its lowest
    std::fill(pos_.begin(), pos_.end(), 0u);
    const std::uint32_t s = tree_.nodes[critical].subset;
    pos_[s] = critical + 1 - tree_.subset_chain[s];
    flat_dirty_ = true;  // selected_ was rewritten: clear it all next frame
  }
  notify();
}

void IncrementalScheduler::write(MckpSolution& out) const {
  if (flat_) {
    write_flat(out);
    return;
  }
  const MckpInstance& f = *frame_;
  out.choice.assign(f.subset_count(), kNoItem);
  out.group_choice.assign(f.groups.size(), kNoItem);
  double profit = 0.0, cost = 0.0;  // locals: stores to `out` would block vectorising
  // Walk the expanded part of the tree; stack_ is reused, so this is const in effect only.
  auto& stack = const_cast<std::vector<std::uint32_t>&>(stack_);
  stack.clear();
  stack.push_back(0);
  while (!stack.empty()) {
    const HmckpNode& en = tree_.nodes[stack.back()];
    stack.pop_back();
    for (std::uint32_t a = en.first; a < en.first + en.count; ++a) {
      std::uint32_t m = tree_.members[a];
      if (tree_.nodes[m].subset != kNoItem) {  // a subset chain: find its selected node
        const std::uint32_t end = m + tree_.subset_chain_len[tree_.nodes[m].subset];
        while (m + 1 < end && !selected_[m]) ++m;
      } else if (!selected_[m]) {
        stack.push_back(m);
        continue;
      }
      const HmckpNode& mn = tree_.nodes[m];
      if (mn.subset != kNoItem)
        out.choice[mn.subset] = mn.index;
      else
        out.group_choice[mn.group] = mn.index;
      const MckpItem& it = item(m);
      profit += it.profit;
      cost += it.cost;
    }
  }
  out.profit = profit;
  out.cost = cost;
  out.feasible = cost <= f.capacity;
}

void IncrementalScheduler::step(const MckpInstance& frame, std::span<const std::uint32_t> prev_choice,
                                std::span<const std::uint32_t> prev_group_choice, const SolveLimits& limits,
                                MckpSolution& out) {
  using Clock = std::chrono::steady_clock;
  // The clock is read only when the caller asked for a wall-clock limit.
  const bool timed = limits.wall_clock_limit.has_value();
  const Clock::time_point start = timed ? Clock::now() : Clock::time_point{};
  frame_ = &frame;
  items_ = frame.items.data();
  n_items_ = frame.items.size();
  std::size_t q = 0;
  for (const MckpGroup& g : frame.groups)
    for (const MckpItem& it : g.impostors)
      if (q < impostor_items_.size()) impostor_items_[q++] = it;
  out.truncated = false;
  out.error_bound = -1.0;
  out.iterations = 0;
  out.proven_optimal = false;

  all_loaded_ = !(critical_key_ > 0.0) || !std::isfinite(critical_key_) || band_ > 1e6;
  band_lo_ = critical_key_ * (1.0 - band_);
  band_hi_ = critical_key_ * (1.0 + band_);
  const bool banded = !all_loaded_;
  if (flat_) {
    place_flat(prev_choice);  // sums the lowest level on the way
  } else {
    lowest_ = MckpItem{};
    const HmckpNode& root = tree_.nodes[0];
    for (std::uint32_t a = root.first; a < root.first + root.count; ++a) {
      const MckpItem& it = item(tree_.members[a]);
      lowest_.profit += it.profit;
      lowest_.cost += it.cost;
    }
  }
  // Pre-test (F&S, Mason): when the lowest level does not fit, answer it, marked infeasible.
  if (lowest_.cost > frame.capacity) {
    if (flat_)
      place_flat({});
    else
      place({}, {});
    write(out);
    out.feasible = false;
    return;
  }
  if (!flat_) place(prev_choice, prev_group_choice);
  notify();

  const std::uint64_t move_cap = std::uint64_t{options_.max_moves_per_node} * tree_.nodes.size() + 64;
  std::uint64_t moves = 0;
  std::uint32_t last = kNoItem;
  bool done = false;
  for (std::uint64_t round = 1; !done; ++round) {
    last = kNoItem;
    // A left-out candidate could beat a heap's top: load them all (rare; widens the band).
    if (!all_loaded_ && (inc_.empty() || keys_[inc_.top()] < band_lo_)) reload();
    if (!inc_.empty()) {
      // Limits are checked before an increment only (nothing left to increment is convergence,
      // not truncation); the decrements below still make the frame fit.
      if (moves >= limits.max_moves || moves > move_cap ||
          (timed && (round & 15) == 0 && Clock::now() - start >= *limits.wall_clock_limit)) {
        out.truncated = true;
      } else {
        last = inc_.top();
        increment(last);
        ++moves;
        notify();
      }
    }
    bool decremented = false;
    while (cost_ > frame.capacity) {
      if (!all_loaded_ && (dec_.empty() || keys_[dec_.top()] > band_hi_)) reload();
      if (dec_.empty()) break;
      const std::uint32_t j = dec_.top();
      decrement(j);
      ++moves;
      decremented = true;
      notify();
      if (j == last) done = true;
    }
    if (out.truncated) break;
    if (last == kNoItem && !decremented) done = true;  // the highest level, and it fits
  }
  out.iterations = moves;
  if (!out.truncated) {
    // The critical set: the best increment left. Mason takes the set incremented and
    // decremented in the last round, which is the same set from a state below the greedy one
    // but not from one above it (then several sets go out in the last round).
    if (!all_loaded_ && (inc_.empty() || keys_[inc_.top()] < band_lo_)) reload();
    last = inc_.empty() ? kNoItem : inc_.top();
    // Next frame's band: around this critical key; wider after a miss, slowly narrower.
    critical_key_ = last == kNoItem ? 0.0 : keys_[last];
    if (banded) band_ = all_loaded_ ? band_ * 4.0 : std::max(band_ * 0.9, 0.02);
    if (last == kNoItem) {
      out.error_bound = 0.0;
    } else {
      const HmckpNode& nd = tree_.nodes[last];
      double set_profit = 0.0;
      for (std::uint32_t a = nd.first; a < nd.first + nd.count; ++a) set_profit += item(tree_.members[a]).profit;
      out.error_bound = set_profit - item(last).profit;
      if (options_.critical_check) critical_solution(last, frame);
    }
  }
  write(out);
  // Rounding drift of the running sum: the written cost is exact, so re-check it.
  if (!out.feasible) {
    cost_ = out.cost;
    while (cost_ > frame.capacity && !dec_.empty()) decrement(dec_.top());
    write(out);
  }
}

MckpSolution solve_mason_incremental(const MckpInstance& instance, const SolveLimits& limits) {
  IncrementalScheduler scheduler;
  IncrementalScheduler::Options options;
  options.drop_ip_dominated = true;
  scheduler.reset(instance, options);
  MckpSolution out;
  scheduler.step(instance, {}, {}, limits, out);
  return out;
}

}  // namespace gazelod::budget
