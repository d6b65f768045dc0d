// SPDX-License-Identifier: Apache-2.0
// Frame-coherent LOD scheduling (Mason 1999 Fig. 41, sec. 9.3.5; Funkhouser & Sequin 1993
// sec. 6): start from the previous frame's selection, increment the best replacement set,
// decrement the worst until the frame fits, stop when the same set goes in and out or when the
// move limit is reached (SolveLimits, mckp.hpp: deterministic; a wall-clock limit only if the
// caller sets one). Set up once per scene structure; step() then allocates nothing.
#pragma once

#include "budget/knapsack_heap.hpp"
#include "budget/mckp.hpp"
#include "budget/mckp_hierarchy.hpp"

#include <span>
#include <vector>

namespace gazelod::budget {

enum class MoveKey : std::uint8_t {
  relative_value,  // Mason: (sum_R p - p_i) / (sum_R w - w_i)
  value,           // Funkhouser & Sequin: sum_R p / sum_R w (flawed, kept for comparison)
};

class IncrementalScheduler {
 public:
  struct Options {
    MoveKey key = MoveKey::relative_value;
    // Drop IP-dominated items at setup (by the setup instance's profits). Off for a scene whose
    // profits change per frame: the chain is then every item in cost order.
    bool drop_ip_dominated = false;
    // Compare with the critical-replacement-set solution after normal termination (the check
    // that makes the answer half-optimal; Mason skipped it in practice).
    bool critical_check = true;
    // Safety stop against ties and non-convex input: at most this many moves per node.
    std::uint32_t max_moves_per_node = 8;
  };

  // Called after every increment and every decrement (tests check each intermediate state).
  using Observer = void (*)(void* context, const IncrementalScheduler& scheduler);

  IncrementalScheduler() = default;
  IncrementalScheduler(const IncrementalScheduler&) = delete;  // the heaps point into members
  IncrementalScheduler& operator=(const IncrementalScheduler&) = delete;

  // Setup for one scene structure (subset sizes, groups). Allocates.
  void reset(const MckpInstance& structure, const Options& options);
  void reset(const MckpInstance& structure) { reset(structure, Options{}); }

  // One frame. `frame` has the structure given to reset() with this frame's profits, costs and
  // capacity. `prev_choice` / `prev_group_choice` are the previous frame's answer (as in
  // MckpSolution; empty spans mean the lowest level). `limits` bounds the optimisation: the
  // answer is a function of the inputs, `limits.max_moves` and the scheduler's state (the
  // previous frames) unless `limits.wall_clock_limit` is set; out.truncated says it stopped at
  // a limit. It is always a complete, affordable level of detail when the lowest one fits.
  // `out` is overwritten; it allocates only the first time.
  void step(const MckpInstance& frame, std::span<const std::uint32_t> prev_choice,
            std::span<const std::uint32_t> prev_group_choice, const SolveLimits& limits, MckpSolution& out);

  void set_observer(Observer observer, void* context) {
    observer_ = observer;
    observer_context_ = context;
  }
  const HmckpTree& tree() const { return tree_; }
  std::span<const std::uint8_t> selected() const { return selected_; }
  double current_cost() const { return cost_; }

 private:
  const MckpItem& item(std::uint32_t node) const {
    const std::uint32_t src = tree_.nodes[node].source;
    return src < n_items_ ? items_[src] : impostor_items_[src - n_items_];
  }
  double key_of(std::uint32_t node) const;  // key of replacing `node` by its set
  void place(std::span<const std::uint32_t> prev_choice, std::span<const std::uint32_t> prev_group_choice);
  void critical_solution(std::uint32_t critical, const MckpInstance& frame);
  // Flat instances (no groups: one chain per subset) take a fast path, in
  // knapsack_incremental_flat.cpp: one pass over the objects per frame, no tree walks.
  double move_key(const MckpItem& from, const MckpItem& to) const {
    return options_.key == MoveKey::value ? item_value(to) : relative_value(from, to);
  }
  void place_flat(std::span<const std::uint32_t> prev_choice);
  void load_all_flat();
  void reload() {
    if (flat_)
      load_all_flat();
    else
      load_all();
  }
  void write_flat(MckpSolution& out) const;
  void consider_inc(std::uint32_t node);  // load into the heap, or leave out if far below the band
  void consider_dec(std::uint32_t node);
  void load_all();  // the band was too narrow: load every candidate
  void increment(std::uint32_t node);
  void decrement(std::uint32_t node);
  void write(MckpSolution& out) const;
  void notify() const {
    if (observer_) observer_(observer_context_, *this);
  }

  Options options_;
  HmckpTree tree_;
  bool flat_ = false;       // no groups: every node but the root is a chain node
  bool flat_dirty_ = true;  // selected_ does not match pos_: clear it all
  // Flat, nothing dropped and every subset's items already in cost order: node 1 + j is item j
  // (no index tables to read per frame). full_ is not kept on the flat path.
  std::vector<std::uint32_t> pos_;  // flat: per subset, the selected chain position
  std::vector<std::uint32_t> src_;  // flat: per node, its index into the frame's items
  bool flat_identity_ = false;
  const MckpInstance* frame_ = nullptr;
  const MckpItem* items_ = nullptr;  // frame_->items, cached for the hot loops
  std::size_t n_items_ = 0;
  std::vector<MckpItem> impostor_items_;  // this frame's group impostors, by node source
  std::vector<std::uint8_t> selected_;    // per node
  std::vector<std::uint32_t> full_;       // per node: members of its set now selected
  std::vector<double> keys_;              // per node
  std::vector<std::uint32_t> stack_;
  KnapsackHeap inc_{&keys_, &tree_.stable_id, true};   // selected nodes with a set
  KnapsackHeap dec_{&keys_, &tree_.stable_id, false};  // nodes whose whole set is selected
  double cost_ = 0.0;
  double profit_ = 0.0;
  MckpItem lowest_;  // this frame's lowest level of detail (sums)
  // Frame coherence: moves happen near last frame's critical key, so only candidates whose key
  // lies in [band_lo_, band_hi_] are heaped. Exact: whenever a heap's top might be beaten by a
  // left-out candidate, every candidate is loaded (load_all) and the band widens next frame.
  double critical_key_ = 0.0;  // last frame's; 0 = none (load everything)
  double band_ = 0.05;         // relative half-width
  double band_lo_ = 0.0, band_hi_ = 0.0;
  bool all_loaded_ = true;
  Observer observer_ = nullptr;
  void* observer_context_ = nullptr;
};

}  // namespace gazelod::budget
