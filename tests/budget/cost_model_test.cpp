// SPDX-License-Identifier: Apache-2.0
// Cost model (Funkhouser & Sequin 1993 sec. 4) and its RLS calibration.
#include "budget/cost_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace gazelod::budget {
namespace {

TEST(BudgetCost, MaxOfGeometryAndFill) {
  const CostCoefficients c{0.0, 2e-8, 1e-8, 1e-9};
  EXPECT_DOUBLE_EQ(object_cost_s(c, 1000, 600, 1000), 2e-8 * 1000 + 1e-8 * 600);  // geometry
  EXPECT_DOUBLE_EQ(object_cost_s(c, 10, 10, 1e6), 1e-9 * 1e6);                    // fill
  EXPECT_DOUBLE_EQ(object_cost_s(c, -5, -5, -5), 0.0);
}

TEST(BudgetCost, RlsRecoversCoefficientsAndTracksAChange) {
  const CostCoefficients truth{5e-4, 3e-8, 1e-8, 2e-9};
  CostModelRls rls(CostCoefficients{1e-3, 1e-8, 1e-8, 1e-9}, 0.98);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 2e-5);
  auto run = [&](const CostCoefficients& t, int frames, CostPredictionReport* report) {
    for (int f = 0; f < frames; ++f) {
      FrameCostFeatures feat = rls.begin_frame();
      double measured = t.c0_s;
      for (int o = 0; o < 50; ++o) {
        const double tris = 2000 * u(rng), verts = 0.6 * tris, px = 4e5 * u(rng) * u(rng);
        add_object(rls.coefficients(), tris, verts, px, feat);
        measured += object_cost_s(t, tris, verts, px);
      }
      measured += noise(rng);
      if (report) report->add(feat.predicted_s, measured);
      ASSERT_TRUE(rls.update(feat, measured));
    }
  };
  run(truth, 400, nullptr);
  CostPredictionReport settled;
  run(truth, 200, &settled);
  EXPECT_LT(settled.mean_rel_error, 0.03);
  // The renderer slows down (thermal throttling): forgetting lets the fit follow.
  CostCoefficients slower = truth;
  slower.c1_s_per_tri *= 2;
  slower.c3_s_per_px *= 2;
  run(slower, 400, nullptr);
  CostPredictionReport after;
  run(slower, 200, &after);
  EXPECT_LT(after.mean_rel_error, 0.03);
  EXPECT_GT(after.frames, 0u);
  // Bad measurements are refused, not fed in.
  const CostCoefficients before = rls.coefficients();
  EXPECT_FALSE(rls.update(rls.begin_frame(), std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(rls.update(rls.begin_frame(), -1.0));
  EXPECT_EQ(rls.coefficients().c1_s_per_tri, before.c1_s_per_tri);
}

}  // namespace
}  // namespace gazelod::budget
