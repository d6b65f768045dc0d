// SPDX-License-Identifier: Apache-2.0
// The simulated clock (see sim_clock.hpp).
#include "sim/runtime/sim_clock.hpp"

#include "auxiliary/time.hpp"

#include <cmath>

namespace gazelod::xrrt {

void SimClock::start(bool paced, double refresh_hz) {
  paced_ = paced;
  // Guarded: the scenario loader checks the rate, but a zero or NaN must not divide here.
  const double hz = std::isfinite(refresh_hz) && refresh_hz >= 1.0 ? refresh_hz : 90.0;
  period_ns_ = aux::period_ns_from_hz(hz);
  origin_mono_ns_ = monotonic_ns();
  last_frame_time_ = kTimeBaseNs;
}

XrTime SimClock::now() const {
  if (paced_) return from_monotonic_ns(monotonic_ns());
  return last_frame_time_;
}

std::int64_t SimClock::monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return aux::ns_from_timespec(ts);
}

}  // namespace gazelod::xrrt
