// SPDX-License-Identifier: Apache-2.0
// Angles and the yaw/pitch convention (auxiliary/angles.hpp, auxiliary/yaw_pitch.hpp): the one
// slerp is defined at parallel and antiparallel inputs, yaw is positive to the left, and the
// conversion from "positive yaw = right" formats gives, bit for bit, what the trace reader and
// the layer configuration computed before they shared it.
#include "auxiliary/angles.hpp"
#include "auxiliary/yaw_pitch.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace gazelod::aux {
namespace {

const glm::dvec3 kForward{0.0, 0.0, -1.0};

TEST(Angles, AngleBetweenIsExactForTinyAngles) {
  const double a = 1e-9;
  EXPECT_NEAR(angle_between_rad(kForward, {std::sin(a), 0.0, -std::cos(a)}), a, 1e-22);
  EXPECT_EQ(angle_between_rad(kForward, glm::dvec3(0.0)), 0.0);
  EXPECT_NEAR(angle_between_rad(kForward, -kForward), std::numbers::pi, 1e-15);
}

TEST(Angles, SlerpFollowsTheGreatCircle) {
  const glm::dvec3 to = glm::normalize(glm::dvec3(1.0, 0.5, -1.0));
  const double whole = angle_between_rad(kForward, to);
  for (double f : {0.0, 0.25, 0.5, 1.0}) {
    const glm::dvec3 d = slerp_direction(kForward, to, f);
    EXPECT_NEAR(glm::length(d), 1.0, 1e-15);
    EXPECT_NEAR(angle_between_rad(kForward, d), f * whole, 1e-14);
    EXPECT_NEAR(angle_between_rad(d, to), (1.0 - f) * whole, 1e-14);
  }
}

TEST(Angles, SlerpAtParallelAndAntiparallelInputs) {
  for (double f : {0.0, 0.3, 1.0}) EXPECT_EQ(slerp_direction(kForward, kForward, f), kForward);
  // Antiparallel: a continuous half turn, from `from` to `to`, the same path every time.
  const glm::dvec3 back = -kForward;
  EXPECT_NEAR(angle_between_rad(slerp_direction(kForward, back, 0.0), kForward), 0.0, 1e-15);
  EXPECT_NEAR(angle_between_rad(slerp_direction(kForward, back, 1.0), back), 0.0, 1e-15);
  const glm::dvec3 half = slerp_direction(kForward, back, 0.5);
  EXPECT_NEAR(glm::length(half), 1.0, 1e-15);
  EXPECT_NEAR(glm::dot(half, kForward), 0.0, 1e-15);
  EXPECT_EQ(half, slerp_direction(kForward, back, 0.5));
  for (double f = 0.0; f <= 1.0; f += 0.125)
    EXPECT_NEAR(angle_between_rad(kForward, slerp_direction(kForward, back, f)), f * std::numbers::pi, 1e-12);
}

TEST(YawPitch, PositiveYawTurnsLeftPositivePitchLooksUp) {
  const glm::dvec3 left = direction_from({0.5, 0.0});
  EXPECT_LT(left.x, 0.0);
  const glm::dvec3 up = direction_from({0.0, 0.5});
  EXPECT_GT(up.y, 0.0);
  // The rotation and the direction agree: R * forward.
  const YawPitch a{0.7, -0.3};
  const glm::dvec3 rotated = rotation_from(a) * kForward;
  EXPECT_NEAR(angle_between_rad(rotated, direction_from(a)), 0.0, 1e-15);
  const YawPitch back = yaw_pitch_of(direction_from(a));
  EXPECT_NEAR(back.yaw_rad, a.yaw_rad, 1e-15);
  EXPECT_NEAR(back.pitch_rad, a.pitch_rad, 1e-15);
}

TEST(YawPitch, OrientationAlongLooksAlongTheDirectionWithoutRoll) {
  for (glm::dvec3 d : {glm::dvec3(0.3, 0.1, -1.0), glm::dvec3(-0.5, -0.4, -0.2), glm::dvec3(1.0, 0.0, 0.0)}) {
    const glm::dquat q = orientation_along(d);
    EXPECT_NEAR(angle_between_rad(q * kForward, d), 0.0, 1e-12);
    EXPECT_NEAR((q * glm::dvec3(1.0, 0.0, 0.0)).y, 0.0, 1e-12);
  }
}

// What gaze::direction_from_yaw_pitch_deg and the layer configuration wrote inline before
// (yaw positive right): the shared conversion must give the same doubles.
TEST(YawPitch, YawRightFormatsKeepTheirMeaningBitForBit) {
  for (double yaw = -170.0; yaw <= 170.0; yaw += 7.3) {
    for (double pitch = -80.0; pitch <= 80.0; pitch += 9.1) {
      const double y = yaw * kRadPerDeg, p = pitch * kRadPerDeg;
      const glm::dvec3 before{std::cos(p) * std::sin(y), std::sin(p), -std::cos(p) * std::cos(y)};
      ASSERT_EQ(direction_from(yaw_pitch_from_yaw_right_deg(yaw, pitch)), before) << yaw << " " << pitch;
      const glm::dquat q_before = glm::angleAxis(-yaw * (std::numbers::pi / 180.0), glm::dvec3(0.0, 1.0, 0.0)) *
                                  glm::angleAxis(pitch * (std::numbers::pi / 180.0), glm::dvec3(1.0, 0.0, 0.0));
      ASSERT_EQ(rotation_from(yaw_pitch_from_yaw_right_deg(yaw, pitch)), q_before) << yaw << " " << pitch;
    }
  }
  EXPECT_GT(direction_from(yaw_pitch_from_yaw_right_deg(30.0, 0.0)).x, 0.0);  // right stays right
}

}  // namespace
}  // namespace gazelod::aux
