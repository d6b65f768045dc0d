// SPDX-License-Identifier: Apache-2.0
// The whole per-frame budget step the plugin runs (budget/frame_budget.hpp): benefits and costs
// for every level, Mason's incremental solve from the last frame, and the RLS update from the
// "measured" time (a synthetic renderer: fixed true coefficients 30 % slower than the prior plus
// 0.5 ms overhead, with 2 % noise). Objects drift in size by ~1 % a frame
// and a share of them (third argument, per mille) changes perceptual level each frame (gaze
// moves: detail rises and falls in the objects it passes). Thread CPU time (thread_cpu.hpp).
// Fourth argument: FrameBudgetOptions::max_moves (0: no limit); fifth: the optional wall-clock
// solve limit in us (0: off, the default, so every run makes the same choices).
#include "budget/frame_budget.hpp"
#include "thread_cpu.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace gazelod::budget::bench {
namespace {

const auto kDefaultMaxMoves = static_cast<std::int64_t>(FrameBudgetOptions{}.max_moves);

void BM_FrameBudget(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto m = static_cast<std::size_t>(state.range(1));
  const double change = 1e-3 * static_cast<double>(state.range(2));
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::lognormal_distribution<double> top_tris(std::log(20000.0), 1.0), px(std::log(3000.0), 1.2);
  std::vector<std::vector<lod::LodLevel>> chains(n);
  std::vector<BudgetObjectView> view(n), base(n);
  std::vector<std::uint8_t> perceptual(n), out(n);
  FrameBudgetOptions options;
  options.max_moves = state.range(3) > 0 ? static_cast<std::uint64_t>(state.range(3)) : SolveLimits::kNoMoveLimit;
  if (state.range(4) > 0) options.solve_time_limit = std::chrono::microseconds(state.range(4));
  double lo = 0, hi = 0;
  for (std::size_t k = 0; k < n; ++k) {
    double t = top_tris(rng);
    for (std::size_t l = 0; l < m; ++l, t *= 0.5) {
      lod::LodLevel level;
      level.triangles = static_cast<std::uint32_t>(std::max(t, 8.0));
      level.vertices = static_cast<std::uint32_t>(0.6 * level.triangles);
      chains[k].push_back(level);
    }
    auto ms = [&](const lod::LodLevel& l) { return 1e3 * object_cost_s(options.prior, l.triangles, l.vertices, 0.0); };
    hi += ms(chains[k].front());
    lo += ms(chains[k].back());
    base[k] = view[k] = {px(rng), 0.3 + 0.7 * u(rng)};
    perceptual[k] = static_cast<std::uint8_t>(u(rng) * 2.0);
  }
  FrameBudget budget(chains, lo + 0.5 * (hi - lo), options);
  std::normal_distribution<double> z(0.0, 0.01), noise(0.0, 0.02);
  std::vector<double> drift(n, 0.0);
  const CostCoefficients truth{0.5e-3, 1.3e-8, 6.5e-9, 0.0};
  double truncated = 0, moves = 0, infeasible = 0, wall_s = 0, measured_ms = -1.0, over = 0;
  std::vector<std::uint64_t> frame_moves;  // per frame, for the percentiles
  for (auto _ : state) {
    for (std::size_t k = 0; k < n; ++k) {
      drift[k] = 0.98 * drift[k] + z(rng);
      view[k].size_px = base[k].size_px * std::exp(drift[k]);
      if (u(rng) < change) perceptual[k] = static_cast<std::uint8_t>(std::min<std::size_t>(m - 1, perceptual[k] ^ 1u));
    }
    const double c0 = thread_cpu_s();
    const auto t0 = std::chrono::steady_clock::now();
    // Last frame's time arrives, then this frame is chosen. Ignoring observe's answer is right:
    // the first frame's -1 (no frame measured yet) is meant to be refused.
    (void)budget.observe(measured_ms);
    const std::string refused = budget.choose(perceptual, view, out);
    const auto t1 = std::chrono::steady_clock::now();
    if (!refused.empty()) {
      state.SkipWithError(refused.c_str());
      break;
    }
    infeasible += budget.infeasible();
    state.SetIterationTime(thread_cpu_s() - c0);
    wall_s += std::chrono::duration<double>(t1 - t0).count();
    truncated += budget.truncated();
    moves += static_cast<double>(budget.solver_moves());
    frame_moves.push_back(budget.solver_moves());
    double true_s = truth.c0_s;  // what this frame "costs" on the synthetic renderer
    for (std::size_t k = 0; k < n; ++k)
      true_s += object_cost_s(truth, chains[k][out[k]].triangles, chains[k][out[k]].vertices, 0.0);
    measured_ms = 1e3 * true_s * (1.0 + noise(rng));
    over += measured_ms > budget.budget_ms();
  }
  const double frames = std::max<double>(static_cast<double>(state.iterations()), 1.0);
  state.counters["wall_ms"] = 1e3 * wall_s / frames;
  state.counters["truncated_frames"] = truncated;
  state.counters["moves_per_frame"] = moves / frames;
  std::sort(frame_moves.begin(), frame_moves.end());
  auto quantile = [&](double q) {
    return frame_moves.empty()
               ? 0.0
               : static_cast<double>(
                     frame_moves[static_cast<std::size_t>(q * static_cast<double>(frame_moves.size() - 1))]);
  };
  state.counters["moves_p50"] = quantile(0.5);
  state.counters["moves_p99"] = quantile(0.99);
  state.counters["moves_max"] = quantile(1.0);
  state.counters["infeasible_frames"] = infeasible;
  state.counters["over_budget_frames"] = over;  // measured (noisy) time above the budget
  state.SetLabel("FrameBudget (mason-incremental)");
}

// Objects, levels, perceptual changes per mille, max moves (0: none), wall-clock limit us (0: off).
BENCHMARK(BM_FrameBudget)
    ->Args({1000, 4, 10, kDefaultMaxMoves, 0})  // the default options
    ->Args({10000, 4, 10, kDefaultMaxMoves, 0})
    ->Args({10000, 8, 10, kDefaultMaxMoves, 0})
    ->Args({10000, 4, 50, kDefaultMaxMoves, 0})
    ->Args({10000, 4, 10, 0, 0})  // no limit: every frame converges (the moves a frame needs)
    ->Args({10000, 8, 10, 0, 0})
    ->Args({10000, 4, 50, 0, 0})
    ->Args({10000, 4, 10, 0, 500})  // the former default: 0.5 ms wall clock (not reproducible)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gazelod::budget::bench
