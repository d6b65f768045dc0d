// SPDX-License-Identifier: Apache-2.0
// simplify_group_triangles (bake/cluster/group_simplify.hpp), one group's step on its own: the target
// share, free collapses past it on flat panels, locks honoured, too small a group left alone,
// and fold retries that never keep a wider fold.
#include "bake/city_mesh.hpp"
#include "bake/cluster/group_simplify.hpp"
#include "bake/meshopt_lock.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

namespace gazelod::bake {
namespace {

GroupSimplified run(std::vector<float> positions, const std::vector<std::uint32_t>& indices,
                    const GroupSimplifyOptions& o, std::vector<std::uint32_t>& out) {
  GroupSimplifyScratch scratch;
  const std::size_t vertices = positions.size() / 3;
  return simplify_group_triangles(positions, vertices, indices, o, out, scratch);
}

// Every output corner is one of the group's own vertices (never a lock copy).
void expect_own_vertices(const std::vector<std::uint32_t>& out, std::size_t count, std::size_t vertices) {
  for (std::size_t i = 0; i < count; ++i) ASSERT_LT(out[i], vertices) << "index " << i;
}

TEST(GroupSimplify, CurvedSurfaceStopsNearTheTargetShare) {
  const testing::TestMesh m = testing::grid(16, 1.0, 0.1);  // 512 triangles, curved everywhere
  std::vector<std::uint32_t> out;
  const GroupSimplified r = run(m.positions, m.indices, {}, out);
  EXPECT_EQ(out.size(), m.indices.size());
  EXPECT_GT(r.index_count, 0u);
  EXPECT_EQ(r.index_count % 3, 0u);
  EXPECT_LE(r.index_count, m.indices.size() / 2);          // meshopt stops at or under the target
  EXPECT_GE(r.index_count, m.indices.size() / 2 - 3 * 8);  // and close to it, with no error limit
  expect_own_vertices(out, r.index_count, m.positions.size() / 3);
}

TEST(GroupSimplify, FlatPanelTakesEveryFreeCollapse) {
  const testing::TestMesh m = testing::grid(16, 1.0, 0.0);  // flat: every collapse is free
  std::vector<std::uint32_t> out;
  const GroupSimplified r = run(m.positions, m.indices, {}, out);
  // Far past half, down to the few triangles a flat square with a free rim needs.
  EXPECT_GT(r.index_count, 0u);
  EXPECT_LE(r.index_count, m.indices.size() / 8) << r.index_count / 3 << " triangles left of " << m.triangles();
  EXPECT_EQ(r.folds.triangles, 0u);
  expect_own_vertices(out, r.index_count, m.positions.size() / 3);
}

TEST(GroupSimplify, LockedPositionsAreKept) {
  const testing::TestMesh m = testing::grid(16, 1.0, 0.0);
  std::vector<float> locked = m.positions;
  const std::size_t vertices = m.positions.size() / 3;
  // The grid's rim, on x = 0 and x = 1, locked by two copies each (meshopt 0.18 has no lock).
  std::set<std::uint32_t> rim;
  for (std::uint32_t v = 0; v < vertices; ++v)
    if (m.positions[3 * v] == 0.0f || m.positions[3 * v] == 1.0f) lock_position(locked, v), rim.insert(v);
  ASSERT_EQ(rim.size(), 2u * 17u);
  GroupSimplifyScratch scratch;
  std::vector<std::uint32_t> out;
  const GroupSimplified r = simplify_group_triangles(locked, vertices, m.indices, {}, out, scratch);
  ASSERT_GT(r.index_count, 0u);
  expect_own_vertices(out, r.index_count, vertices);
  std::set<std::uint32_t> used(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(r.index_count));
  for (std::uint32_t v : rim) EXPECT_TRUE(used.count(v)) << "locked vertex " << v << " collapsed";
  // With everything locked nothing moves at all.
  std::vector<float> all = m.positions;
  for (std::size_t v = 0; v < vertices; ++v) lock_position(all, v);
  const GroupSimplified none = simplify_group_triangles(all, vertices, m.indices, {}, out, scratch);
  EXPECT_EQ(none.index_count, m.indices.size());
}

TEST(GroupSimplify, TooFewTrianglesForTheTargetIsNoResult) {
  const std::vector<float> one{0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<std::uint32_t> out;
  EXPECT_EQ(run(one, {0, 1, 2}, {}, out).index_count, 0u);  // half of one triangle is none
}

// On one generated city block (panelled walls, where meshopt 0.18 folds) the retries never keep
// a result with a wider fold, and on some groups narrow it.
TEST(GroupSimplify, FoldRetriesNeverWidenTheWidestFold) {
  CityOptions city;
  city.triangles = 10'000;
  const GeneratedMesh block = city_meshes(city).at(0);
  GroupSimplifyOptions once, retried;
  once.fold_retries = 0;
  retried.fold_retries = 2;
  std::vector<std::uint32_t> out;
  const GroupSimplified r0 = run(block.positions, block.indices, once, out);
  const GroupSimplified r2 = run(block.positions, block.indices, retried, out);
  ASSERT_GT(r0.folds.triangles, 0u) << "no fold to retry";
  EXPECT_LE(r2.folds.width_m, r0.folds.width_m);
  EXPECT_GT(r2.index_count, 0u);
  EXPECT_LE(double(r2.index_count), retried.stuck_ratio * double(block.indices.size()));
  expect_own_vertices(out, r2.index_count, block.positions.size() / 3);
  std::printf("city block as one group: %zu folded, widest %.3f m without retries; %zu, %.3f m with 2\n",
              r0.folds.triangles, r0.folds.width_m, r2.folds.triangles, r2.folds.width_m);
}

}  // namespace
}  // namespace gazelod::bake
