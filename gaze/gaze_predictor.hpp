// Prediction of gaze to a display time (the time the frame will be seen), for the foveal
// cone. During fixation / smooth pursuit the direction is extrapolated at the recent angular
// velocity (least-squares over a short window), for at most max_horizon; beyond it the
// prediction stops moving. During a saccade nothing is extrapolated (its landing point is not
// predictable from its start with a velocity model) and the sample is held.
// The uncertainty grows with the requested horizon h (never shrinks, capped):
//   accuracy + (drift + velocity_error_fraction * |v|) * h   [+ |v| * h while in a saccade]
// so the cone widens the further ahead the renderer asks.
#pragma once

#include "gaze/gaze_sample.hpp"
#include "gaze/main_sequence.hpp"

#include <cstdint>
#include <deque>
#include <optional>

namespace gazelod::gaze {

struct PredictorOptions {
  std::int64_t max_horizon_ns = 50'000'000;   // extrapolate at most 50 ms
  std::size_t window = 5;                     // samples in the velocity fit
  std::int64_t max_gap_ns = 25'000'000;       // older / gapped samples leave the window
  double accuracy_deg = 0.5;                  // tracker accuracy at h = 0
  double drift_deg_s = 10.0;                  // unmodelled motion per second of horizon
  double velocity_error_fraction = 0.25;      // relative error of the velocity estimate
  double saccade_threshold_deg_s = main_sequence::kIvtThreshold_deg_s;
  double max_uncertainty_deg = 60.0;
};

struct Prediction {
  GazeSample sample;            // direction at the display time (t_ns = display time)
  double uncertainty_deg = 0.0;  // half-angle to add to the foveal cone
  std::int64_t horizon_ns = 0;   // display time - newest sample time (requested, >= 0)
  bool clamped = false;          // horizon exceeded max_horizon
  bool in_saccade = false;
};

class GazePredictor {
 public:
  explicit GazePredictor(PredictorOptions options = {}) : options_(options) {}
  void push(const GazeSample& sample);  // invalid or out-of-order samples reset the window
  std::optional<Prediction> predict(std::int64_t display_t_ns) const;
  // Angular velocity magnitude of the current fit, deg/s (0 without a fit).
  double speed_deg_s() const;

 private:
  // Tangent velocity of the gaze direction at the newest sample (rad/s), from a LS fit.
  std::optional<glm::dvec3> velocity_axis_rad_s() const;
  PredictorOptions options_;
  std::deque<GazeSample> recent_;
};

}  // namespace gazelod::gaze
