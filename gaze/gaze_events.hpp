// SPDX-License-Identifier: Apache-2.0
// Groups labeled samples into fixation and saccade events (streaming), for statistics and
// for the replay source's "never interpolate across a saccade" rule.
#pragma once

#include "gaze/ivt_classifier.hpp"

#include <cstdint>
#include <optional>

namespace gazelod::gaze {

struct SaccadeEvent {
  std::int64_t start_ns = 0, end_ns = 0;  // first and last saccade-labelled sample
  double amplitude_deg = 0.0;             // angle between the directions at start and end
  double peak_velocity_deg_s = 0.0;
};

struct FixationEvent {
  std::int64_t start_ns = 0, end_ns = 0;
};

struct EventOptions {
  std::int64_t min_fixation_ns = 60'000'000;  // shorter fixation runs are not counted
};

class EventTracker {
 public:
  explicit EventTracker(EventOptions options = {}) : options_(options) {}
  // Feeds one labeled sample; returns a finished event when this sample ended one.
  struct Finished {
    std::optional<SaccadeEvent> saccade;
    std::optional<FixationEvent> fixation;
  };
  Finished push(const LabeledSample& s);
  Finished finish();  // closes the open event at end of stream

 private:
  Finished close();
  EventOptions options_;
  GazeLabel run_ = GazeLabel::unknown;
  LabeledSample first_, last_;
  double peak_ = 0.0;
};

}  // namespace gazelod::gaze
