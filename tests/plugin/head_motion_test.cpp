// SPDX-License-Identifier: Apache-2.0
#include "plugin/head_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::plugin {
namespace {

glm::dquat about(const glm::dvec3& axis, double angle_rad) {
  return glm::angleAxis(angle_rad, glm::normalize(axis));
}

TEST(HeadMotion, ConstantYawRateIsRecovered) {
  const double rate = glm::radians(120.0);  // deg/s
  const glm::dquat q0 = about({0, 1, 0}, 0.3);
  const glm::dquat q1 = about({0, 1, 0}, 0.3 + rate * 0.011);
  const glm::dvec3 w = angular_velocity_from_poses(q0, q1, 0.011);
  EXPECT_NEAR(w.y, rate, 1e-9);
  EXPECT_NEAR(w.x, 0.0, 1e-12);
  EXPECT_NEAR(w.z, 0.0, 1e-12);
}

TEST(HeadMotion, SignFlippedQuaternionGivesTheShortRotation) {
  const glm::dquat q0 = about({1, 0, 0}, 0.1);
  const glm::dquat q1 = -about({1, 0, 0}, 0.12);  // same rotation, opposite sign
  const glm::dvec3 w = angular_velocity_from_poses(q0, q1, 0.01);
  EXPECT_NEAR(w.x, 2.0, 1e-9);
}

TEST(HeadMotion, TinyRotationsKeepTheirSize) {
  // 1e-7 rad in 10 ms: acos of a dot product would round this to 0.
  const glm::dquat q1 = about({0, 0, 1}, 1e-7);
  const glm::dvec3 w = angular_velocity_from_poses(glm::dquat(1, 0, 0, 0), q1, 0.01);
  EXPECT_NEAR(w.z, 1e-5, 1e-15);
}

TEST(HeadMotion, BadIntervalsGiveZero) {
  const glm::dquat q1 = about({0, 1, 0}, 0.5);
  EXPECT_EQ(glm::length(angular_velocity_from_poses(glm::dquat(1, 0, 0, 0), q1, 0.0)), 0.0);
  EXPECT_EQ(glm::length(angular_velocity_from_poses(glm::dquat(1, 0, 0, 0), q1, -1.0)), 0.0);
  EXPECT_EQ(glm::length(angular_velocity_from_poses(glm::dquat(1, 0, 0, 0), q1, NAN)), 0.0);
  const glm::dquat bad(NAN, 0, 0, 0);
  const glm::dvec3 w = angular_velocity_from_poses(bad, q1, 0.01);
  EXPECT_TRUE(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z));
}

}  // namespace
}  // namespace gazelod::plugin
