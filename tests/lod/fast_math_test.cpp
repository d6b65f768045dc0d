// The selection loop's atan2 and log10 against libm, including tiny angles.
#include "lod/fast_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace gazelod::lod {
namespace {

TEST(FastMath, Atan2MatchesLibmEverywhere) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double y = std::abs(u(rng)) * std::pow(10.0, 6 * u(rng)), x = u(rng) * std::pow(10.0, 6 * u(rng));
    worst = std::max(worst, std::abs(fast::atan2_nonneg(y, x) - std::atan2(y, x)));
  }
  EXPECT_LT(worst, 2e-10);
  EXPECT_EQ(fast::atan2_nonneg(0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(fast::atan2_nonneg(0.0, -1.0), M_PI);
  EXPECT_DOUBLE_EQ(fast::atan2_nonneg(1.0, 0.0), M_PI / 2);
}

TEST(FastMath, Atan2KeepsTinyAnglesRelative) {
  for (double a : {1e-7, 1e-12, 1e-300}) EXPECT_NEAR(fast::atan2_nonneg(a, 1.0) / a, 1.0, 1e-12) << a;
  // acos of the matching dot product: 1e-7 rad keeps only 3 digits, 1e-9 rad becomes 0.
  EXPECT_GT(std::abs(std::acos(std::cos(1e-7)) / 1e-7 - 1.0), 1e-5);
  EXPECT_EQ(std::acos(std::cos(1e-9)), 0.0);
}

TEST(FastMath, Log10MatchesLibm) {
  double worst = 0.0;
  for (double x = 0.825; x < 1e7; x *= 1.0001) worst = std::max(worst, std::abs(fast::log10_normal(x) - std::log10(x)));
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(fast::log10_normal(1000.0), 3.0, 1e-12);
}

TEST(FastMath, Log10CoversTheSquaredVelocityRange) {
  // The selection takes log10 of v^2 clamped to [0.825^2, 200^2] (lod/select_kernel.cpp).
  double worst = 0.0;
  for (double x = 0.5; x < 1e5; x *= 1.00001) worst = std::max(worst, std::abs(fast::log10_normal(x) - std::log10(x)));
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(fast::log10_normal(0.825 * 0.825), 2.0 * std::log10(0.825), 1e-12);
}

TEST(FastMath, Atan2OctantSeamsAndSigns) {
  // Around tan(pi/8) (the reduction seam, where the series' truncation is largest), the
  // diagonal (steep) and x < 0: within the documented 2e-10, and no step across a seam.
  const double t8 = std::tan(M_PI / 8);
  for (double sx : {1.0, -1.0}) {
    for (double t : {t8 * (1 - 1e-15), t8, t8 * (1 + 1e-15), 1.0 - 1e-15, 1.0, 1.0 + 1e-15})
      EXPECT_NEAR(fast::atan2_nonneg(t, sx), std::atan2(t, sx), 2e-10) << t << " " << sx;
    for (double seam : {t8, 1.0})
      EXPECT_NEAR(fast::atan2_nonneg(seam * (1 + 4e-16), sx), fast::atan2_nonneg(seam * (1 - 4e-16), sx), 2e-10);
  }
  EXPECT_DOUBLE_EQ(fast::atan2_nonneg(0.0, -0.0), 0.0);  // -0 is not negative
  EXPECT_DOUBLE_EQ(fast::atan2_nonneg(1e-300, -1.0), M_PI);
}

}  // namespace
}  // namespace gazelod::lod
