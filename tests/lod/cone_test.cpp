// SPDX-License-Identifier: Apache-2.0
// Foveal cone: widened by the tracker's error, clamped, NaN includes everything.
#include "lod/cone.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::lod {
namespace {

TEST(Cone, InflatedByTrackerError) {
  const Cone c = make_foveal_cone({0, 0, 0}, {0, 0, -2}, 5.0, 1.5);
  EXPECT_NEAR(c.half_angle_rad, 6.5 * M_PI / 180, 1e-15);
  EXPECT_NEAR(glm::length(c.axis), 1.0, 1e-15);
  EXPECT_NEAR(make_foveal_cone({}, {0, 0, -1}, NAN, 0).half_angle_rad, M_PI, 1e-15);
  EXPECT_NEAR(make_foveal_cone({}, {0, 0, -1}, 170.0, 20.0).half_angle_rad, M_PI, 1e-15);
  EXPECT_EQ(make_foveal_cone({}, {0, 0, -1}, -5.0, 1.0).half_angle_rad, 0.0);
}

}  // namespace
}  // namespace gazelod::lod
