// SPDX-License-Identifier: Apache-2.0
// Maps a tracker's device timestamps (microseconds, on its own clock) to the host clock the
// frame loop uses (nanoseconds), estimating offset and drift from (device time, host receive
// time) pairs. The USB transfer only ever adds latency, so the lowest "receive - device" values
// are the best offset estimates: we keep the minimum per window of device time and fit a line
// through those minima (offset + drift * t), the usual lower-envelope clock sync.
//
// Timestamp wrap-around: only the low `counter_bits` bits of the device timestamp are trusted
// and unwrapped modulo 2^counter_bits. With the default 32 bits this handles trackers with a
// 32-bit microsecond counter (wraps every 71.6 minutes) and, just as well, 64-bit ones, as long
// as consecutive reports are less than half a wrap (35 minutes) apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>

namespace gazelod::gaze::hid {

struct ClockMapConfig {
  int counter_bits = 32;                             // 8..64
  std::int64_t window_ns = 500'000'000;              // one offset minimum per 0.5 s of device time
  std::size_t max_windows = 40;                      // fit over the last ~20 s
  double max_drift_ppm = 1000.0;                     // crystals are within ~100 ppm; clamp the fit
  std::int64_t max_forward_gap_ns = 10'000'000'000;  // a larger jump means a restarted device
  std::int64_t stale_drop_ns = 1'000'000;            // a window's minimum this far under the fit: earlier ones dropped
};

class ClockMap {
 public:
  explicit ClockMap(ClockMapConfig config = {});

  // Feeds one report: its device timestamp and when the host received it. Returns the host
  // time at which the sample was taken: never later than `host_receive_ns`, never before the
  // previous sample's (after a restart of the device clock, its receive time).
  std::int64_t map(std::uint64_t device_us, std::int64_t host_receive_ns);

  // Forgets everything (after a reconnect the device clock may have restarted).
  void reset();

  double drift_ppm() const { return slope_ * 1e6; }
  // Offset (host - device) at the most recent sample, in ns.
  std::int64_t offset_ns() const;
  // How many times the device clock jumped (backwards or by more than max_forward_gap_ns).
  std::size_t clock_resets() const { return clock_resets_; }
  // The unwrapped device time of the last sample, ns since the first sample after a reset.
  std::int64_t device_ns() const { return device_ns_; }

 private:
  struct Window {
    std::int64_t device_ns;  // device time of the minimum
    double offset_ns;        // its host - device offset
  };
  void restart(std::uint64_t raw, std::int64_t host_receive_ns);
  void refit();
  double offset_at(std::int64_t device_ns) const;

  ClockMapConfig config_;
  std::uint64_t mask_;
  bool started_ = false;
  std::uint64_t last_raw_ = 0;
  std::int64_t device_ns_ = 0;
  std::int64_t window_start_ns_ = 0;
  std::int64_t last_mapped_ns_ = 0;
  std::deque<Window> windows_;                            // completed windows, then the current one at the back
  double fit_x_ns_ = 0.0, fit_y_ns_ = 0.0, slope_ = 0.0;  // offset(x) = fit_y + slope (x - fit_x)
  std::size_t clock_resets_ = 0;
};

}  // namespace gazelod::gaze::hid
