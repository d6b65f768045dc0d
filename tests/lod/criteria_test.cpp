// SPDX-License-Identifier: Apache-2.0
// Per-object criteria: the geometric hard cases (gaze through the centre, eye inside the
// sphere, object behind the eye, tiny angles) and retinal velocity.
#include "auxiliary/angles.hpp"
#include "tests/lod/reference_criteria.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::lod {
namespace {

const glm::dvec3 kEye{0.0}, kFwd{0.0, 0.0, -1.0};

TEST(Criteria, GazeThroughCentre) {
  EXPECT_EQ(nearest_point_eccentricity_deg(kEye, kFwd, {0, 0, -10}, 1.0), 0.0);
  // Off-centre but the gaze ray still passes through the sphere: 0 as well.
  EXPECT_EQ(nearest_point_eccentricity_deg(kEye, kFwd, {0.5, 0, -10}, 1.0), 0.0);
}

TEST(Criteria, EyeInsideBoundingSphere) {
  EXPECT_EQ(nearest_point_eccentricity_deg(kEye, kFwd, {0, 0, 3}, 5.0), 0.0);
  EXPECT_DOUBLE_EQ(angular_radius_rad(3.0, 5.0), M_PI / 2);
  EXPECT_DOUBLE_EQ(angular_radius_rad(5.0, 5.0), M_PI / 2);  // on the surface
  EXPECT_DOUBLE_EQ(angular_radius_rad(0.0, 5.0), M_PI / 2);
}

TEST(Criteria, ObjectBehindEye) {
  const double e = nearest_point_eccentricity_deg(kEye, kFwd, {0, 0, 10}, 1.0);
  EXPECT_NEAR(e, 180.0 - std::asin(0.1) * 180 / M_PI, 1e-9);
  EXPECT_LE(e, 180.0);
}

TEST(Criteria, TinyAngles1em7Rad) {
  // A direction 1e-7 rad off the gaze: acos of the dot product returns 0, atan2 keeps it.
  const glm::dvec3 dir{std::sin(1e-7), 0.0, -std::cos(1e-7)};
  EXPECT_NEAR(aux::angle_between_rad(kFwd, dir), 1e-7, 1e-15);
  // acos of the dot product keeps only about 3 digits here (and returns 0 at 1e-9 rad).
  EXPECT_GT(std::abs(std::acos(glm::dot(kFwd, glm::normalize(dir))) / 1e-7 - 1.0), 1e-5);
  EXPECT_NEAR(nearest_point_eccentricity_deg(kEye, kFwd, dir * 1000.0, 0.0), 1e-7 * 180 / M_PI, 1e-15);
  EXPECT_NEAR(angular_radius_rad(1.0, 1e-7), 1e-7, 1e-20);
}

TEST(Criteria, AngularRadiusJustOutside) {
  EXPECT_NEAR(angular_radius_rad(2.0, 1.0), M_PI / 6, 1e-15);
  const double a = angular_radius_rad(std::nextafter(1.0, 2.0), 1.0);
  EXPECT_LE(a, M_PI / 2);
  EXPECT_GT(a, 1.57);
  EXPECT_EQ(angular_radius_rad(10.0, 0.0), 0.0);
}

TEST(Criteria, PixelDiameter) {
  EXPECT_DOUBLE_EQ(pixel_diameter_px(1.0, 20.0), 40.0);
}

TEST(Criteria, HeadRotationSweepsStaticObjects) {
  // 100 deg/s yaw: a static object ahead moves at 100 deg/s on the retina (eyes fixed in head).
  const glm::dvec3 w{0.0, 100.0 * M_PI / 180, 0.0};
  EXPECT_NEAR(retinal_velocity_dps(kEye, {}, w, {0, 0, -5}, {}), 100.0, 1e-9);
  // On the rotation axis it does not move.
  EXPECT_NEAR(retinal_velocity_dps(kEye, {}, w, {0, 5, 0}, {}), 0.0, 1e-9);
}

TEST(Criteria, TranslationAndObjectMotion) {
  // Object 10 m ahead crossing at 1 m/s: 0.1 rad/s.
  EXPECT_NEAR(retinal_velocity_dps(kEye, {}, {}, {0, 0, -10}, {1, 0, 0}), 0.1 * 180 / M_PI, 1e-9);
  // The head moving the same way: no relative motion.
  EXPECT_NEAR(retinal_velocity_dps(kEye, {1, 0, 0}, {}, {0, 0, -10}, {1, 0, 0}), 0.0, 1e-12);
  // Motion along the line of sight: no angular motion.
  EXPECT_NEAR(retinal_velocity_dps(kEye, {}, {}, {0, 0, -10}, {0, 0, 5}), 0.0, 1e-12);
}

TEST(Criteria, SmoothPursuitKeepsObjectStill) {
  // The object crosses at 0.1 rad/s about +y... and the gaze follows it at the same rate.
  const glm::dvec3 c{0, 0, -10}, v{1, 0, 0};
  const glm::dvec3 w_obj = glm::cross(c, v) / glm::dot(c, c);
  EXPECT_NEAR(retinal_velocity_dps(kEye, {}, w_obj, c, v), 0.0, 1e-12);
  EXPECT_EQ(retinal_velocity_dps(kEye, {}, w_obj, kEye, v), 0.0);  // centre at the eye
}

}  // namespace
}  // namespace gazelod::lod
