// Cost model (F&S sec. 4, RLS calibration), benefit (F&S sec. 5 with the acuity limit) and
// Reddy's global scale.
#include "lod/benefit.hpp"
#include "lod/budget_scale.hpp"
#include "lod/cost_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace gazelod::lod {
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

TEST(BudgetBenefit, AccuracyFollowsFunkhouserSequin) {
  EXPECT_DOUBLE_EQ(fs_accuracy(0, 100, 2, 0.5), 0.0);               // nothing drawn
  EXPECT_DOUBLE_EQ(fs_accuracy(1, 100, 1, 0.5), 0.5);               // one flat polygon
  EXPECT_DOUBLE_EQ(fs_accuracy(4, 100, 2, 0.5), 1.0 - 0.5 / 16.0);  // Gouraud, 4 vertices
  EXPECT_DOUBLE_EQ(fs_accuracy(1000, 4, 1, 0.5), 1.0 - 0.5 / 4.0);  // capped by pixels
}

TEST(BudgetBenefit, DetailAboveTheAcuityLimitLosesNothing) {
  BenefitInputs in;
  in.size_px = 1000;
  in.samples = 50;
  in.full_samples = 5000;
  in.interpolation_m = 1;
  in.acuity_limit_cpd = 10;
  BenefitInputs full = in;
  full.samples = in.full_samples;
  full.removed_detail_cpd = 0;
  const double b_full = benefit(full);
  in.removed_detail_cpd = 12;  // removes only invisible detail
  EXPECT_DOUBLE_EQ(benefit(in), b_full);
  in.removed_detail_cpd = 10;  // the seam: still nothing visible
  EXPECT_DOUBLE_EQ(benefit(in), b_full);
  in.removed_detail_cpd = 9.999;  // just below: a tiny, continuous loss
  EXPECT_LT(benefit(in), b_full);
  EXPECT_NEAR(benefit(in), b_full, 1e-3 * b_full);
  in.removed_detail_cpd = 2;  // mostly visible loss
  const double b2 = benefit(in);
  in.removed_detail_cpd = 0;  // the whole loss
  EXPECT_LT(benefit(in), b2);
  EXPECT_DOUBLE_EQ(visible_loss_share(10, 0), 1.0);
  EXPECT_DOUBLE_EQ(visible_loss_share(0, 3), 0.0);  // no visible frequency at all
  EXPECT_DOUBLE_EQ(visible_loss_share(std::numeric_limits<double>::quiet_NaN(), 3), 0.0);
}

TEST(BudgetBenefit, ProductOfFactors) {
  BenefitInputs in;
  in.size_px = 200;
  in.samples = in.full_samples = 100;
  in.interpolation_m = 1;
  in.acuity_limit_cpd = 20;
  const double base = benefit(in);
  EXPECT_DOUBLE_EQ(base, 200 * (1 - 0.5 / 100));
  in.importance = 0.5;
  EXPECT_DOUBLE_EQ(benefit(in), 0.5 * base);
  in.level_change = 2;
  in.hysteresis_per_level = 0.1;
  EXPECT_DOUBLE_EQ(benefit(in), 0.5 * 0.8 * base);
  in.level_change = 50;
  EXPECT_DOUBLE_EQ(benefit(in), 0.0);  // clamped, never negative
  in.size_px = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(std::isnan(benefit(in)));
}

TEST(BudgetScaleTest, LowersOnOverrunRaisesWithSlack) {
  BudgetScale s;
  EXPECT_DOUBLE_EQ(s.scale(), 1.0);
  s.update(12.0, 10.0);  // 20 % over: proportional cut
  EXPECT_NEAR(s.scale(), 10.0 / 12.0, 1e-12);
  s.update(100.0, 10.0);  // far over: at most max_cut at once
  EXPECT_NEAR(s.scale(), 10.0 / 12.0 * 0.5, 1e-12);
  const double low = s.scale();
  s.update(9.0, 10.0);  // within the dead band: hold
  EXPECT_DOUBLE_EQ(s.scale(), low);
  for (int i = 0; i < 200; ++i) s.update(5.0, 10.0);
  EXPECT_NEAR(s.scale(), 1.0, 1e-6);
  EXPECT_LE(s.scale(), 1.0);
  for (int i = 0; i < 200; ++i) s.update(1000.0, 10.0);
  EXPECT_DOUBLE_EQ(s.scale(), 0.05);  // floor
  EXPECT_DOUBLE_EQ(s.apply(20.0), 1.0);
  s.update(std::numeric_limits<double>::quiet_NaN(), 10.0);
  EXPECT_DOUBLE_EQ(s.scale(), 0.05);
}

}  // namespace
}  // namespace gazelod::lod
