// SPDX-License-Identifier: Apache-2.0
// The simulated clock: XrTime is nanoseconds on a clock whose scenario time 0 is kTimeBaseNs,
// so scenario time = XrTime - kTimeBaseNs. Paced, the clock runs with CLOCK_MONOTONIC from
// instance creation; unpaced, only xrWaitFrame moves time (one display period per frame).
#pragma once

#include "auxiliary/time.hpp"
#include "sim/runtime/xr_headers.hpp"

#include <cstdint>

namespace gazelod::xrrt {

// XrTime of scenario time 0. Non-zero, so that a sample time of 0 ("unknown") stands out.
inline constexpr XrTime kTimeBaseNs = aux::ns_from_seconds(1.0);

class SimClock {
 public:
  void start(bool paced, double refresh_hz);

  bool paced() const { return paced_; }
  std::int64_t period_ns() const { return period_ns_; }
  // The current time: paced, from CLOCK_MONOTONIC; unpaced, the last frame's display time.
  XrTime now() const;
  // XrTime <-> CLOCK_MONOTONIC (XR_KHR_convert_timespec_time). Unpaced, the same mapping is
  // used; it is then unrelated to frame times.
  XrTime from_monotonic_ns(std::int64_t mono_ns) const { return kTimeBaseNs + (mono_ns - origin_mono_ns_); }
  std::int64_t to_monotonic_ns(XrTime t) const { return t - kTimeBaseNs + origin_mono_ns_; }
  // Called by xrWaitFrame with the predicted display time it returns (unpaced "now").
  void note_frame(XrTime predicted) { last_frame_time_ = predicted; }

  static std::int64_t monotonic_ns();
  static std::int64_t scenario_ns(XrTime t) { return t - kTimeBaseNs; }

 private:
  bool paced_ = true;
  std::int64_t period_ns_ = 11'111'111;
  std::int64_t origin_mono_ns_ = 0;
  XrTime last_frame_time_ = kTimeBaseNs;
};

}  // namespace gazelod::xrrt
