// SPDX-License-Identifier: Apache-2.0
#include "budget/cost_model.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::budget {

double object_cost_s(const CostCoefficients& c, double triangles, double vertices, double pixels) {
  const double geometry = c.c1_s_per_tri * std::max(triangles, 0.0) + c.c2_s_per_vert * std::max(vertices, 0.0);
  const double fill = c.c3_s_per_px * std::max(pixels, 0.0);
  return std::max({geometry, fill, 0.0});
}

void add_object(const CostCoefficients& c, double triangles, double vertices, double pixels, FrameCostFeatures& frame) {
  triangles = std::max(triangles, 0.0);
  vertices = std::max(vertices, 0.0);
  pixels = std::max(pixels, 0.0);
  const double geometry = c.c1_s_per_tri * triangles + c.c2_s_per_vert * vertices;
  const double fill = c.c3_s_per_px * pixels;
  if (geometry >= fill) {
    frame.triangles_geometry_bound += triangles;
    frame.vertices_geometry_bound += vertices;
  } else {
    frame.pixels_fill_bound += pixels;
  }
  frame.predicted_s += std::max(geometry, fill);
}

CostModelRls::CostModelRls(const CostCoefficients& prior, double forgetting, double initial_variance)
    : coeff_(prior), lambda_(std::clamp(forgetting, 0.5, 1.0)) {
  const double v = std::isfinite(initial_variance) && initial_variance > 0.0 ? initial_variance : 1e6;
  for (int i = 0; i < 4; ++i) p_[i][i] = v;
  trace_cap_ = v;  // the per-direction variance cap
  // Work in units where each coefficient is O(1) relative to its prior (or a nominal scale).
  const double nominal[4] = {1e-3, 1e-8, 1e-8, 1e-9};
  const double given[4] = {prior.c0_s, prior.c1_s_per_tri, prior.c2_s_per_vert, prior.c3_s_per_px};
  for (int i = 0; i < 4; ++i) {
    scale_[i] = given[i] > 0.0 ? given[i] : nominal[i];
    theta_[i] = std::max(given[i], 0.0);
  }
}

FrameCostFeatures CostModelRls::begin_frame() const {
  FrameCostFeatures f;
  f.predicted_s = coeff_.c0_s;
  return f;
}

bool CostModelRls::update(const FrameCostFeatures& frame, double measured_s) {
  if (!std::isfinite(measured_s) || measured_s < 0.0) return false;
  const double raw[4] = {1.0, frame.triangles_geometry_bound, frame.vertices_geometry_bound, frame.pixels_fill_bound};
  for (double v : raw)
    if (!std::isfinite(v)) return false;
  double theta[4] = {theta_[0], theta_[1], theta_[2], theta_[3]};
  // Scaled regressors x_i = raw_i * scale_i and parameters theta_i / scale_i.
  double x[4], th[4];
  for (int i = 0; i < 4; ++i) {
    x[i] = raw[i] * scale_[i];
    th[i] = theta[i] / scale_[i];
  }
  double px[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) px[i] += p_[i][j] * x[j];
  double denom = lambda_;
  for (int i = 0; i < 4; ++i) denom += x[i] * px[i];
  if (!(denom > 0.0) || !std::isfinite(denom)) return false;
  double pred = 0.0;
  for (int i = 0; i < 4; ++i) pred += x[i] * th[i];
  const double err = measured_s - pred;
  double k[4];
  for (int i = 0; i < 4; ++i) k[i] = px[i] / denom;
  for (int i = 0; i < 4; ++i) th[i] += k[i] * err;
  // P <- (P - k (P x)') / lambda, kept symmetric.
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p_[i][j] = (p_[i][j] - k[i] * px[j]) / lambda_;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) p_[i][j] = p_[j][i] = 0.5 * (p_[i][j] + p_[j][i]);
  // Wind-up guard: forgetting inflates the variance of directions the data does not excite.
  // Cap each variance at its initial value by the congruence P <- D P D (D diagonal), which
  // keeps P positive definite and leaves the well-excited directions alone.
  double d[4];
  for (int i = 0; i < 4; ++i) d[i] = p_[i][i] > trace_cap_ ? std::sqrt(trace_cap_ / p_[i][i]) : 1.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p_[i][j] *= d[i] * d[j];
  for (int i = 0; i < 4; ++i) {
    theta_[i] = th[i] * scale_[i];
    theta[i] = i == 0 ? theta_[i] : std::max(theta_[i], 0.0);  // overhead: an intercept, may go < 0
  }
  coeff_ = {theta[0], theta[1], theta[2], theta[3]};
  return true;
}

void CostPredictionReport::add(double predicted_s, double measured_s) {
  if (!std::isfinite(predicted_s) || !std::isfinite(measured_s)) return;
  const double e = predicted_s - measured_s;
  const double n = static_cast<double>(++frames);
  mean_abs_error_s += (std::fabs(e) - mean_abs_error_s) / n;
  mean_signed_error_s += (e - mean_signed_error_s) / n;
  rms_error_s = std::sqrt(rms_error_s * rms_error_s + (e * e - rms_error_s * rms_error_s) / n);
  max_abs_error_s = std::max(max_abs_error_s, std::fabs(e));
  if (measured_s > 0.0) mean_rel_error += (std::fabs(e) / measured_s - mean_rel_error) / n;
}

}  // namespace gazelod::budget
