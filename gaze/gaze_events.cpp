// SPDX-License-Identifier: Apache-2.0
#include "gaze/gaze_events.hpp"

#include "auxiliary/angles.hpp"

namespace gazelod::gaze {

EventTracker::Finished EventTracker::close() {
  Finished f;
  if (run_ == GazeLabel::saccade) {
    f.saccade =
        SaccadeEvent{first_.sample.t_ns, last_.sample.t_ns,
                     aux::angle_between_rad(first_.sample.direction, last_.sample.direction) * aux::kDegPerRad, peak_};
  } else if (run_ == GazeLabel::fixation && last_.sample.t_ns - first_.sample.t_ns >= options_.min_fixation_ns) {
    f.fixation = FixationEvent{first_.sample.t_ns, last_.sample.t_ns};
  }
  run_ = GazeLabel::unknown;
  return f;
}

EventTracker::Finished EventTracker::push(const LabeledSample& s) {
  Finished f;
  if (s.label != run_) {
    f = close();
    run_ = s.label;
    first_ = s;
    peak_ = 0.0;
  }
  last_ = s;
  if (s.velocity_deg_s > peak_) peak_ = s.velocity_deg_s;
  return f;
}

EventTracker::Finished EventTracker::finish() {
  return close();
}

}  // namespace gazelod::gaze
