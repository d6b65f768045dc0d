// SPDX-License-Identifier: Apache-2.0
// The frame budget's options and its per-object inputs, plain data (the plugin's
// PluginConfig carries FrameBudgetOptions; budget/frame_budget.hpp uses them).
#pragma once

#include "budget/cost_model.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace gazelod::budget {

// Per object, per frame: what the benefit is made of.
struct BudgetObjectView {
  double size_px = 0.0;     // projected area, pixels (also the fill-rate term of the cost)
  double importance = 1.0;  // semantic importance, clamped to [0, 1]
};

struct FrameBudgetOptions {
  // Prior cost coefficients (seconds per frame / triangle / vertex / pixel); the RLS fit
  // starts here. Defaults: a mid-range GPU, ~100 M triangles/s; C3 = 0 leaves the fill-rate
  // term out (give it a prior > 0 to model fill-bound objects: the fit only moves a term the
  // current coefficients make binding).
  budget::CostCoefficients prior{0.0, 1e-8, 5e-9, 0.0};
  double forgetting = 0.98;  // RLS forgetting factor: ~50 frames of memory
  // Most solver moves (increments + decrements) one choose() may start (Mason sec. 9.3.5
  // truncation, by moves so that the choice depends only on the inputs); truncated() reports a
  // frame that stopped there, which is still a complete level of detail under the budget, and
  // the next frame continues from it. SolveLimits::kNoMoveLimit: always run to convergence.
  // Why 4096: on bench_budget's BM_FrameBudget scenes (10 000 objects, 4 or 8 levels, 1-5 % of
  // objects changing perceptual level per frame, RLS fit moving every cost) a frame needs a
  // median of ~100-600 moves to converge, p99 ~2 300-3 500, p99.9 ~3 500-4 800; at 1 000
  // objects, p99 ~25. With 4096, about 0.1-0.7 % of frames truncate once warm (the rest are
  // the first frames climbing from the coarsest levels), and the mean cost of choose() stays
  // ~0.5-0.6 ms CPU, as with the former 500 us wall-clock limit (which truncated ~16 % of the
  // frames, at whatever point the clock said). A move costs ~0.4-0.55 us there (dev VM), so
  // the limit bounds a frame's improving moves to ~2 ms however far the scene jumps (the
  // decrements that bring an over-budget start back under the budget are never cut short).
  std::uint64_t max_moves = 4096;
  // Optional outer wall-clock limit on one choose()'s solve, off by default. Setting it makes
  // the chosen levels depend on timing (machine speed, load), so runs are no longer
  // reproducible; max_moves still applies.
  std::optional<std::chrono::nanoseconds> solve_time_limit;
  // Share of the budget kept free (in [0, 0.9]): with an unbiased cost fit about half the frames
  // land above the prediction, so a margin of ~2 standard deviations of the relative prediction
  // error keeps most measured frames under the budget. 0: plan right up to the budget.
  double headroom = 0.0;
};

// "" when the options are usable, else the first bad one by name with its value: prior
// coefficients finite (C1..C3 >= 0), forgetting in [0.5, 1] (CostModelRls's range), headroom
// in [0, 0.9], a set solve_time_limit > 0. FrameBudget's constructor refuses what this refuses.
[[nodiscard]] std::string validate_frame_budget_options(const FrameBudgetOptions& options);

}  // namespace gazelod::budget
