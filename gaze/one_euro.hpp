// Fixation smoothing with the One Euro filter (Casiez, Roussel & Vogel 2012, CHI): a low-pass
// whose cutoff rises with speed, applied to gaze direction on the sphere (the smoothed
// direction is slerped toward each raw one by the filter's alpha). Saccades are left raw: a
// sample labelled saccade (I-VT), or one more than saccade_jump_deg from the smoothed gaze,
// is passed through unchanged and restarts the filter. Invalid samples pass through and reset it.
// The raw sample is never modified; callers keep both.
#pragma once

#include "gaze/gaze_sample.hpp"
#include "gaze/ivt_classifier.hpp"

#include <optional>

namespace gazelod::gaze {

struct OneEuroOptions {
  double min_cutoff_hz = 1.0;   // smoothing at rest (lower = smoother, more lag)
  double beta = 0.02;           // cutoff increase per deg/s of speed
  double d_cutoff_hz = 1.0;     // cutoff of the speed estimate
  double saccade_jump_deg = 1.0;  // a raw sample this far from the smoothed one is left raw
};

class FixationSmoother {
 public:
  explicit FixationSmoother(OneEuroOptions options = {}) : options_(options) {}
  // The smoothed sample for `raw` (same time, validity, confidence).
  GazeSample filter(const GazeSample& raw, GazeLabel label = GazeLabel::unknown);
  void reset() { state_.reset(); }

 private:
  struct State {
    GazeSample last;        // last smoothed sample
    double speed_deg_s = 0;  // filtered speed
  };
  OneEuroOptions options_;
  std::optional<State> state_;
};

}  // namespace gazelod::gaze
