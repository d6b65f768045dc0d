// SPDX-License-Identifier: Apache-2.0
// The float atan2 and log10 of the cluster kernel (lod/cluster/cluster_select_math.hpp) against libm,
// within the bounds its slacks assume (lod/cluster/cluster_select_kernel.hpp).
#include "lod/cluster/cluster_select_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace gazelod::lod {
namespace {

TEST(ClusterSelectMath, Atan2WithinAMicroradian) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 300000; ++i) {
    const float y = static_cast<float>(std::abs(u(rng)) * std::pow(10.0, 4 * u(rng)));
    const float x = static_cast<float>(u(rng) * std::pow(10.0, 4 * u(rng)));
    const float n = static_cast<float>(std::hypot(double(x), double(y)));
    worst = std::max(worst, std::abs(double(fastf::atan2_with_norm(y, x, n)) - std::atan2(double(y), double(x))));
  }
  EXPECT_LT(worst, 1e-6);  // the kernel allows 4e-6 rad for E altogether
  EXPECT_EQ(fastf::atan2_with_norm(0.0f, 1.0f, 1.0f), 0.0f);
  EXPECT_NEAR(fastf::atan2_with_norm(0.0f, -1.0f, 1.0f), M_PI, 1e-6);
  // Tiny angles keep their relative precision.
  const float tiny = 1e-7f;
  EXPECT_NEAR(fastf::atan2_with_norm(tiny, 1.0f, 1.0f), tiny, 1e-13);
}

TEST(ClusterSelectMath, Log10OverTheVelocityRange) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const float x = static_cast<float>(0.825 * std::pow(200.0 / 0.825, i / 200000.0));
    worst = std::max(worst, std::abs(double(fastf::log10_normal(x)) - std::log10(double(x))));
  }
  EXPECT_LT(worst, 5e-7);                             // G within 27.78 x 5e-7 = 1.4e-5 cycles/deg; slack 1e-4
  EXPECT_NEAR(fastf::log10_normal(1.0f), 0.0, 3e-7);  // an end of the fitted interval
  EXPECT_NEAR(fastf::log10_normal(100.0f), 2.0, 5e-7);
}

}  // namespace
}  // namespace gazelod::lod
