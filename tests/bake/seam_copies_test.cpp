// SPDX-License-Identifier: Apache-2.0
// A group stuck at attribute seams is simplified across them (ClusterBuildOptions::
// stuck_across_seams), each new corner given back the copy of its position from its triangle's
// side (bake/cluster/seam_copies.hpp).
#include "bake/cluster/cluster_build.hpp"
#include "bake/cluster/cluster_source.hpp"
#include "bake/cluster/seam_copies.hpp"
#include "tests/bake/cluster_invariants.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace gazelod::bake {
namespace {

// An L: a floor quad (z = 0, x in [0, 1]) and a wall quad (x = 0, z in [0, 1]) over y in
// [0, 1], meeting at x = z = 0 with the edge's vertices split (a hard edge): floor 0-3, wall
// 4-7, vertices 4 and 5 at the positions of 0 and 1. Vertex 8 is an unused copy of 2's position.
struct HardEdge {
  std::vector<float> pos{0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0,  // floor
                         0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1,  // wall
                         1, 0, 0};                            // unused
  std::vector<std::uint32_t> tris{0, 2, 3, 0, 3, 1,           // floor, facing +z
                                  4, 5, 7, 4, 7, 6};          // wall, facing +x
};

TEST(SeamCopies, ACornerTakesTheCopyOfTheSideItsTriangleFaces) {
  const HardEdge m;
  const std::vector<std::uint32_t> weld = weld_positions(m.pos);
  ASSERT_EQ(weld[4], 0u);
  ASSERT_EQ(weld[8], 2u);
  const SeamCopies seams(m.pos, weld, m.tris);
  EXPECT_EQ(seams.seam_positions(), 2u);  // the edge's two positions
  EXPECT_EQ(seams.copies(0), 2u);
  EXPECT_EQ(seams.copies(2), 1u) << "the unused vertex 8 is no copy";
  std::vector<std::uint64_t> pairs;
  seams.collect(m.tris, pairs);
  EXPECT_EQ(pairs.size(), 8u) << "every used vertex once";
  // One triangle over the floor and one over the wall, written with the representatives.
  std::vector<std::uint32_t> t{0, 2, 1, 0, 1, 6};
  seams.choose(t, pairs);
  EXPECT_EQ(t, (std::vector<std::uint32_t>{0, 2, 1, 4, 5, 6}));
  // The wall triangle first, and wall copies asked for a floor triangle: the facing decides.
  t = {4, 5, 6, 4, 2, 5};
  seams.choose(t, pairs);
  EXPECT_EQ(t, (std::vector<std::uint32_t>{4, 5, 6, 0, 2, 1}));
}

// Where many vertices share one position (a flat-shaded fan's apex: 100 copies), only the copies
// the group's own triangles use are candidates (the work per corner stays bounded).
TEST(SeamCopies, AManyCopyPositionChoosesAmongTheGroupsCopies) {
  std::vector<float> pos;
  std::vector<std::uint32_t> tris;
  for (int i = 0; i < 100; ++i) {  // triangle i: apex, rim i, rim i + 1, its own three vertices
    const double a0 = 2 * M_PI * i / 100, a1 = 2 * M_PI * (i + 1) / 100;
    const float t[9] = {0, 0, 0, float(std::cos(a0)), float(std::sin(a0)), 0, float(std::cos(a1)), float(std::sin(a1)),
                        0};
    for (int k = 0; k < 3; ++k) {
      tris.push_back(static_cast<std::uint32_t>(pos.size() / 3));
      pos.insert(pos.end(), t + 3 * k, t + 3 * k + 3);
    }
  }
  const std::vector<std::uint32_t> weld = weld_positions(pos);
  const SeamCopies seams(pos, weld, tris);
  EXPECT_EQ(seams.copies(0), 100u);
  std::vector<std::uint64_t> all, group_0_to_9;
  seams.collect(tris, all);
  seams.collect(std::span<const std::uint32_t>(tris).subspan(0, 30), group_0_to_9);
  // A triangle over fan triangle 50 (apex, its rim corners): all copies give triangle 50's apex.
  const std::vector<std::uint32_t> over_50{0, weld[tris[150 + 1]], weld[tris[150 + 2]]};
  std::vector<std::uint32_t> t = over_50;
  seams.choose(t, all);
  EXPECT_EQ(t[0], tris[150]);
  t = over_50;
  seams.choose(t, group_0_to_9);
  EXPECT_LT(t[0], 30u) << "an apex copy of the group's triangles 0..9";
  EXPECT_EQ(pos[3 * t[0]], 0.0f);
}

// A UV seam on a flat strip: both sides face alike, so the side the triangle lies on decides.
TEST(SeamCopies, OnAFlatSeamTheNearerSideWins) {
  // Left quad x in [-1, 0] (vertices 0-3), right quad x in [0, 1] (4-7); 1/3 and 4/6 share the
  // seam x = 0 as separate copies.
  const std::vector<float> pos{-1, 0, 0, 0, 0, 0, -1, 1, 0, 0, 1, 0,   // left
                               0,  0, 0, 1, 0, 0, 0,  1, 0, 1, 1, 0};  // right
  const std::vector<std::uint32_t> tris{0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6};
  const std::vector<std::uint32_t> weld = weld_positions(pos);
  const SeamCopies seams(pos, weld, tris);
  EXPECT_EQ(seams.seam_positions(), 2u);
  // A triangle over the right half, written with the left copies (the representatives).
  std::vector<std::uint64_t> pairs;
  seams.collect(tris, pairs);
  std::vector<std::uint32_t> t{1, 5, 3};
  seams.choose(t, pairs);
  EXPECT_EQ(t, (std::vector<std::uint32_t>{4, 5, 6}));
  t = {0, 1, 3};
  seams.choose(t, pairs);
  EXPECT_EQ(t, (std::vector<std::uint32_t>{0, 1, 3}));
}

// Every triangle with its own three vertices (a flat-shaded export): every vertex is a seam,
// which meshopt 0.18 will not collapse, so with seams kept nothing simplifies; across them the
// hierarchy goes on, keeps its invariants, and every stored corner is a vertex the source uses.
TEST(ClusterBuild, AGroupStuckAtSeamsIsSimplifiedAcrossThem) {
  const testing::TestMesh smooth = testing::grid(40, 10.0, 1.0);  // 3,200 triangles
  testing::TestMesh flat;
  for (std::uint32_t v : smooth.indices) {
    flat.indices.push_back(static_cast<std::uint32_t>(flat.positions.size() / 3));
    flat.positions.insert(flat.positions.end(), &smooth.positions[3 * v], &smooth.positions[3 * v + 3]);
  }
  ClusterBuildOptions kept, across;
  kept.stuck_across_seams = false;
  const ClusterBuildResult k = build_cluster_hierarchy(flat.positions, flat.indices, kept);
  const ClusterBuildResult a = build_cluster_hierarchy(flat.positions, flat.indices, across);
  EXPECT_EQ(k.groups, 0u) << "meshopt 0.18 collapsed a seam vertex";
  EXPECT_GT(a.groups, 0u);
  EXPECT_EQ(a.groups_across_seams, a.groups);
  EXPECT_GE(a.levels, 4u);
  std::size_t top = 0;
  for (std::size_t c = 0; c < a.hierarchy.size(); ++c)
    if (a.parent_group[c] < 0) top += a.hierarchy.index_count[c] / 3;
  EXPECT_LT(top, flat.triangles() / 8);
  testing::expect_hierarchy_invariants(a, flat.positions, flat.indices, across);
  // Corners are source vertices (each vertex here is used by one triangle only).
  std::set<std::uint32_t> used(flat.indices.begin(), flat.indices.end());
  for (std::uint32_t v : a.indices) ASSERT_TRUE(used.contains(v)) << v;
  // The same mesh welded simplifies by itself: nothing is retried.
  const ClusterBuildResult w = build_cluster_hierarchy(smooth.positions, smooth.indices, across);
  EXPECT_GT(w.groups, 0u);
  EXPECT_EQ(w.groups_across_seams, 0u);
}

}  // namespace
}  // namespace gazelod::bake
