// SPDX-License-Identifier: Apache-2.0
// An indexed binary heap of node ids for the knapsack solvers: O(1) top, O(log n) push,
// erase and re-key, no allocation after reserve(). Order: the strict greedy order of
// mckp.hpp on (key, stable id), either first-in-order on top (max) or last-in-order (min).
#pragma once

#include "budget/mckp.hpp"

#include <cstdint>
#include <vector>

namespace gazelod::budget {

class KnapsackHeap {
 public:
  // `keys` and `ids` are indexed by node and must outlive the heap; `max_first`: the node
  // that comes first in the greedy order is on top, else the one that comes last.
  KnapsackHeap(const std::vector<double>* keys, const std::vector<std::uint32_t>* ids, bool max_first)
      : keys_(keys), ids_(ids), max_first_(max_first) {}

  void reserve(std::size_t universe) {
    pos_.assign(universe, kAbsent);
    heap_.reserve(universe);
  }
  void clear() {
    for (std::uint32_t n : heap_) pos_[n] = kAbsent;
    heap_.clear();
  }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  std::uint32_t top() const { return heap_.front(); }
  bool contains(std::uint32_t n) const { return pos_[n] != kAbsent; }

  // Bulk load: append without ordering, then heapify() once (O(n)).
  void append(std::uint32_t n) {
    pos_[n] = static_cast<std::uint32_t>(heap_.size());
    heap_.push_back(n);
  }
  void heapify() {
    for (std::size_t i = heap_.size() / 2; i-- > 0;) sift_down(i);
  }
  void push(std::uint32_t n) {
    append(n);
    sift_up(heap_.size() - 1);
  }
  void erase(std::uint32_t n) {
    const std::uint32_t i = pos_[n];
    if (i == kAbsent) return;
    const std::uint32_t last = heap_.back();
    heap_.pop_back();
    pos_[n] = kAbsent;
    if (last == n) return;
    heap_[i] = last;
    pos_[last] = i;
    sift_up(i);
    sift_down(pos_[last]);
  }

 private:
  static constexpr std::uint32_t kAbsent = 0xffffffffu;

  bool above(std::uint32_t a, std::uint32_t b) const {
    const double ka = (*keys_)[a], kb = (*keys_)[b];
    const std::uint32_t ia = (*ids_)[a], ib = (*ids_)[b];
    return max_first_ ? precedes(ka, ia, kb, ib) : precedes(kb, ib, ka, ia);
  }
  void place(std::size_t i, std::uint32_t n) {
    heap_[i] = n;
    pos_[n] = static_cast<std::uint32_t>(i);
  }
  void sift_up(std::size_t i) {
    const std::uint32_t n = heap_[i];
    while (i > 0) {
      const std::size_t p = (i - 1) / 2;
      if (!above(n, heap_[p])) break;
      place(i, heap_[p]);
      i = p;
    }
    place(i, n);
  }
  void sift_down(std::size_t i) {
    const std::uint32_t n = heap_[i];
    const std::size_t size = heap_.size();
    for (;;) {
      std::size_t c = 2 * i + 1;
      if (c >= size) break;
      if (c + 1 < size && above(heap_[c + 1], heap_[c])) ++c;
      if (!above(heap_[c], n)) break;
      place(i, heap_[c]);
      i = c;
    }
    place(i, n);
  }

  const std::vector<double>* keys_;
  const std::vector<std::uint32_t>* ids_;
  bool max_first_;
  std::vector<std::uint32_t> heap_;
  std::vector<std::uint32_t> pos_;
};

}  // namespace gazelod::budget
