// SPDX-License-Identifier: Apache-2.0
// The bake's one way of running work on several threads: items taken in turn from a shared
// counter by `threads` threads (the caller's among them), each task told which thread runs it
// (for per-thread scratch). Every task must write only its own output, so that the result is
// the same for any thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace gazelod::bake {

// 0 threads: one per core.
inline unsigned thread_count(unsigned threads) {
  return threads ? threads : std::max(1u, std::thread::hardware_concurrency());
}

// Runs task(i, thread) for every i < count on min(threads, count) threads (thread < that);
// rethrows the first exception a thread caught (e.g. bad_alloc), after the others stopped.
template <typename Task>
void parallel_for(std::size_t count, unsigned threads, Task&& task) {
  threads = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, count)));
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failed(threads);
  auto work = [&](unsigned t) {
    try {
      for (std::size_t i; (i = next.fetch_add(1)) < count;) task(i, t);
    } catch (...) {
      failed[t] = std::current_exception();
      next = count;
    }
  };
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace gazelod::bake
