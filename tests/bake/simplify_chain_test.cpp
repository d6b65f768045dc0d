// SPDX-License-Identifier: Apache-2.0
// simplify_chain and the detail descriptor on generated meshes.
#include "bake/detail.hpp"
#include "bake/simplify_chain.hpp"

#include "bake/cluster_distance.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace gazelod::bake {
namespace {

using testing::icosphere;

// Largest distance from the sphere surface inward to a triangle's centroid: a lower bound on how
// far the simplified surface departs from the true sphere (independent of meshopt's metric).
double max_centroid_sag(const std::vector<float>& p, const std::vector<std::uint32_t>& idx, double r) {
  double sag = 0.0;
  for (std::size_t i = 0; i < idx.size(); i += 3) {
    double c[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) c[d] += p[3 * idx[i + k] + d] / 3.0;
    sag = std::max(sag, r - std::hypot(c[0], c[1], c[2]));
  }
  return sag;
}

TEST(SimplifyChain, IcosphereTrianglesFallAndErrorsRise) {
  const auto m = icosphere(4, 0.5);  // 5120 triangles
  ASSERT_EQ(m.triangles(), 5120u);
  ChainOptions o;  // 1/4, 1/16, 1/64
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, o);
  ASSERT_EQ(c.levels.size(), 4u);
  EXPECT_EQ(c.levels[0].indices, m.indices);
  EXPECT_EQ(c.levels[0].error_rel, 0.0);
  EXPECT_EQ(c.levels[0].vertices, m.positions.size() / 3);
  for (std::size_t k = 1; k < c.levels.size(); ++k) {
    const auto& l = c.levels[k];
    const double target = 5120.0 * o.ratios[k - 1];
    EXPECT_LT(l.indices.size(), c.levels[k - 1].indices.size()) << "level " << k;
    EXPECT_LE(double(l.indices.size() / 3), 1.2 * target) << "level " << k;
    EXPECT_GT(l.error_rel, c.levels[k - 1].error_rel) << "level " << k;
    EXPECT_NEAR(l.error_m, l.error_rel * c.scale_m, 1e-12);
    EXPECT_FALSE(l.sloppy);  // a closed sphere never gets stuck
    const double sag = max_centroid_sag(m.positions, l.indices, 0.5);
    // meshopt's error and the centroid sag measure the same deviation to within a small factor.
    EXPECT_GT(l.error_m, 0.2 * sag) << "level " << k;
    EXPECT_LT(l.error_m, 5.0 * sag) << "level " << k;
  }
}

TEST(SimplifyChain, ScaleIsTheLargestExtent) {
  const auto m = icosphere(2, 0.5);
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, ChainOptions{});
  double lo = 1e9, hi = -1e9;  // x extent; the icosphere is symmetric, all axes alike
  for (std::size_t i = 0; i < m.positions.size(); i += 3)
    lo = std::min(lo, double(m.positions[i])), hi = std::max(hi, double(m.positions[i]));
  EXPECT_NEAR(c.scale_m, hi - lo, 1e-6);
}

TEST(SimplifyChain, IndicesAreTrianglesIntoTheOriginalVertices) {
  const auto m = testing::grid(20, 1.0, 0.1);
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, ChainOptions{{0.5, 0.1}, 1.0});
  for (const auto& l : c.levels) {
    EXPECT_EQ(l.indices.size() % 3, 0u);
    std::set<std::uint32_t> used(l.indices.begin(), l.indices.end());
    EXPECT_EQ(l.vertices, used.size());
    for (auto i : l.indices) EXPECT_LT(i, m.positions.size() / 3);
  }
}

TEST(SimplifyChain, TargetErrorCapsEveryLevel) {
  const auto m = icosphere(4, 0.5);
  ChainOptions o;
  o.target_error_rel = 2e-3;
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, o);
  // A 5120-triangle sphere of diameter 1 cannot drop to 80 triangles within 2 mm of meshopt's
  // estimate: the last level stays far above its target (and may repeat the level before).
  EXPECT_GT(c.levels.back().indices.size() / 3, 2 * 80u);
  const PrimitiveChain free = simplify_chain(m.positions, m.indices, ChainOptions{});
  EXPECT_LT(c.levels.back().error_m, free.levels.back().error_m);
}

// The stored error is the largest distance from a source vertex to the level's triangles
// (brute force here), never meshopt's smaller estimate.
TEST(SimplifyChain, ErrorIsTheLargestDistanceFromTheSource) {
  const auto m = icosphere(4, 0.5);
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, ChainOptions{});
  double previous_m = 0.0;
  for (std::size_t k = 1; k < c.levels.size(); ++k) {
    const std::vector<std::uint32_t>& t = c.levels[k].indices;
    ASSERT_FALSE(t.empty());
    double largest_m = 0.0;
    for (std::size_t v = 0; v < m.positions.size() / 3; ++v) {
      const double p[3] = {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
      double nearest_m = 1e300;
      for (std::size_t i = 0; i < t.size(); i += 3) {
        double a[3], b[3], q[3];
        for (int j = 0; j < 3; ++j)
          a[j] = m.positions[3 * t[i] + j], b[j] = m.positions[3 * t[i + 1] + j], q[j] = m.positions[3 * t[i + 2] + j];
        nearest_m = std::min(nearest_m, point_triangle_distance(p, a, b, q));
      }
      largest_m = std::max(largest_m, nearest_m);
    }
    const double expected_m = std::max(largest_m, previous_m);  // a running maximum
    EXPECT_NEAR(c.levels[k].error_m, expected_m, 1e-9) << "level " << k;
    EXPECT_GT(c.levels[k].error_m, 0.0);
    previous_m = c.levels[k].error_m;
  }
}

TEST(SimplifyChain, SloppyFallbackWhenTopologyBlocks) {
  // Separate triangles have only border edges: with borders locked meshopt_simplify cannot
  // collapse any of them, so the level is reached by the sloppy simplifier.
  const auto m = testing::triangle_soup(2000);
  const PrimitiveChain locked = simplify_chain(m.positions, m.indices, ChainOptions{{0.25}, 1.0, true});
  ASSERT_EQ(locked.levels.size(), 2u);
  EXPECT_TRUE(locked.levels[1].sloppy);
  EXPECT_LE(locked.levels[1].indices.size(), m.indices.size() / 4 * 12 / 10);
  // Unlocked, meshopt_simplify removes whole triangles itself and needs no fallback.
  const PrimitiveChain free = simplify_chain(m.positions, m.indices, ChainOptions{{0.25}, 1.0, false});
  EXPECT_FALSE(free.levels[1].sloppy);
  EXPECT_LE(free.levels[1].indices.size(), m.indices.size() / 4 * 12 / 10);
}

TEST(SimplifyChain, FlatGridErrorStaysFiniteInDetail) {
  const auto m = testing::grid(16, 1.0, 0.0);  // flat: simplification is exact
  const PrimitiveChain c = simplify_chain(m.positions, m.indices, ChainOptions{{0.1}, 1.0});
  EXPECT_LT(c.levels[1].indices.size(), m.indices.size() / 4);
  EXPECT_LT(c.levels[1].error_m, 1e-5);
  const double d = detail_cycles_per_diameter(std::sqrt(2.0), c.levels[1].error_m);
  EXPECT_TRUE(std::isfinite(d));
  EXPECT_LE(d, 0.5 / kMinErrorFraction);
}

TEST(Detail, DiameterOverTwiceTheError) {
  EXPECT_DOUBLE_EQ(detail_cycles_per_diameter(2.0, 0.01), 100.0);  // 2 / 0.02
  EXPECT_DOUBLE_EQ(detail_cycles_per_diameter(1.0, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(detail_cycles_per_diameter(1.0, 0.0), 0.5 / kMinErrorFraction);  // floor
  EXPECT_EQ(detail_cycles_per_diameter(0.0, 0.1), 0.0);
  EXPECT_EQ(detail_cycles_per_diameter(NAN, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(detail_cycles_per_diameter(1.0, INFINITY), 0.5);
}

TEST(ChainOptions, ValidationNamesTheBadValue) {
  EXPECT_EQ(validate_chain_options(ChainOptions{}), "");
  EXPECT_NE(validate_chain_options(ChainOptions{{}, 1.0}).find("1 to 254"), std::string::npos);
  EXPECT_NE(validate_chain_options(ChainOptions{{1.0}, 1.0}).find("ratio 1 must be in (0, 1)"), std::string::npos);
  EXPECT_NE(validate_chain_options(ChainOptions{{0.5, 0.5}, 1.0}).find("decrease strictly"), std::string::npos);
  EXPECT_NE(validate_chain_options(ChainOptions{{0.5}, 0.0}).find("target error"), std::string::npos);
  EXPECT_NE(validate_chain_options(ChainOptions{{0.5}, NAN}).find("target error"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::bake
