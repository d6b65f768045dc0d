// SPDX-License-Identifier: Apache-2.0
// View and projection against hand-computed values (OpenXR's XrFovf convention, Vulkan clip
// space with y down and depth 0..1).
#include "render/camera.hpp"
#include "render/render_error.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gazelod::render {
namespace {

// tan(left) = -1, tan(right) = 0.5, tan(up) = 0.5, tan(down) = -1: asymmetric both ways.
EyeView asymmetric_view() {
  EyeView v;
  v.fov = {-std::atan(1.0), std::atan(0.5), std::atan(0.5), -std::atan(1.0)};
  return v;
}

TEST(Camera, PointAtKnownAngleLandsOnHandComputedPixel) {
  // A point 0.25 to the right per metre ahead, on the horizon. The image spans tangents
  // -1..0.5 horizontally, so x = (0.25 + 1) / 1.5 * 300 = 250; vertically it spans
  // +0.5 (top) .. -1 (bottom), so the horizon is 0.5 / 1.5 = 1/3 down: y = 120 / 3 = 40.
  glm::dvec2 px;
  ASSERT_TRUE(project_to_pixel(asymmetric_view(), {0.25 * 4.0, 0.0, -4.0}, 300, 120, px));
  EXPECT_NEAR(px.x, 250.0, 1e-9);
  EXPECT_NEAR(px.y, 40.0, 1e-9);
}

TEST(Camera, FovEdgesMapToImageEdges) {
  const EyeView v = asymmetric_view();
  glm::dvec2 px;
  ASSERT_TRUE(project_to_pixel(v, {-2.0, 0.5 * 2.0, -2.0}, 300, 120, px));  // left, up edge
  EXPECT_NEAR(px.x, 0.0, 1e-9);
  EXPECT_NEAR(px.y, 0.0, 1e-9);
  ASSERT_TRUE(project_to_pixel(v, {0.5 * 3.0, -3.0, -3.0}, 300, 120, px));  // right, down edge
  EXPECT_NEAR(px.x, 300.0, 1e-9);
  EXPECT_NEAR(px.y, 120.0, 1e-9);
}

TEST(Camera, DepthIsZeroAtNearAndOneAtFar) {
  const glm::dmat4 p = projection_matrix({-0.5, 0.5, 0.5, -0.5}, 0.1, 100.0);
  const glm::dvec4 near_clip = p * glm::dvec4(0.0, 0.0, -0.1, 1.0);
  const glm::dvec4 far_clip = p * glm::dvec4(0.0, 0.0, -100.0, 1.0);
  EXPECT_NEAR(near_clip.z / near_clip.w, 0.0, 1e-12);
  EXPECT_NEAR(far_clip.z / far_clip.w, 1.0, 1e-12);
  const glm::dvec4 mid = p * glm::dvec4(0.0, 0.0, -1.0, 1.0);
  // z_ndc = f (z - n) / (z (f - n)) at z = 1: 100 * 0.9 / 99.9.
  EXPECT_NEAR(mid.z / mid.w, 100.0 * 0.9 / 99.9, 1e-12);
}

TEST(Camera, PoseRotatesAndTranslatesTheView) {
  EyeView v;
  v.fov = {-0.5, 0.5, 0.5, -0.5};
  // Yaw 90 degrees left (about +y): the eye at (1, 2, 3) now looks down -x.
  v.pose.orientation = glm::angleAxis(std::numbers::pi / 2.0, glm::dvec3(0.0, 1.0, 0.0));
  v.pose.position_m = {1.0, 2.0, 3.0};
  glm::dvec2 px;
  ASSERT_TRUE(project_to_pixel(v, {1.0 - 5.0, 2.0, 3.0}, 200, 100, px));
  EXPECT_NEAR(px.x, 100.0, 1e-9);
  EXPECT_NEAR(px.y, 50.0, 1e-9);
  // What was straight ahead before (-z) is now to the right of the eye, beyond the view edge
  // but still in front: 1 m towards -z at 5 m ahead is tan = 0.2 right: x = (0.2/tan 0.5 + 1) / 2 * 200.
  ASSERT_TRUE(project_to_pixel(v, {1.0 - 5.0, 2.0, 3.0 - 1.0}, 200, 100, px));
  EXPECT_NEAR(px.x, (0.2 / std::tan(0.5) + 1.0) * 100.0, 1e-9);
  // Behind the eye: no pixel.
  EXPECT_FALSE(project_to_pixel(v, {1.0 + 5.0, 2.0, 3.0}, 200, 100, px));
}

TEST(Camera, RejectsDegenerateFovAndDepthRange) {
  EXPECT_THROW(projection_matrix({0.5, -0.5, 0.5, -0.5}, 0.1, 10.0), RenderError);  // left > right
  EXPECT_THROW(projection_matrix({-0.5, 0.5, -0.5, 0.5}, 0.1, 10.0), RenderError);  // up < down
  EXPECT_THROW(projection_matrix({-1.6, 0.5, 0.5, -0.5}, 0.1, 10.0), RenderError);  // beyond 90 deg
  EXPECT_THROW(projection_matrix({-0.5, 0.5, 0.5, -0.5}, 0.0, 10.0), RenderError);
  EXPECT_THROW(projection_matrix({-0.5, 0.5, 0.5, -0.5}, 1.0, 1.0), RenderError);
  EXPECT_THROW(projection_matrix({-0.5, 0.5, NAN, -0.5}, 0.1, 10.0), RenderError);
}

}  // namespace
}  // namespace gazelod::render

namespace gazelod::render {
namespace {

TEST(ViewCuller, KeepsSpheresTouchingTheViewAndDropsTheRest) {
  EyeView v;
  v.fov = {-std::atan(1.0), std::atan(0.5), std::atan(0.5), -std::atan(1.0)};
  v.near_m = 0.1;
  v.far_m = 50.0;
  const ViewCuller c(v);
  EXPECT_TRUE(c.visible({0.0, 0.0, -5.0}, 0.1));
  // The right plane x = 0.5 * depth has unit normal (-1, 0.5) / sqrt(1.25): a centre at
  // depth 4 and x = 2 + s * sqrt(1.25) lies s outside it.
  const double k = std::sqrt(1.25);
  EXPECT_TRUE(c.visible({2.0 + 0.3 * k, 0.0, -4.0}, 0.31));
  EXPECT_FALSE(c.visible({2.0 + 0.3 * k, 0.0, -4.0}, 0.29));
  // Left plane x = -depth, normal (1, 1) / sqrt(2).
  EXPECT_TRUE(c.visible({-4.0 - 0.5 * std::sqrt(2.0), 0.0, -4.0}, 0.51));
  EXPECT_FALSE(c.visible({-4.0 - 0.5 * std::sqrt(2.0), 0.0, -4.0}, 0.49));
  // Up (y = 0.5 depth) and down (y = -depth).
  EXPECT_FALSE(c.visible({0.0, 2.0 + 0.3 * k, -4.0}, 0.29));
  EXPECT_FALSE(c.visible({0.0, -4.0 - 0.5 * std::sqrt(2.0), -4.0}, 0.49));
  // Behind the eye, before the near plane, beyond the far plane.
  EXPECT_FALSE(c.visible({0.0, 0.0, 5.0}, 1.0));
  EXPECT_TRUE(c.visible({0.0, 0.0, 0.5}, 1.0));  // the eye is inside it
  EXPECT_FALSE(c.visible({0.0, 0.0, -51.0}, 0.5));
  EXPECT_TRUE(c.visible({0.0, 0.0, -51.0}, 1.5));
}

}  // namespace
}  // namespace gazelod::render
