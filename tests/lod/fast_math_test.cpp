// SPDX-License-Identifier: Apache-2.0
// The selection loop's atan2 and log10 against libm, including tiny angles.
#include "lod/fast_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace gazelod::lod {
namespace {

// atan2 through the half-angle form, with the length computed as the kernel has it.
double atan2_fast(double y, double x) {
  return fast::atan2_with_norm(y, x, std::hypot(x, y));
}

TEST(FastMath, Atan2MatchesLibmEverywhere) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double y = std::abs(u(rng)) * std::pow(10.0, 6 * u(rng)), x = u(rng) * std::pow(10.0, 6 * u(rng));
    worst = std::max(worst, std::abs(atan2_fast(y, x) - std::atan2(y, x)));
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_EQ(atan2_fast(0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(atan2_fast(0.0, -1.0), M_PI);
  EXPECT_DOUBLE_EQ(atan2_fast(1.0, 0.0), M_PI / 2);
  EXPECT_TRUE(std::isnan(atan2_fast(0.0, 0.0)));  // n = 0: the kernel blends it away
}

TEST(FastMath, AtanUnitRatioOverTheWholeRange) {
  double worst = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double num = i / 100000.0;
    worst = std::max(worst, std::abs(fast::atan_unit_ratio(num, 1.0) - std::atan(num)));
    worst = std::max(worst, std::abs(fast::atan_unit_ratio(num * 3e-200, 3e-200) - std::atan(num)));
  }
  EXPECT_LT(worst, 1e-10);
}

TEST(FastMath, Atan2KeepsTinyAnglesRelative) {
  for (double a : {1e-7, 1e-12, 1e-300}) EXPECT_NEAR(atan2_fast(a, 1.0) / a, 1.0, 1e-12) << a;
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

TEST(FastMath, Atan2SeamsAndSigns) {
  // The half angle at tan(pi/8) (the reduction seam, where the polynomial's error is
  // largest: atan2 = pi/4 there), the x = 0 and x < 0 sides: within the documented 1e-10,
  // and no step across a seam.
  const double s4 = std::sin(M_PI / 4), c4 = std::cos(M_PI / 4);
  for (double sx : {1.0, -1.0}) {
    for (double k : {1 - 1e-15, 1.0, 1 + 1e-15})
      EXPECT_NEAR(atan2_fast(s4 * k, sx * c4), std::atan2(s4 * k, sx * c4), 1e-10) << k << " " << sx;
    const double t8 = std::tan(M_PI / 8);
    EXPECT_NEAR(fast::atan_unit_ratio(t8 * (1 + 4e-16), 1.0), fast::atan_unit_ratio(t8 * (1 - 4e-16), 1.0), 1e-10);
  }
  EXPECT_DOUBLE_EQ(atan2_fast(1.0, -1e-300), M_PI / 2);
  EXPECT_DOUBLE_EQ(atan2_fast(0.0, -0.0 - 1.0), M_PI);
  EXPECT_DOUBLE_EQ(atan2_fast(1e-300, -1.0), M_PI);
}

}  // namespace
}  // namespace gazelod::lod
