// SPDX-License-Identifier: Apache-2.0
// Render-time cost of an object tuple after Funkhouser & Sequin (1993 sec. 4):
// cost = max(C1 triangles + C2 vertices, C3 pixels), the per-primitive and per-pixel pipeline
// stages whose slower one bounds the time. C1..C3 (plus a per-frame overhead C0) are fit online
// from measured frame times by recursive least squares with exponential forgetting.
#pragma once

#include <array>
#include <cstddef>

namespace gazelod::budget {

struct CostCoefficients {
  double c0_s = 0.0;           // per-frame overhead (a fitted intercept: not clamped)
  double c1_s_per_tri = 0.0;   // C1
  double c2_s_per_vert = 0.0;  // C2
  double c3_s_per_px = 0.0;    // C3
};

// Predicted render time of one object tuple, in seconds (>= 0; negative inputs count as 0).
double object_cost_s(const CostCoefficients& c, double triangles, double vertices, double pixels);

// One frame's regressors: the objects' counts summed on the stage that bounds each of them
// under the current coefficients (the max() linearised around the current fit).
struct FrameCostFeatures {
  double triangles_geometry_bound = 0.0;
  double vertices_geometry_bound = 0.0;
  double pixels_fill_bound = 0.0;
  double predicted_s = 0.0;  // sum of object_cost_s + c0, with the coefficients used
};

// Adds one drawn object to `frame` (call for each object of the frame).
void add_object(const CostCoefficients& c, double triangles, double vertices, double pixels, FrameCostFeatures& frame);

// Recursive least squares with forgetting factor lambda in (0, 1]: theta <- theta + k e,
// k = P x / (lambda + x'P x), P <- (P - k x'P) / lambda. The coefficients used for prediction
// are the estimate with C1..C3 clamped to >= 0 (a negative time per triangle is not physical;
// C0 is an intercept and stays free, else the clamp biases every prediction); the estimate
// itself stays unconstrained. Each coefficient's variance is capped at its initial value so that
// forgetting without excitation cannot blow it up.
class CostModelRls {
 public:
  explicit CostModelRls(const CostCoefficients& prior, double forgetting = 0.98, double initial_variance = 1e4);

  const CostCoefficients& coefficients() const { return coeff_; }
  // Frame overhead included. Starts a frame's features; add objects with add_object().
  FrameCostFeatures begin_frame() const;
  // Feeds one measured frame; ignores non-finite or negative measurements (returns false).
  [[nodiscard]] bool update(const FrameCostFeatures& frame, double measured_s);

 private:
  CostCoefficients coeff_;         // clamped to >= 0, what predictions use
  std::array<double, 4> theta_{};  // the unconstrained estimate (clamping it would bias RLS)
  double lambda_;
  double trace_cap_;                          // largest variance of any one coefficient (scaled units)
  std::array<std::array<double, 4>, 4> p_{};  // covariance, in scaled units
  std::array<double, 4> scale_{};             // regressor scaling (keeps P well conditioned)
};

// Predicted against measured frame time over a run (the report asked of the cost model).
struct CostPredictionReport {
  std::size_t frames = 0;
  double mean_abs_error_s = 0.0;
  double rms_error_s = 0.0;
  double max_abs_error_s = 0.0;
  double mean_rel_error = 0.0;       // |pred - meas| / meas over frames with meas > 0
  double mean_signed_error_s = 0.0;  // bias: > 0 means the model over-predicts
  void add(double predicted_s, double measured_s);
};

}  // namespace gazelod::budget
