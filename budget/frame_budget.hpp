// SPDX-License-Identifier: Apache-2.0
// Frame-budget LOD scheduling for `gazelod run --budget-ms X`: per frame, choose one
// level per object so that the predicted frame time stays under the budget, never finer than
// the perceptual choice (finer levels buy nothing visible). Prediction: Funkhouser & Sequin's
// cost, max(C1 triangles + C2 vertices, C3 pixels) + C0 per frame, with the coefficients fit
// online by recursive least squares from observe(measured frame time). Choice: Mason's (1999)
// incremental MCKP solver, started from the previous frame's answer. Plain data in and out.
//
// Benefit of drawing object k at level L (coarser than or equal to its perceptual level P):
//   size_px_k * importance_k * sqrt(triangles_L / triangles_P)   (capped at 1)
// The resolvable spatial frequency of a mesh scales with 1 / edge length ~ sqrt(triangles), so
// the root is the share of the perceptually needed detail a coarser level still carries. It is
// concave in cost, so Mason's convexity assumption (and his half-optimality bound) holds.
//
// Cluster meshes (docs/cluster-budget.md) are items of the same MCKP: mesh c's "levels" are the
// coarsening steps of its cut (budget/cluster_cut_cost.hpp: step k divides its errors by
// s_k = 2^(k/2); step 0 is the frame's cut as drawn), with the triangles the caller predicts
// per step, the same cost model and the same benefit, size_px * importance *
// sqrt(triangles_k / triangles_0), so objects and clusters trade on one scale.
#pragma once

#include "budget/cluster_cut_cost.hpp"
#include "budget/cost_model.hpp"
#include "budget/frame_budget_options.hpp"
#include "budget/knapsack_incremental.hpp"
#include "lod/lod_chain.hpp"
#include "budget/mckp.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::budget {

// Per cluster mesh, per frame: the benefit's size and importance (as BudgetObjectView) and the
// triangles of each step's cut (ClusterCutCost::predict_steps; non-increasing in the step).
struct BudgetClusterView {
  double size_px = 0.0;
  double importance = 1.0;
  std::array<double, kClusterSteps> triangles{};
};

class FrameBudget {
 public:
  // chains[k]: object k's levels, level 0 the finest (lod/lod_chain.hpp). Construction is the
  // registration: it throws std::invalid_argument naming the object when a chain is empty or has
  // more than 255 levels, when budget_ms is not a positive finite number, or with
  // validate_frame_budget_options' reason. What passes here cannot make choose() fail.
  // cluster_meshes: how many cluster meshes join the objects (kClusterSteps items each).
  FrameBudget(std::vector<std::vector<lod::LodLevel>> chains, double budget_ms, const FrameBudgetOptions& options = {},
              std::size_t cluster_meshes = 0);

  // One frame. perceptual_lod[k]: the finest level worth drawing (0 = full detail);
  // out_lod[k] receives the chosen level, never finer (smaller) than perceptual_lod[k].
  // The prediction stays under budget_ms * (1 - headroom). When even the coarsest levels are
  // predicted over that, out_lod is the coarsest level of every object (the cheapest frame
  // there is) and infeasible() says so: an outcome, not an error. Returns "" when out_lod was
  // written, else why the inputs were refused (a span's size is not the object count, or a
  // perceptual level is past the end of its chain, naming the object), writing nothing. Never
  // throws: this runs every frame (docs/error-policy.md).
  [[nodiscard]] std::string choose(std::span<const std::uint8_t> perceptual_lod, std::span<const BudgetObjectView> view,
                                   std::span<std::uint8_t> out_lod);
  // The same with the cluster meshes: out_step[c] receives mesh c's step (0 = its cut as drawn,
  // kClusterSteps - 1 the coarsest; with infeasible(), the coarsest). Refuses spans whose sizes
  // are not the object and mesh counts. Triangles that are negative or not finite count as 0, a
  // step with more triangles than step 0 as step 0's (the benefit is capped at 1).
  [[nodiscard]] std::string choose(std::span<const std::uint8_t> perceptual_lod, std::span<const BudgetObjectView> view,
                                   std::span<std::uint8_t> out_lod, std::span<const BudgetClusterView> clusters,
                                   std::span<std::uint8_t> out_step);
  // The triangles mesh c actually drew at its chosen step (the cut selected at that scale), for
  // the cost fit in observe(); without this call observe() takes the predicted ones. Sizes other
  // than the mesh count are ignored (returns false).
  [[nodiscard]] bool record_cluster_triangles(std::span<const double> drawn_triangles);
  // Of the last choose(): mesh c's predicted triangles at its chosen step.
  double cluster_predicted_triangles(std::size_t c) const { return cluster_pred_tris_[c]; }

  // Feeds the measured time of the frame last chosen (ms); updates the cost fit. Non-finite or
  // negative times are ignored (returns false), as is a call before any choose().
  [[nodiscard]] bool observe(double measured_frame_ms);

  double predicted_ms() const { return predicted_ms_; }                // of the last choose()
  bool infeasible() const { return infeasible_; }                      // of the last choose()
  bool truncated() const { return truncated_; }                        // last solve stopped at max_moves (or time)
  std::uint64_t solver_moves() const { return solution_.iterations; }  // last solve's moves
  double budget_ms() const { return budget_ms_; }
  void set_budget_ms(double budget_ms);  // throws std::invalid_argument unless positive finite
  const budget::CostCoefficients& coefficients() const { return rls_.coefficients(); }
  std::size_t object_count() const { return chains_.size(); }
  std::size_t cluster_mesh_count() const { return cluster_pred_tris_.size(); }

 private:
  // Cost in ms under the current fit (F&S max form), from the flattened level tables.
  struct MsCoefficients {
    double per_tri, per_vert, per_px;
  };
  MsCoefficients ms_coefficients() const;
  static double fs_cost_ms(const MsCoefficients& c, double tris, double verts, double pixels) {
    const double geometry = c.per_tri * tris + c.per_vert * verts;
    const double fill = c.per_px * pixels;
    return geometry > fill ? (geometry > 0.0 ? geometry : 0.0) : (fill > 0.0 ? fill : 0.0);
  }
  double level_cost_ms(const MsCoefficients& c, std::size_t index, double pixels) const {
    return fs_cost_ms(c, level_tris_[index], level_verts_[index], pixels);
  }
  void write_cluster_items(const MsCoefficients& c, std::span<const BudgetClusterView> clusters);

  std::vector<std::vector<lod::LodLevel>> chains_;
  // Per level, objects one after another (level_first_[k] + level): the hot loop's inputs.
  std::vector<std::uint32_t> level_first_;
  std::vector<double> level_tris_, level_verts_;
  std::vector<double> level_sqrt_;  // sqrt(max(triangles, 1))
  double budget_ms_;
  FrameBudgetOptions options_;
  budget::CostModelRls rls_;
  budget::MckpInstance frame_;  // subset k: object k's levels, coarsest first
  budget::IncrementalScheduler scheduler_;
  budget::MckpSolution solution_;
  std::vector<std::uint32_t> prev_choice_;  // within-subset index (coarsest first)
  std::vector<std::uint8_t> last_lod_;      // the levels last chosen
  std::vector<double> last_pixels_;
  // Per cluster mesh: the chosen step's predicted triangles, the triangles observe() fits
  // (the drawn ones where recorded), its pixels.
  std::vector<double> cluster_pred_tris_, cluster_fit_tris_, cluster_pixels_;
  bool have_frame_ = false;
  double predicted_ms_ = 0.0;
  bool infeasible_ = false;
  bool truncated_ = false;
};

}  // namespace gazelod::budget
