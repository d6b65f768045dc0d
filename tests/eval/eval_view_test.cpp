// SPDX-License-Identifier: Apache-2.0
// The evaluation's helpers: the frustum test behind the "in view" figures, and the bar chart.
#include "apps/gazelod/compare/svg.hpp"
#include "apps/gazelod/eval/lod_map_frame.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace gazelod::cli {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Symmetric 43.6 x 33.4 deg (Reddy 1998's display).
lod::FovRad reddy_fov() {
  return {-21.8 * kDeg, 21.8 * kDeg, 16.7 * kDeg, -16.7 * kDeg};
}

TEST(SphereInView, AheadBehindAndBesides) {
  const glm::dquat still{1.0, 0.0, 0.0, 0.0};
  const glm::dvec3 eye{0.0};
  EXPECT_TRUE(sphere_in_view({0, 0, -10}, 0.5, eye, still, reddy_fov()));
  EXPECT_FALSE(sphere_in_view({0, 0, 10}, 0.5, eye, still, reddy_fov()));
  // 30 deg to the right at 10 m: outside the 21.8 deg half-width...
  const glm::dvec3 right30{10 * std::sin(30 * kDeg), 0, -10 * std::cos(30 * kDeg)};
  EXPECT_FALSE(sphere_in_view(right30, 0.5, eye, still, reddy_fov()));
  // ...unless the sphere reaches back inside: angular radius asin(2/10) = 11.5 deg > 8.2 deg.
  EXPECT_TRUE(sphere_in_view(right30, 2.0, eye, still, reddy_fov()));
  // A sphere around the eye is always in view.
  EXPECT_TRUE(sphere_in_view({0, 0, 1}, 2.0, eye, still, reddy_fov()));
}

TEST(SphereInView, FollowsTheHeadAndTheEyePosition) {
  // Head yawed 90 deg left (+Y): looking down -X; an object at -X is ahead, one at -Z is not.
  const glm::dquat left90 = glm::angleAxis(90 * kDeg, glm::dvec3(0, 1, 0));
  EXPECT_TRUE(sphere_in_view({-10, 0, 0}, 0.5, glm::dvec3(0.0), left90, reddy_fov()));
  EXPECT_FALSE(sphere_in_view({0, 0, -10}, 0.5, glm::dvec3(0.0), left90, reddy_fov()));
  // Moving past an object leaves it behind.
  const glm::dquat still{1.0, 0.0, 0.0, 0.0};
  EXPECT_FALSE(sphere_in_view({0, 0, -10}, 0.5, {0, 0, -20}, still, reddy_fov()));
  // Vertical: 20 deg up is outside the 16.7 deg half-height.
  EXPECT_FALSE(sphere_in_view({0, 10 * std::sin(20 * kDeg), -10 * std::cos(20 * kDeg)}, 0.1, glm::dvec3(0.0), still,
                              reddy_fov()));
}

TEST(SphereInView, NonFiniteIsNotInView) {
  const glm::dquat still{1.0, 0.0, 0.0, 0.0};
  EXPECT_FALSE(sphere_in_view({std::nan(""), 0, -10}, 0.5, glm::dvec3(0.0), still, reddy_fov()));
}

TEST(BarChart, OneBarPerValueEscapedLabelsNoBarForNonFinite) {
  BarChart c;
  c.title = "a<b & c";
  c.groups = {"g1", "g2"};
  c.series = {{"s1", "#111", {1.0, 2.0}}, {"s2", "#222", {std::nan(""), -1.0}}};
  std::ostringstream out;
  write_bar_chart(c, out);
  const std::string svg = out.str();
  std::size_t bars = 0;
  for (std::size_t p = svg.find("<title>"); p != std::string::npos; p = svg.find("<title>", p + 1)) ++bars;
  EXPECT_EQ(bars, 2u);  // NaN and negative values draw nothing
  EXPECT_NE(svg.find("a&lt;b &amp; c"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.rfind("</svg>"), svg.size() - 7);
}

}  // namespace
}  // namespace gazelod::cli
