// SPDX-License-Identifier: Apache-2.0
// World-space triangle soups and one-sided surface distances (bake/surface_deviation.hpp), the
// measure of gazelod eval gltfpack.
#include "bake/surface_deviation.hpp"

#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace gazelod::bake {
namespace {

TriangleSoup square(double z, int cells) {  // [0, 1]^2 at height z, cells x cells quads
  TriangleSoup s;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i)
      s.positions_xyz.insert(s.positions_xyz.end(), {float(i) / float(cells), float(j) / float(cells), float(z)});
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i)
      s.indices.insert(s.indices.end(),
                       {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  return s;
}

TEST(SurfaceDeviation, DistancesBetweenParallelSquares) {
  const SurfaceDeviation d = surface_deviation(square(0.25, 8), square(0.0, 1));
  EXPECT_EQ(d.vertices, 81u);
  EXPECT_NEAR(d.max_m, 0.25, 1e-6);
  EXPECT_NEAR(d.p99_m, 0.25, 1e-6);
  EXPECT_NEAR(d.mean_m, 0.25, 1e-6);
  // A fine grid's vertices lie on the coarse square it was cut from.
  const SurfaceDeviation same = surface_deviation(square(0.0, 8), square(0.0, 1));
  EXPECT_LT(same.max_m, 1e-6);
}

TEST(SurfaceDeviation, OneFarVertexShowsInTheLargestNotTheMean) {
  TriangleSoup bumped = square(0.0, 10);
  bumped.positions_xyz[3 * 60 + 2] = 1.0f;  // one inner vertex lifted 1 m
  const SurfaceDeviation d = surface_deviation(bumped, square(0.0, 1));
  EXPECT_NEAR(d.max_m, 1.0, 1e-6);
  EXPECT_LT(d.p99_m, 1e-6);  // 1 of 121 vertices is above the 99th percentile
  EXPECT_NEAR(d.mean_m, 1.0 / 121.0, 1e-6);
}

TEST(SurfaceDeviation, EmptySoups) {
  const SurfaceDeviation to_nothing = surface_deviation(square(0.0, 2), TriangleSoup{});
  EXPECT_TRUE(std::isinf(to_nothing.max_m));
  EXPECT_TRUE(std::isinf(to_nothing.mean_m));
  const SurfaceDeviation from_nothing = surface_deviation(TriangleSoup{}, square(0.0, 2));
  EXPECT_EQ(from_nothing.vertices, 0u);
  EXPECT_EQ(from_nothing.max_m, 0.0);
}

TEST(SurfaceDeviation, WorldTrianglesPlaceEveryInstance) {
  // scene_model (test_meshes.hpp): the sphere mesh on two nodes, the two-primitive wavy grid on one.
  const tinygltf::Model m = testing::scene_model();
  const TriangleSoup soup = world_triangles(m);
  EXPECT_EQ(soup.triangles(), 2u * 5120u + 2048u);
  // SphereCopy sits 5 m to the left of the origin, radius 0.5 m, no scale: x reaches -5.5.
  float min_x = std::numeric_limits<float>::infinity();
  for (std::size_t v = 0; v < soup.positions_xyz.size(); v += 3) min_x = std::min(min_x, soup.positions_xyz[v]);
  EXPECT_NEAR(min_x, -5.5f, 1e-3f);
  EXPECT_GT(soup_extent_m(soup), 5.0);
}

}  // namespace
}  // namespace gazelod::bake
