// SPDX-License-Identifier: Apache-2.0
// Determinism (issue: budget answers depend only on their inputs): Mason's incremental solver and
// FrameBudget give bit-identical results on repeated runs of the same frames, however many, with
// or without truncation; truncation is by a move limit (SolveLimits::max_moves), is reported,
// and still yields a complete, affordable level of detail.
#include "budget/frame_budget.hpp"
#include "budget/knapsack.hpp"
#include "budget/knapsack_incremental.hpp"
#include "mckp_test_util.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace gazelod::budget {
namespace {

std::uint64_t bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

// Everything a step reports, doubles by their bits.
void expect_identical(const MckpSolution& a, const MckpSolution& b, int frame) {
  EXPECT_EQ(a.choice, b.choice) << "frame " << frame;
  EXPECT_EQ(a.group_choice, b.group_choice) << "frame " << frame;
  EXPECT_EQ(bits(a.profit), bits(b.profit)) << "frame " << frame;
  EXPECT_EQ(bits(a.cost), bits(b.cost)) << "frame " << frame;
  EXPECT_EQ(bits(a.error_bound), bits(b.error_bound)) << "frame " << frame;
  EXPECT_EQ(a.feasible, b.feasible) << "frame " << frame;
  EXPECT_EQ(a.truncated, b.truncated) << "frame " << frame;
  EXPECT_EQ(a.iterations, b.iterations) << "frame " << frame;
}

// A flat frame-budget-like scene: `objects` concave chains of 5 levels, in cost order.
MckpInstance chains_scene(std::mt19937& rng, int objects) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MckpInstance inst;
  for (int k = 0; k < objects; ++k) {
    std::vector<MckpItem> items;
    double w = 1 + u(rng), p = 1, slope = 1 + 3 * u(rng);
    for (int j = 0; j < 5; ++j) {
      items.push_back({p, w});
      const double dw = 0.5 + 2 * u(rng);
      w += dw;
      p += slope * dw;
      slope *= 0.3 + 0.6 * u(rng);
    }
    inst.add_subset(items);
  }
  inst.capacity = lowest_cost(inst) * 2.5;
  return inst;
}

// The frames of one run: profits drift per object, the capacity changes now and then.
std::vector<MckpInstance> drifting_frames(int objects, int frames, std::uint32_t seed) {
  std::mt19937 rng(seed);
  MckpInstance inst = chains_scene(rng, objects);
  const std::vector<MckpItem> base = inst.items;
  std::normal_distribution<double> z(0.0, 0.03);
  std::vector<double> scale(inst.subset_count(), 1.0);
  std::vector<MckpInstance> out;
  for (int f = 0; f < frames; ++f) {
    for (std::size_t k = 0; k < inst.subset_count(); ++k) {
      scale[k] *= std::exp(z(rng));
      for (std::uint32_t j = inst.subset_offsets[k]; j < inst.subset_offsets[k + 1]; ++j)
        inst.items[j].profit = base[j].profit * scale[k];
    }
    if (f % 97 == 96) inst.capacity *= f % 2 ? 1.15 : 0.9;
    out.push_back(inst);
  }
  return out;
}

// One run: a fresh (or reset) scheduler, each frame started from the previous answer.
std::vector<MckpSolution> run_frames(IncrementalScheduler& sched, const std::vector<MckpInstance>& frames,
                                     const SolveLimits& limits) {
  sched.reset(frames.front());
  std::vector<MckpSolution> answers;
  MckpSolution prev, cur;
  for (const MckpInstance& frame : frames) {
    sched.step(frame, prev.choice, prev.group_choice, limits, cur);
    answers.push_back(cur);
    std::swap(prev, cur);
  }
  return answers;
}

TEST(BudgetDeterminism, IncrementalIsBitIdenticalAcrossRunsOfManyFrames) {
  const std::vector<MckpInstance> frames = drifting_frames(2000, 400, 31);
  for (const std::uint64_t max_moves : {SolveLimits::kNoMoveLimit, std::uint64_t{40}}) {
    SolveLimits limits;
    limits.max_moves = max_moves;
    IncrementalScheduler a, b;
    const std::vector<MckpSolution> first = run_frames(a, frames, limits);
    const std::vector<MckpSolution> second = run_frames(b, frames, limits);
    // The same scheduler object again after reset(): no state survives from the first run.
    const std::vector<MckpSolution> third = run_frames(a, frames, limits);
    int truncated = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
      expect_identical(first[f], second[f], static_cast<int>(f));
      expect_identical(first[f], third[f], static_cast<int>(f));
      EXPECT_TRUE(first[f].feasible) << f;
      truncated += first[f].truncated;
    }
    if (max_moves == SolveLimits::kNoMoveLimit)
      EXPECT_EQ(truncated, 0);
    else
      EXPECT_GT(truncated, 10);  // the limit really binds in the limited run
  }
}

TEST(BudgetDeterminism, HierarchicalIncrementalIsBitIdenticalAcrossRuns) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 100; ++trial) {
    const MckpInstance inst = test::random_hierarchical(rng);
    for (const std::uint64_t max_moves : {SolveLimits::kNoMoveLimit, std::uint64_t{2}}) {
      const SolveLimits limits{.max_moves = max_moves};
      const MckpSolution a = solve(SolverKind::mason_incremental, inst, limits);
      const MckpSolution b = solve(SolverKind::mason_incremental, inst, limits);
      expect_identical(a, b, trial);
    }
  }
}

// A scene far from converged at the lowest level: 2000 objects, room for three times the
// lowest cost (the greedy answer needs thousands of moves).
MckpInstance big_scene() {
  std::mt19937 rng(3);
  MckpInstance inst;
  for (int k = 0; k < 2000; ++k) {
    std::vector<MckpItem> items;
    double w = 1, p = 1, slope = 2 + std::uniform_real_distribution<double>(0, 1)(rng);
    for (int j = 0; j < 6; ++j) {
      items.push_back({p, w});
      w += 1 + j;
      p += slope * (1 + j);
      slope *= 0.6;
    }
    inst.add_subset(items);
  }
  inst.capacity = lowest_cost(inst) * 3;
  return inst;
}

void expect_complete_and_affordable(const MckpInstance& inst, const MckpSolution& s) {
  EXPECT_TRUE(s.feasible);
  EXPECT_LE(s.cost, inst.capacity);
  ASSERT_EQ(s.choice.size(), inst.subset_count());
  for (std::uint32_t c : s.choice) EXPECT_NE(c, kNoItem);
  MckpSolution check = s;  // the reported sums are the choice's
  evaluate(inst, check);
  EXPECT_TRUE(check.feasible);
  EXPECT_NEAR(check.cost, s.cost, 1e-9 * std::max(1.0, s.cost));
  EXPECT_NEAR(check.profit, s.profit, 1e-9 * std::max(1.0, s.profit));
}

TEST(BudgetDeterminism, MoveLimitTruncationIsReportedFeasibleAndComplete) {
  const MckpInstance inst = big_scene();
  IncrementalScheduler sched;
  sched.reset(inst);
  MckpSolution full, out;
  sched.step(inst, {}, {}, SolveLimits{}, full);
  ASSERT_FALSE(full.truncated);
  ASSERT_GT(full.iterations, 1000u);
  for (const std::uint64_t limit :
       {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{100}, std::uint64_t{1000}, full.iterations / 2}) {
    sched.reset(inst);
    sched.step(inst, {}, {}, SolveLimits{.max_moves = limit}, out);
    EXPECT_TRUE(out.truncated) << limit;
    // No increment starts at the limit; the decrements that make the frame fit may follow.
    EXPECT_GE(out.iterations, limit);
    EXPECT_LE(out.iterations, limit + 16) << limit;
    EXPECT_LT(out.profit, full.profit) << limit;
    expect_complete_and_affordable(inst, out);
  }
  // Limit 0 from the lowest level: nothing is incremented, the lowest level is the answer.
  sched.reset(inst);
  sched.step(inst, {}, {}, SolveLimits{.max_moves = 0}, out);
  EXPECT_EQ(out.iterations, 0u);
  EXPECT_EQ(out.choice, std::vector<std::uint32_t>(inst.subset_count(), 0u));
  // A start over the capacity (the finest level everywhere): the frame is made to fit even
  // with no moves left for improvement.
  const std::vector<std::uint32_t> finest(inst.subset_count(), 5u);
  sched.reset(inst);
  sched.step(inst, finest, {}, SolveLimits{.max_moves = 0}, out);
  EXPECT_TRUE(out.truncated);
  EXPECT_GT(out.iterations, 0u);
  expect_complete_and_affordable(inst, out);
  // A limit at or above what the solve needs changes nothing.
  for (const std::uint64_t limit : {full.iterations, full.iterations + 1}) {
    sched.reset(inst);
    sched.step(inst, {}, {}, SolveLimits{.max_moves = limit}, out);
    EXPECT_FALSE(out.truncated);
    expect_identical(out, full, 0);
  }
  // Frame after frame under a limit, the answer climbs to the converged one.
  sched.reset(inst);
  MckpSolution prev;
  int frames = 0;
  do {
    sched.step(inst, prev.choice, {}, SolveLimits{.max_moves = 200}, out);
    expect_complete_and_affordable(inst, out);
    std::swap(prev, out);
  } while (prev.truncated && ++frames < 1000);
  EXPECT_FALSE(prev.truncated);
  EXPECT_NEAR(prev.profit, solve_mason_greedy(inst, false).profit, 1e-9 * prev.profit);
}

TEST(BudgetDeterminism, MoveLimitOnHierarchiesGivesValidLevelsOfDetail) {
  std::mt19937 rng(23);
  int truncated = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const MckpInstance inst = test::random_hierarchical(rng);
    IncrementalScheduler sched;
    sched.reset(inst);
    MckpSolution out;
    sched.step(inst, {}, {}, SolveLimits{.max_moves = 1}, out);
    EXPECT_TRUE(is_valid_lod(sched.tree(), sched.selected())) << trial;
    if (out.feasible) {
      EXPECT_LE(out.cost, inst.capacity) << trial;
    }
    truncated += out.truncated;
  }
  EXPECT_GT(truncated, 20);
}

TEST(BudgetDeterminism, OneShotSolversTakeTheMoveLimit) {
  const MckpInstance inst = big_scene();
  for (SolverKind kind : {SolverKind::mason_incremental, SolverKind::funkhouser_incremental}) {
    const MckpSolution full = solve(kind, inst);
    EXPECT_FALSE(full.truncated) << solver_name(kind);
    const MckpSolution a = solve(kind, inst, SolveLimits{.max_moves = 300});
    const MckpSolution b = solve(kind, inst, SolveLimits{.max_moves = 300});
    EXPECT_TRUE(a.truncated) << solver_name(kind);
    expect_identical(a, b, 0);
    expect_complete_and_affordable(inst, a);
  }
  EXPECT_TRUE(is_incremental(SolverKind::mason_incremental));
  EXPECT_FALSE(is_incremental(SolverKind::mason_greedy));
}

// --- FrameBudget -------------------------------------------------------------------------

using Chains = std::vector<std::vector<lod::LodLevel>>;

Chains random_chains(std::mt19937& rng, std::size_t objects, std::size_t levels) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Chains chains(objects);
  for (auto& chain : chains) {
    double tris = 2000.0 + 60000.0 * u(rng);
    for (std::size_t l = 0; l < levels; ++l, tris *= 0.5) {
      lod::LodLevel level;
      level.triangles = static_cast<std::uint32_t>(std::max(tris, 4.0));
      level.vertices = static_cast<std::uint32_t>(level.triangles * (0.5 + 0.5 * u(rng)));
      chain.push_back(level);
    }
  }
  return chains;
}

struct FrameRecord {
  std::vector<std::uint8_t> lods;
  std::uint64_t predicted_bits, c0_bits, c1_bits;
  bool feasible, truncated;
  std::uint64_t moves;
};

// A closed loop like the plugin's: perceptual levels jump and sizes drift, and the "measured"
// time (a renderer 30 % slower than the prior, with noise from a seeded generator) is fed back.
std::vector<FrameRecord> run_frame_budget(const FrameBudgetOptions& options, int frames) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.02);
  const std::size_t n = 400, m = 5;
  const Chains chains = random_chains(rng, n, m);
  double lo = 0, hi = 0;
  for (const auto& c : chains) {
    lo += 1e3 * object_cost_s(options.prior, c.back().triangles, c.back().vertices, 0.0);
    hi += 1e3 * object_cost_s(options.prior, c.front().triangles, c.front().vertices, 0.0);
  }
  FrameBudget fb(chains, lo + 0.4 * (hi - lo), options);
  std::vector<std::uint8_t> perceptual(n), out(n);
  std::vector<BudgetObjectView> view(n);
  for (auto& v : view) v = {100.0 + 1e5 * u(rng) * u(rng), 0.2 + 0.8 * u(rng)};
  const CostCoefficients truth{0.5e-3, 1.3e-8, 6.5e-9, 0.0};
  std::vector<FrameRecord> records;
  for (int f = 0; f < frames; ++f) {
    for (std::size_t k = 0; k < n; ++k) {
      if (f == 0 || u(rng) < 0.03) perceptual[k] = static_cast<std::uint8_t>(u(rng) * 3);
      view[k].size_px *= std::exp(0.02 * (u(rng) - 0.5));
    }
    if (f % 200 == 199) fb.set_budget_ms(lo + (0.2 + 0.6 * u(rng)) * (hi - lo));
    EXPECT_EQ(fb.choose(perceptual, view, out), "") << f;
    const bool feasible = !fb.infeasible();
    for (std::size_t k = 0; k < n; ++k) EXPECT_GE(out[k], perceptual[k]);
    if (feasible) {
      EXPECT_LE(fb.predicted_ms(), fb.budget_ms() * (1 + 1e-9)) << f;
    }
    double true_s = truth.c0_s;
    for (std::size_t k = 0; k < n; ++k)
      true_s += object_cost_s(truth, chains[k][out[k]].triangles, chains[k][out[k]].vertices, 0.0);
    EXPECT_TRUE(fb.observe(1e3 * true_s * (1.0 + noise(rng)))) << f;
    records.push_back({out, bits(fb.predicted_ms()), bits(fb.coefficients().c0_s), bits(fb.coefficients().c1_s_per_tri),
                       feasible, fb.truncated(), fb.solver_moves()});
  }
  return records;
}

void expect_identical(const std::vector<FrameRecord>& a, const std::vector<FrameRecord>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t f = 0; f < a.size(); ++f) {
    EXPECT_EQ(a[f].lods, b[f].lods) << "frame " << f;
    EXPECT_EQ(a[f].predicted_bits, b[f].predicted_bits) << "frame " << f;
    EXPECT_EQ(a[f].c0_bits, b[f].c0_bits) << "frame " << f;
    EXPECT_EQ(a[f].c1_bits, b[f].c1_bits) << "frame " << f;
    EXPECT_EQ(a[f].feasible, b[f].feasible) << "frame " << f;
    EXPECT_EQ(a[f].truncated, b[f].truncated) << "frame " << f;
    EXPECT_EQ(a[f].moves, b[f].moves) << "frame " << f;
  }
}

TEST(BudgetDeterminism, FrameBudgetDefaultsAreDeterministic) {
  const FrameBudgetOptions defaults;
  EXPECT_FALSE(defaults.solve_time_limit.has_value());  // no wall clock unless asked for
  EXPECT_GT(defaults.max_moves, 0u);
  EXPECT_LT(defaults.max_moves, SolveLimits::kNoMoveLimit);
}

TEST(BudgetDeterminism, FrameBudgetIsBitIdenticalAcrossRunsOfManyFrames) {
  const std::vector<FrameRecord> a = run_frame_budget(FrameBudgetOptions{}, 600);
  const std::vector<FrameRecord> b = run_frame_budget(FrameBudgetOptions{}, 600);
  expect_identical(a, b);
  int truncated = 0;
  for (const FrameRecord& r : a) truncated += r.truncated;
  EXPECT_EQ(truncated, 0);  // the default limit does not bind on a scene this size
}

TEST(BudgetDeterminism, FrameBudgetTruncatedAtTheMoveLimitIsBitIdenticalAndFeasible) {
  FrameBudgetOptions options;
  options.max_moves = 8;
  const std::vector<FrameRecord> a = run_frame_budget(options, 600);
  const std::vector<FrameRecord> b = run_frame_budget(options, 600);
  expect_identical(a, b);
  int truncated = 0, infeasible = 0;
  for (const FrameRecord& r : a) {
    truncated += r.truncated;
    infeasible += !r.feasible;
    if (r.truncated) {
      EXPECT_GE(r.moves, 8u);
    }
  }
  EXPECT_GT(truncated, 50);  // the limit really binds
  EXPECT_EQ(infeasible, 0);  // and a truncated frame is still under the budget
}

}  // namespace
}  // namespace gazelod::budget
