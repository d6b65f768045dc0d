// SPDX-License-Identifier: Apache-2.0
// A cluster mesh's predicted triangles per coarsening step (see cluster_cut_cost.hpp).
#include "budget/cluster_cut_cost.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace gazelod::budget {
namespace {

// Rungs at most: 128 octaves of error, more than float's normal range of ratios a bake makes.
constexpr std::size_t kMaxRungs = 512;

double clean(double v) {
  return std::isfinite(v) && v > 0.0 ? v : 0.0;
}

}  // namespace

ClusterCutCost::ClusterCutCost(const lod::ClusterHierarchy& h) {
  double finest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (std::span<const float> errors :
       {std::span<const float>(h.self_error_m), std::span<const float>(h.parent_error_m)})
    for (float e : errors)
      if (e > 0.0f && std::isfinite(e)) finest = std::min(finest, double(e)), largest = std::max(largest, double(e));
  // Rung 0 lies below the finest positive error (the source cut), the last one above the largest
  // finite error (the top of the hierarchy).
  const double r = std::exp2(1.0 / kRungsPerOctave);
  std::size_t rungs = 1;
  if (std::isfinite(finest)) {
    tau0_m_ = finest / r;
    const double span = std::log2(largest * r / tau0_m_) * kRungsPerOctave;
    rungs = std::min<std::size_t>(kMaxRungs, static_cast<std::size_t>(std::ceil(span)) + 1);
  } else {
    tau0_m_ = 1.0;  // no positive error: every threshold gives the source cut
  }
  std::vector<double> tau(rungs);
  for (std::size_t j = 0; j < rungs; ++j) tau[j] = threshold_m(j);
  // A cluster is in the uniform cut at tau when self < tau <= parent: rungs [first tau > self,
  // first tau > parent). A difference array over the rungs.
  std::vector<double> delta(rungs + 1, 0.0);
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double t = static_cast<double>(h.index_count[i] / 3);
    const auto lo =
        static_cast<std::size_t>(std::upper_bound(tau.begin(), tau.end(), double(h.self_error_m[i])) - tau.begin());
    const auto hi =
        static_cast<std::size_t>(std::upper_bound(tau.begin(), tau.end(), double(h.parent_error_m[i])) - tau.begin());
    // parent +inf (the hierarchy's top): drawn from lo to the last rung.
    const std::size_t end = std::isinf(h.parent_error_m[i]) ? rungs : hi;
    if (lo >= end) continue;
    delta[lo] += t;
    delta[end] -= t;
  }
  triangles_.resize(rungs);
  log_triangles_.resize(rungs);
  double running = 0.0;
  for (std::size_t j = 0; j < rungs; ++j) {
    running += delta[j];
    // A coarser threshold never draws more (a group's simplification does not add triangles);
    // the running minimum keeps the curve monotone for the lookups should a hierarchy break that.
    triangles_[j] = j == 0 ? std::max(running, 0.0) : std::clamp(running, 0.0, triangles_[j - 1]);
    log_triangles_[j] = std::log(std::max(triangles_[j], 1.0));
  }
}

double ClusterCutCost::triangles_at_rung(double x) const {
  const double last = static_cast<double>(triangles_.size() - 1);
  if (!(x > 0.0)) return triangles_.front();  // NaN too: the finest cut
  if (x >= last) return triangles_.back();
  const auto j = static_cast<std::size_t>(x);
  const double u = x - static_cast<double>(j);
  return std::exp(log_triangles_[j] + u * (log_triangles_[j + 1] - log_triangles_[j]));
}

double ClusterCutCost::rung_of(double triangles) const {
  const double lt = std::log(std::max(clean(triangles), 1.0));
  if (!(lt < log_triangles_.front())) return 0.0;
  if (!(lt > log_triangles_.back())) {
    // The first rung at or below the triangles (the finest threshold that reaches them).
    const auto at = std::find_if(log_triangles_.begin(), log_triangles_.end(), [&](double v) { return v <= lt; });
    return static_cast<double>(at - log_triangles_.begin());
  }
  // log_triangles_[j] > lt > log_triangles_[j + 1]: the first rung below lt, by bisection.
  std::size_t lo = 0, hi = log_triangles_.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (log_triangles_[mid] > lt ? lo : hi) = mid;
  }
  const double drop = log_triangles_[lo] - log_triangles_[hi];
  return static_cast<double>(lo) + (drop > 0.0 ? (log_triangles_[lo] - lt) / drop : 0.0);
}

namespace {

// Rungs from step 0 to step k: s_k = 2^(k / 2) is k / 2 octaves.
double step_rungs(std::size_t k) {
  return 0.5 * ClusterCutCost::kRungsPerOctave * static_cast<double>(k);
}

}  // namespace

void ClusterCutCost::predict_steps(double perceptual_triangles, double drawn_triangles,
                                   std::span<double, kClusterSteps> out, double elasticity) const {
  const double p = clean(perceptual_triangles);
  const double x = rung_of(p);
  const double at_p = triangles_at_rung(x);  // P, or the ladder's end where P lies beyond it
  const double g = std::isfinite(elasticity) ? std::clamp(elasticity, 0.0, 2.0) : 1.0;
  out[0] = clean(drawn_triangles);
  for (std::size_t k = 1; k < kClusterSteps; ++k) {
    const double ratio = at_p > 0.0 ? triangles_at_rung(x + step_rungs(k)) / at_p : 1.0;
    out[k] = std::min(out[k - 1], p * std::pow(std::min(ratio, 1.0), g));
  }
}

double ClusterCutCost::observed_elasticity(double perceptual_triangles, std::size_t step,
                                           double drawn_triangles) const {
  const double p = clean(perceptual_triangles), drawn = clean(drawn_triangles);
  if (step == 0 || step >= kClusterSteps || !(p >= 1.0) || !(drawn >= 1.0)) return std::nan("");
  const double x = rung_of(p);
  const double uniform = std::log(triangles_at_rung(x + step_rungs(step)) / triangles_at_rung(x));
  if (!(uniform < -0.05)) return std::nan("");  // a flat stretch of the curve: nothing to learn
  return std::log(std::min(drawn / p, 1.0)) / uniform;
}

}  // namespace gazelod::budget
