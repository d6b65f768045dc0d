// SPDX-License-Identifier: Apache-2.0
// A frame that takes ten times its budget, and measured times that are no time at all (NaN,
// infinite, negative), fed to the frame-budget scheduler (budget/frame_budget.hpp): the next
// frames are still chosen, coarser or equal, under the budget by prediction, with finite
// coefficients; bad measurements are refused and change nothing.
#include "budget/frame_budget.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

namespace gazelod::budget {
namespace {

lod::LodLevel level(std::uint32_t tris) {
  lod::LodLevel l;
  l.triangles = tris;
  l.vertices = tris / 2;
  return l;
}

std::vector<std::vector<lod::LodLevel>> chains(std::size_t objects) {
  return std::vector<std::vector<lod::LodLevel>>(objects,
                                                 {level(200000), level(50000), level(12500), level(3000), level(800)});
}

int total(const std::vector<std::uint8_t>& lods) {
  return std::accumulate(lods.begin(), lods.end(), 0);
}

bool finite(const budget::CostCoefficients& c) {
  return std::isfinite(c.c0_s) && std::isfinite(c.c1_s_per_tri) && std::isfinite(c.c2_s_per_vert) &&
         std::isfinite(c.c3_s_per_px);
}

TEST(BudgetFaults, AFrameTenTimesOverBudgetMakesTheNextFramesCoarserNotBroken) {
  const std::size_t n = 20;
  const double budget_ms = 11.1;
  FrameBudget fb(chains(n), budget_ms);
  const std::vector<std::uint8_t> perceptual(n, 0);
  const std::vector<BudgetObjectView> view(n, BudgetObjectView{5000.0, 1.0});
  std::vector<std::uint8_t> lods(n);
  // Settle on the prior's model: measured = predicted.
  for (int i = 0; i < 30; ++i) {
    ASSERT_EQ(fb.choose(perceptual, view, lods), "");
    ASSERT_TRUE(fb.observe(fb.predicted_ms()));
  }
  const int settled = total(lods);
  ASSERT_EQ(fb.choose(perceptual, view, lods), "");
  ASSERT_FALSE(fb.infeasible());
  ASSERT_TRUE(fb.observe(10.0 * budget_ms));  // the hitch
  EXPECT_TRUE(finite(fb.coefficients()));
  ASSERT_EQ(fb.choose(perceptual, view, lods), "");
  const bool feasible = !fb.infeasible();
  EXPECT_TRUE(std::isfinite(fb.predicted_ms()));
  if (feasible) {
    EXPECT_LE(fb.predicted_ms(), budget_ms * (1 + 1e-9));
  }
  EXPECT_GE(total(lods), settled);  // coarser (larger level numbers) or equal, never finer
  for (std::size_t k = 0; k < n; ++k) EXPECT_LT(lods[k], 5) << k;
  // Frames go back to normal: the scheduler keeps choosing complete frames.
  for (int i = 0; i < 200; ++i) {
    ASSERT_EQ(fb.choose(perceptual, view, lods), "");
    ASSERT_TRUE(fb.observe(fb.predicted_ms()));
    ASSERT_TRUE(std::isfinite(fb.predicted_ms())) << i;
  }
  EXPECT_TRUE(finite(fb.coefficients()));
}

TEST(BudgetFaults, NonTimesAreRefusedAndChangeNothing) {
  const std::size_t n = 5;
  FrameBudget fb(chains(n), 11.1);
  const std::vector<std::uint8_t> perceptual(n, 0);
  const std::vector<BudgetObjectView> view(n, BudgetObjectView{1000.0, 1.0});
  std::vector<std::uint8_t> lods(n);
  EXPECT_FALSE(fb.observe(5.0));  // before any choose()
  ASSERT_EQ(fb.choose(perceptual, view, lods), "");
  const budget::CostCoefficients before = fb.coefficients();
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity(), -1.0})
    EXPECT_FALSE(fb.observe(bad)) << bad;
  EXPECT_EQ(fb.coefficients().c1_s_per_tri, before.c1_s_per_tri);
  EXPECT_EQ(fb.coefficients().c0_s, before.c0_s);
}

// The same faults replayed give the same frames: the choice depends on the inputs only (a move
// limit, no wall clock), so a hitch can be reproduced exactly.
TEST(BudgetFaults, ReplayingTheSameFaultsGivesTheSameFrames) {
  const std::size_t n = 50;
  auto replay = [&] {
    FrameBudget fb(chains(n), 11.1);
    std::vector<std::uint8_t> perceptual(n, 0);
    std::vector<BudgetObjectView> view(n, BudgetObjectView{5000.0, 1.0});
    std::vector<std::uint8_t> lods(n);
    std::vector<std::vector<std::uint8_t>> frames;
    for (int i = 0; i < 120; ++i) {
      view[static_cast<std::size_t>(i) % n].size_px *= 1.5;
      perceptual[static_cast<std::size_t>(i * 7) % n] ^= 1;
      EXPECT_EQ(fb.choose(perceptual, view, lods), "");
      frames.push_back(lods);
      const double measured = i % 40 == 20   ? 10.0 * 11.1                               // a hitch
                              : i % 40 == 30 ? std::numeric_limits<double>::quiet_NaN()  // refused
                                             : fb.predicted_ms() * 1.1;
      EXPECT_EQ(fb.observe(measured), std::isfinite(measured)) << i;  // the NaN frame is refused
    }
    return frames;
  };
  EXPECT_EQ(replay(), replay());
}

}  // namespace
}  // namespace gazelod::budget
