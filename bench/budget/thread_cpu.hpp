// SPDX-License-Identifier: Apache-2.0
// This thread's CPU time, for benchmarks on the shared VM: wall time there includes whatever
// the scheduler gave to other processes (other builds run), so both are reported.
#pragma once

#include <ctime>

namespace gazelod::budget::bench {

inline double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace gazelod::budget::bench
