// SPDX-License-Identifier: Apache-2.0
// The incremental scheduler's fast path for flat instances (no groups: one chain of levels per
// object, the frame-budget case). The general path walks the replacement-set tree with a stack
// and clears per-node state every frame; here a frame is one pass over the objects that reads
// the selected level and its two neighbours, computes the two candidate keys and heaps only
// those near last frame's critical key (the band, see knapsack_incremental.hpp). Same states,
// same moves, same answer as the general path.
#include "budget/knapsack_incremental.hpp"

#include <algorithm>

namespace gazelod::budget {

void IncrementalScheduler::place_flat(std::span<const std::uint32_t> prev_choice) {
  const MckpInstance& f = *frame_;
  const std::size_t r = f.subset_count();
  if (flat_dirty_) std::fill(selected_.begin(), selected_.end(), 0);
  inc_.clear();
  dec_.clear();
  double profit = 0.0, cost = 0.0, low_profit = 0.0, low_cost = 0.0;
  const std::uint32_t* chain = tree_.subset_chain.data();
  const std::uint32_t* chain_len = tree_.subset_chain_len.data();
  const std::uint32_t* offsets = f.subset_offsets.data();
  const std::uint32_t* src = src_.data();
  const MckpItem* items = items_;
  const bool all = all_loaded_, identity = flat_identity_, dirty = flat_dirty_;
  const double lo = band_lo_, hi = band_hi_;
  // Keys are stored only for heaped nodes (the heaps read nothing else; reload() recomputes).
  auto consider = [&](std::uint32_t sel, std::uint32_t target, std::uint32_t len, const MckpItem* prev,
                      const MckpItem& cur, const MckpItem* next) {
    if (target > 0) {
      const double key = move_key(*prev, cur);
      if (all || key <= hi) {
        keys_[sel - 1] = key;
        dec_.append(sel - 1);
      }
    }
    if (target + 1 < len) {
      const double key = move_key(cur, *next);
      if (all || key >= lo) {
        keys_[sel] = key;
        inc_.append(sel);
      }
    }
  };
  for (std::size_t k = 0; k < r; ++k) {
    const std::uint32_t off = offsets[k], size = offsets[k + 1] - off;
    const std::uint32_t base = identity ? off + 1 : chain[k];
    if (!dirty) selected_[base + pos_[k]] = 0;  // undo last frame's selection of this object
    std::uint32_t target = 0;
    if (k < prev_choice.size() && prev_choice[k] < size)
      target = identity ? prev_choice[k] : tree_.chain_pos[off + prev_choice[k]];
    pos_[k] = target;
    const std::uint32_t sel = base + target;
    selected_[sel] = 1;
    if (identity) {  // items of object k are its chain, in order
      const MckpItem* it = items + off;
      low_profit += it[0].profit;
      low_cost += it[0].cost;
      profit += it[target].profit;
      cost += it[target].cost;
      consider(sel, target, size, target > 0 ? it + target - 1 : nullptr, it[target],
               target + 1 < size ? it + target + 1 : nullptr);
    } else {
      const MckpItem& low = items[src[base]];
      const MckpItem& cur = items[src[sel]];
      low_profit += low.profit;
      low_cost += low.cost;
      profit += cur.profit;
      cost += cur.cost;
      const std::uint32_t len = chain_len[k];
      consider(sel, target, len, target > 0 ? &items[src[sel - 1]] : nullptr, cur,
               target + 1 < len ? &items[src[sel + 1]] : nullptr);
    }
  }
  flat_dirty_ = false;
  profit_ = profit;
  cost_ = cost;
  lowest_ = {low_profit, low_cost};
  inc_.heapify();
  dec_.heapify();
}

void IncrementalScheduler::load_all_flat() {
  all_loaded_ = true;
  inc_.clear();
  dec_.clear();
  const std::size_t r = frame_->subset_count();
  for (std::size_t k = 0; k < r; ++k) {
    const std::uint32_t sel = tree_.subset_chain[k] + pos_[k];
    const MckpItem& cur = items_[src_[sel]];
    if (pos_[k] > 0) {
      keys_[sel - 1] = move_key(items_[src_[sel - 1]], cur);
      dec_.append(sel - 1);
    }
    if (pos_[k] + 1 < tree_.subset_chain_len[k]) {
      keys_[sel] = move_key(cur, items_[src_[sel + 1]]);
      inc_.append(sel);
    }
  }
  inc_.heapify();
  dec_.heapify();
}

// The running sums (this frame's placement plus each move's delta) are the ones the moves were
// decided on, so the reported cost and feasibility agree with the decisions.
void IncrementalScheduler::write_flat(MckpSolution& out) const {
  const MckpInstance& f = *frame_;
  const std::size_t r = f.subset_count();
  out.choice.resize(r);
  out.group_choice.clear();
  if (flat_identity_) {
    std::copy(pos_.begin(), pos_.end(), out.choice.begin());
  } else {
    for (std::size_t k = 0; k < r; ++k) out.choice[k] = src_[tree_.subset_chain[k] + pos_[k]] - f.subset_offsets[k];
  }
  out.profit = profit_;
  out.cost = cost_;
  out.feasible = cost_ <= f.capacity;
}

}  // namespace gazelod::budget
