// SPDX-License-Identifier: Apache-2.0
// The HID eye tracker as a GazeSource: the frame loop asks for gaze at time t and gets the
// newest valid sample taken at or before t, held for at most `max_hold_ns` (a blink or a late
// report), else nothing. sample_at() only drains the reader thread's queue (never blocks).
#pragma once

#include "gaze/gaze_source.hpp"
#include "gaze/hid/hid_tracker.hpp"

#include <cstdint>
#include <deque>
#include <vector>

namespace gazelod::gaze::hid {

class HidGazeSource : public GazeSource {
 public:
  // Starts the device thread. max_hold_ns: how long a sample stays usable (default 100 ms).
  explicit HidGazeSource(HidTrackerConfig config, std::int64_t max_hold_ns = 100'000'000);

  std::string name() const override { return "hid"; }
  std::optional<GazeSample> sample_at(std::int64_t t_ns) override;
  std::string status() const override;

  HidTracker& tracker() { return tracker_; }

 private:
  HidTracker tracker_;
  std::int64_t max_hold_ns_;
  std::vector<GazeSample> incoming_;
  std::deque<GazeSample> history_;  // recent valid samples, oldest first
};

}  // namespace gazelod::gaze::hid
