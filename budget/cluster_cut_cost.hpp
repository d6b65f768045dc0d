// SPDX-License-Identifier: Apache-2.0
// A cluster mesh's coarsening steps for the frame budget (budget/frame_budget.hpp), and their
// predicted triangles from the mesh's own hierarchy.
//
// Step k of a mesh draws the cut the perceptual rule gives with every error of the mesh divided
// by s_k = 2^(k / 2) (lod::ClusterSet::mesh_detail_scale): the largest invisible error at every
// point grows by s_k. s_0 = 1 is the perceptual cut itself; s_8 = 16.
//
// Predicted triangles per step, without selecting each step's cut: at registration, the
// triangles of the uniform cut (a cluster drawn where its self error < tau <= its parent
// error) for a geometric ladder of thresholds tau_j = tau_0 r^j, r = 2^(1/4), from the finest
// positive error to past the largest finite one: T(tau), a non-increasing staircase made of the
// hierarchy's real cluster sizes. Each frame, the perceptual cut (which is not uniform: fine at
// the gaze, coarse away from it) is summarised by the effective threshold tau_P where the
// uniform cut has its triangles, T(tau_P) = P (log-linear between rungs); step k then predicts
// T(tau_P s_k), i.e. 2k rungs further (s_k = r^(2k)). The mesh's own curve, not 1 / s^2: a
// hierarchy whose groups halve their triangles per doubling of the error gives 1 / s, a flat
// terrain nearer 1 / s^2, and the curve flattens where the hierarchy runs out of levels.
//
// The uniform curve alone over-states the drop: a perceptual cut is partly pinned (at the
// source clusters near the gaze, where the acuity asks for more than the mesh has, and at the
// top far away), and a pinned part does not coarsen with s: on a baked terrain walk the
// actual log drop was about a fifth of the uniform one (g ~ 0.18; docs/cluster-budget.md). So
// the prediction is P (T(tau_P s_k) / P)^g with a per-mesh elasticity g, learnt online from the
// cut the budget draws at the chosen step (ClusterStepElasticity: the observed log ratio over
// the uniform one, smoothed), starting at 1 (the uniform cut). tests/budget/cluster_scale_test.cpp
// and docs/cluster-budget.md measure the error against the triangles actually drawn.
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace gazelod::budget {

inline constexpr std::size_t kClusterSteps = 9;  // k = 0..8
// s_k = 2^(k / 2): a geometric ladder, each step about 1.41 x the error of the one before.
inline constexpr std::array<double, kClusterSteps> kClusterStepScale = {
    1.0, 1.4142135623730951, 2.0, 2.8284271247461903, 4.0, 5.656854249492381, 8.0, 11.313708498984761, 16.0};
// Vertices per triangle of a cut, for the cost model's vertex term: a hierarchy carries no
// vertex counts, and a closed or grid-like mesh has about half as many vertices as triangles.
inline constexpr double kClusterVerticesPerTriangle = 0.5;

// A mesh's elasticity g (see above), smoothed over the frames that show one.
struct ClusterStepElasticity {
  static constexpr double kGain = 0.25;  // about 4 frames of memory: cuts change with the gaze
  double value = 1.0;                    // the uniform cut until a frame says otherwise
  void update(double observed) {
    if (std::isfinite(observed)) value = std::clamp(value + kGain * (observed - value), 0.0, 2.0);
  }
};

class ClusterCutCost {
 public:
  // Registration: linear in the clusters (plus a sort of the ladder lookups). A hierarchy with
  // no positive finite error (only source clusters) has one rung: every step predicts the same.
  explicit ClusterCutCost(const lod::ClusterHierarchy& hierarchy);

  // Rungs per doubling of the threshold, and so per 2 steps.
  static constexpr double kRungsPerOctave = 4.0;

  // Triangles of the uniform cut at rung position x (fractional; log-linear between rungs,
  // clamped to the ladder).
  double triangles_at_rung(double x) const;
  // The rung position where the uniform cut has `triangles` (clamped to the ladder's ends).
  double rung_of(double triangles) const;
  // Per step: out[0] = drawn_triangles (step 0 draws the frame's cut as it is, switch policy
  // included); out[k] = min(out[k - 1], T(tau_P s_k)) with tau_P from perceptual_triangles.
  // Non-increasing in k. No allocation; negative or non-finite inputs count as 0.
  // elasticity: g above (1: the uniform cut's drop).
  void predict_steps(double perceptual_triangles, double drawn_triangles, std::span<double, kClusterSteps> out,
                     double elasticity = 1.0) const;
  // The elasticity one frame shows: log(drawn / P) / log(T(tau_P s_step) / P) for the cut drawn
  // at step > 0; NaN where it says nothing (step 0, a flat curve there, no triangles).
  double observed_elasticity(double perceptual_triangles, std::size_t step, double drawn_triangles) const;

  std::size_t rungs() const { return triangles_.size(); }
  double threshold_m(std::size_t rung) const {
    return tau0_m_ * std::exp2(static_cast<double>(rung) / kRungsPerOctave);
  }
  double finest_triangles() const { return triangles_.front(); }
  double coarsest_triangles() const { return triangles_.back(); }

 private:
  double tau0_m_ = 0.0;
  std::vector<double> triangles_;      // per rung, non-increasing
  std::vector<double> log_triangles_;  // log(max(triangles, 1))
};

}  // namespace gazelod::budget
