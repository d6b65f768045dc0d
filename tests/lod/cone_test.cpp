// Foveal cone: shells from the acuity model, and the membership tests never exclude an object
// that touches the cone (checked against points sampled inside the objects).
#include "lod/acuity.hpp"
#include "lod/cone.hpp"
#include "lod/criteria.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

bool point_in(const Cone& c, const glm::dvec3& p) {
  return angle_between_rad(c.axis, p - c.apex_m) <= c.half_angle_rad;
}

TEST(Cone, InflatedByTrackerError) {
  const Cone c = make_foveal_cone({0, 0, 0}, {0, 0, -2}, 5.0, 1.5);
  EXPECT_NEAR(c.half_angle_rad, 6.5 * M_PI / 180, 1e-15);
  EXPECT_NEAR(glm::length(c.axis), 1.0, 1e-15);
  EXPECT_NEAR(make_foveal_cone({}, {0, 0, -1}, NAN, 0).half_angle_rad, M_PI, 1e-15);
}

TEST(Cone, ShellsFollowAcuityModel) {
  const double xi = 12.45;
  const std::vector<double> f{13.0, 12.45, 8.0, 2.0, 0.0};
  std::vector<double> out(f.size());
  lod_shell_half_angles_deg(f, 0.0, xi, 1.0, 1.0, out);
  EXPECT_EQ(out[0], 0.0);  // above the display limit: invisible everywhere
  EXPECT_NEAR(out[1], eccentricity_threshold_deg(12.45) + 1.0, 1e-12);
  EXPECT_NEAR(out[2], eccentricity_threshold_deg(8.0) + 1.0, 1e-12);
  EXPECT_GT(out[3], out[2]);  // coarser detail: wider shell
  EXPECT_TRUE(std::isinf(out[4]));
  // Faster motion shrinks every shell.
  std::vector<double> fast(f.size());
  lod_shell_half_angles_deg(f, 30.0, xi, 1.0, 1.0, fast);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_LE(fast[k], out[k]);
}

TEST(Cone, SphereTestExactOnTangentCase) {
  const Cone c = make_foveal_cone({}, {0, 0, -1}, 10.0, 0.0);
  // Centre at 30 deg, radius subtending exactly 20 deg: touches.
  const double d = 10.0, r = d * std::sin(20.0 * M_PI / 180);
  const glm::dvec3 dir{std::sin(30.0 * M_PI / 180), 0, -std::cos(30.0 * M_PI / 180)};
  EXPECT_TRUE(sphere_touches_cone(c, dir * d, r * (1 + 1e-9)));
  EXPECT_FALSE(sphere_touches_cone(c, dir * d, r * (1 - 1e-6)));
  EXPECT_TRUE(sphere_touches_cone(c, {0, 0, 0.5}, 1.0));  // eye inside
  EXPECT_FALSE(sphere_touches_cone(c, {0, 0, 10}, 1.0));  // behind the eye
}

TEST(Cone, SphereAndBoxNeverExcludeTouchingObjects) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
  int touching = 0, box_over = 0;
  for (int scene = 0; scene < 3000; ++scene) {
    const glm::dvec3 eye{u(rng), u(rng), u(rng)};
    const Cone c = make_foveal_cone(eye, {u(rng) * 0.5, u(rng) * 0.5, -1}, 2 + 40 * u01(rng), 0.0);
    const glm::dvec3 centre = eye + glm::dvec3{u(rng) * 10, u(rng) * 10, -12 * u01(rng) + 2};
    const glm::dvec3 half{0.05 + u01(rng), 0.05 + u01(rng), 0.05 + u01(rng)};
    const glm::dvec3 lo = centre - half, hi = centre + half;
    bool sampled_inside = false;
    for (int k = 0; k < 4000 && !sampled_inside; ++k) {
      const glm::dvec3 p{lo.x + (hi.x - lo.x) * u01(rng), lo.y + (hi.y - lo.y) * u01(rng),
                         lo.z + (hi.z - lo.z) * u01(rng)};
      sampled_inside = point_in(c, p);
    }
    const bool box = box_touches_cone(c, lo, hi);
    const bool sphere = sphere_touches_cone(c, centre, glm::length(half));
    if (sampled_inside) {
      ++touching;
      ASSERT_TRUE(box) << scene;
      ASSERT_TRUE(sphere) << scene;
    }
    if (box) { ASSERT_TRUE(sphere) << scene; }  // the sphere encloses the box
    box_over += box && !sampled_inside;
  }
  EXPECT_GT(touching, 300);
  // Sampling misses thin slivers, so a few boxes report touching that sampling did not see.
  EXPECT_LT(box_over, 300);
}

TEST(Cone, BoxAxisThroughFaceOnly) {
  // The axis pierces a big face while every corner and edge lies outside a narrow cone.
  const Cone c = make_foveal_cone({}, {0, 0, -1}, 1.0, 0.0);
  EXPECT_TRUE(box_touches_cone(c, {-5, -5, -11}, {5, 5, -10}));
  EXPECT_FALSE(box_touches_cone(c, {1, 1, -11}, {2, 2, -10}));
  EXPECT_TRUE(box_touches_cone(c, {-1, -1, -1}, {1, 1, 1}));  // apex inside
  // Edge crossing: the box spans the cone sideways with corners outside.
  EXPECT_TRUE(box_touches_cone(c, {-5, -0.01, -10.01}, {5, 0.01, -9.99}));
}

TEST(Cone, ProjectedCircleBasics) {
  const Cone c = make_foveal_cone({}, {0, 0, -1}, 5.0, 0.0);
  EXPECT_TRUE(projected_circle_touches(c, {0, 0, -1}, {0, 1, 0}, {0, 0, -10}, 0.1));
  EXPECT_FALSE(projected_circle_touches(c, {0, 0, -1}, {0, 1, 0}, {5, 0, -10}, 0.1));
  EXPECT_TRUE(projected_circle_touches(c, {0, 0, -1}, {0, 1, 0}, {0, 0, 0.05}, 0.1));  // straddles eye
}

}  // namespace
}  // namespace gazelod::lod
