// SPDX-License-Identifier: Apache-2.0
// The selection's thread pool (see cluster_thread_pool.hpp).
#include "lod/cluster/cluster_thread_pool.hpp"

#include <algorithm>

namespace gazelod::lod {

ClusterThreadPool::ClusterThreadPool(unsigned threads) {
  const unsigned workers = std::max(1u, threads) - 1;
  workers_.reserve(workers);
  for (unsigned t = 1; t <= workers; ++t) workers_.emplace_back([this, t] { loop(t); });
}

ClusterThreadPool::~ClusterThreadPool() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void ClusterThreadPool::work(unsigned thread) {
  for (std::size_t i; (i = next_.fetch_add(1, std::memory_order_relaxed)) < count_;) {
    try {
      fn_(context_, i, thread);
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      next_.store(count_, std::memory_order_relaxed);  // the others take no more tasks
    }
  }
}

void ClusterThreadPool::loop(unsigned thread) {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    work(thread);
    {
      const std::lock_guard lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }
}

void ClusterThreadPool::run_erased(std::size_t count, Fn fn, void* context) {
  if (workers_.empty() || count <= 1) {  // nothing to share: no wake-up
    for (std::size_t i = 0; i < count; ++i) fn(context, i, 0);
    return;
  }
  {
    const std::lock_guard lock(mutex_);
    fn_ = fn, context_ = context, count_ = count;
    next_.store(0, std::memory_order_relaxed);
    error_ = nullptr;
    busy_ = static_cast<unsigned>(workers_.size());
    ++generation_;
  }
  wake_.notify_all();
  work(0);
  std::exception_ptr error;
  {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return busy_ == 0; });
    error = error_;
    error_ = nullptr;
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace gazelod::lod
