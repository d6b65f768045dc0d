// SPDX-License-Identifier: Apache-2.0
// A fixed pool of threads for the per-frame cluster selection (cluster_selector.hpp): started
// once, woken per frame (a frame must not pay for creating threads), each run's tasks taken in
// turn from a shared counter by the workers and the calling thread. Every task writes only its
// own output, so results do not depend on which thread ran what.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace gazelod::lod {

class ClusterThreadPool {
 public:
  // threads >= 1 in all, the caller's among them: threads - 1 workers start here.
  explicit ClusterThreadPool(unsigned threads);
  ~ClusterThreadPool();  // stops and joins the workers
  ClusterThreadPool(const ClusterThreadPool&) = delete;
  ClusterThreadPool& operator=(const ClusterThreadPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

  // Runs task(i, thread) for every i < count (thread < threads(): 0 is the caller's) and returns
  // when all have finished; rethrows the first exception a task threw (the others' tasks then
  // stop being taken). One run at a time: not to be called from two threads at once.
  template <typename Task>
  void run(std::size_t count, Task& task) {
    run_erased(
        count, [](void* t, std::size_t i, unsigned thread) { (*static_cast<Task*>(t))(i, thread); }, &task);
  }

 private:
  using Fn = void (*)(void*, std::size_t, unsigned);
  void run_erased(std::size_t count, Fn fn, void* context);
  void work(unsigned thread);  // takes tasks until none is left
  void loop(unsigned thread);  // a worker: waits for runs

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  // The current run, written under mutex_ before generation_ moves (a worker reads them after it
  // saw the new generation under mutex_).
  Fn fn_ = nullptr;
  void* context_ = nullptr;
  std::size_t count_ = 0;
  std::uint64_t generation_ = 0;
  unsigned busy_ = 0;  // workers not yet done with the current run
  bool stop_ = false;
  std::exception_ptr error_;
  std::atomic<std::size_t> next_{0};
  std::vector<std::thread> workers_;
};

}  // namespace gazelod::lod
