// SPDX-License-Identifier: Apache-2.0
// A bounded queue between the HID reader thread (producer) and the frame loop (consumer).
// The producer never grows it past its capacity: when full it drops the oldest sample (new gaze
// is worth more than old) and counts the drop. The consumer never waits: drain() uses try_lock
// and, when the reader happens to hold the lock, returns nothing this time.
#pragma once

#include "gaze/gaze_sample.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

namespace gazelod::gaze::hid {

class SampleQueue {
 public:
  explicit SampleQueue(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

  void push(const GazeSample& s) {
    std::lock_guard lock(mutex_);
    if (q_.size() >= capacity_) {
      q_.pop_front();
      dropped_.fetch_add(1, std::memory_order_relaxed);
    }
    q_.push_back(s);
  }

  // Appends everything queued to `out` (oldest first). Never blocks; false if it had to skip.
  bool drain(std::vector<GazeSample>& out) {
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return false;
    out.insert(out.end(), q_.begin(), q_.end());
    q_.clear();
    return true;
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return q_.size();
  }
  std::size_t capacity() const { return capacity_; }
  std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::deque<GazeSample> q_;
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace gazelod::gaze::hid
