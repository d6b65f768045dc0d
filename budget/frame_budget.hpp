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
#pragma once

#include "budget/cost_model.hpp"
#include "budget/frame_budget_options.hpp"
#include "budget/knapsack_incremental.hpp"
#include "lod/lod_chain.hpp"
#include "budget/mckp.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::budget {

class FrameBudget {
 public:
  // chains[k]: object k's levels, level 0 the finest (lod/lod_chain.hpp). Construction is the
  // registration: it throws std::invalid_argument naming the object when a chain is empty or has
  // more than 255 levels, when budget_ms is not a positive finite number, or with
  // validate_frame_budget_options' reason. What passes here cannot make choose() fail.
  FrameBudget(std::vector<std::vector<lod::LodLevel>> chains, double budget_ms, const FrameBudgetOptions& options = {});

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

 private:
  // Cost in ms under the current fit (F&S max form), from the flattened level tables.
  struct MsCoefficients {
    double per_tri, per_vert, per_px;
  };
  MsCoefficients ms_coefficients() const;
  double level_cost_ms(const MsCoefficients& c, std::size_t index, double pixels) const {
    const double geometry = c.per_tri * level_tris_[index] + c.per_vert * level_verts_[index];
    const double fill = c.per_px * pixels;
    return geometry > fill ? (geometry > 0.0 ? geometry : 0.0) : (fill > 0.0 ? fill : 0.0);
  }

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
  bool have_frame_ = false;
  double predicted_ms_ = 0.0;
  bool infeasible_ = false;
  bool truncated_ = false;
};

}  // namespace gazelod::budget
