// SPDX-License-Identifier: Apache-2.0
// ClusterCover (apps/gazelod/clusters/cover.hpp) on hierarchies bake builds: the groups it
// derives from record equality are the build's own groups, every threshold cut covers every
// leaf exactly once with the cover a reference computes on the build's group links, broken cuts
// are caught, and records that loop are refused.
#include "apps/gazelod/clusters/cover.hpp"

#include "bake/cluster/cluster_build.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace gazelod::cli {
namespace {

bake::ClusterBuildResult wavy_wall() {
  const bake::testing::TestMesh wall = bake::testing::grid(48, 4.0, 0.2);  // 4608 triangles
  bake::ClusterBuildOptions options;
  options.threads = 1;
  return bake::build_cluster_hierarchy(wall.positions, wall.indices, options);
}

std::vector<std::uint8_t> cut_at(const lod::ClusterHierarchy& h, float t) {
  std::vector<std::uint8_t> drawn(h.size(), 0);
  for (std::size_t c = 0; c < h.size(); ++c) drawn[c] = h.self_error_m[c] <= t && t < h.parent_error_m[c];
  return drawn;
}

// The coarsest drawn cluster over each leaf, on the build's own group links (not records).
std::vector<LeafCover> reference_covers(const bake::ClusterBuildResult& r, std::span<const std::uint8_t> drawn) {
  std::map<std::int32_t, std::vector<std::uint32_t>> outputs;
  for (std::uint32_t c = 0; c < r.hierarchy.size(); ++c)
    if (r.source_group[c] >= 0) outputs[r.source_group[c]].push_back(c);
  std::map<std::uint32_t, LeafCover> memo;
  const auto coarser = [](const LeafCover& a, const LeafCover& b) {
    if (a.self_error_m != b.self_error_m) return a.self_error_m > b.self_error_m ? a : b;
    return a.cluster <= b.cluster ? a : b;
  };
  std::function<LeafCover(std::uint32_t)> up = [&](std::uint32_t c) {
    if (auto it = memo.find(c); it != memo.end()) return it->second;
    LeafCover best;
    if (r.parent_group[c] >= 0)
      for (std::uint32_t o : outputs[r.parent_group[c]]) best = coarser(best, up(o));
    if (drawn[c]) best = coarser(best, LeafCover{c, r.hierarchy.self_error_m[c]});
    return memo[c] = best;
  };
  std::vector<LeafCover> out;
  for (std::uint32_t c = 0; c < r.hierarchy.size(); ++c)
    if (r.hierarchy.depth[c] == 0) out.push_back(up(c));
  return out;
}

TEST(ClusterCover, DerivesTheBuildsGroupsFromTheRecords) {
  const bake::ClusterBuildResult r = wavy_wall();
  ASSERT_GT(r.levels, 2u);
  const ClusterCover cover(r.hierarchy);
  EXPECT_EQ(cover.cluster_count(), r.hierarchy.size());
  EXPECT_EQ(cover.group_count(), r.groups);
  std::size_t leaves = 0;
  for (std::uint8_t d : r.hierarchy.depth) leaves += d == 0;
  EXPECT_EQ(cover.leaves().size(), leaves);
  // One to one: the same derived group exactly when the same build group.
  std::map<std::int32_t, std::int32_t> derived_of_build, build_of_derived;
  for (std::uint32_t c = 0; c < r.hierarchy.size(); ++c) {
    const std::int32_t built = r.parent_group[c], derived = cover.parent_group(c);
    ASSERT_EQ(built < 0, derived < 0) << "cluster " << c;
    if (built < 0) continue;
    EXPECT_EQ(derived_of_build.try_emplace(built, derived).first->second, derived) << "cluster " << c;
    EXPECT_EQ(build_of_derived.try_emplace(derived, built).first->second, built) << "cluster " << c;
  }
}

TEST(ClusterCover, EveryThresholdCutCoversEachLeafOnceAsTheReferenceSays) {
  const bake::ClusterBuildResult r = wavy_wall();
  ClusterCover cover(r.hierarchy);
  std::set<float> errors{0.0f, std::numeric_limits<float>::max()};
  for (std::size_t c = 0; c < r.hierarchy.size(); ++c) errors.insert(r.hierarchy.self_error_m[c]);
  std::vector<LeafCover> covers(cover.leaves().size()), previous;
  for (const float t : errors) {
    SCOPED_TRACE("cut at " + std::to_string(t));
    const std::vector<std::uint8_t> drawn = cut_at(r.hierarchy, t);
    ASSERT_EQ(cover.evaluate(drawn, covers), 0u);
    const std::vector<LeafCover> expected = reference_covers(r, drawn);
    for (std::size_t k = 0; k < covers.size(); ++k) {
      ASSERT_NE(covers[k].cluster, kNoCluster) << "leaf " << k;
      EXPECT_EQ(covers[k].cluster, expected[k].cluster) << "leaf " << k;
      EXPECT_TRUE(drawn[covers[k].cluster]);
      EXPECT_LE(covers[k].self_error_m, t);
      // A coarser threshold never gives a leaf a finer cover.
      if (!previous.empty()) {
        EXPECT_GE(covers[k].self_error_m, previous[k].self_error_m) << "leaf " << k;
      }
    }
    previous = covers;
  }
  // The finest cut: every leaf is its own cover, at error 0.
  cover.evaluate(cut_at(r.hierarchy, 0.0f), covers);
  for (std::size_t k = 0; k < covers.size(); ++k) EXPECT_EQ(covers[k].cluster, cover.leaves()[k]);
}

TEST(ClusterCover, CracksAndOverlapsAreCounted) {
  const bake::ClusterBuildResult r = wavy_wall();
  ClusterCover cover(r.hierarchy);
  std::vector<LeafCover> covers(cover.leaves().size());
  // A crack: one leaf of the finest cut left out.
  std::vector<std::uint8_t> drawn = cut_at(r.hierarchy, 0.0f);
  drawn[cover.leaves()[3]] = 0;
  EXPECT_GE(cover.evaluate(drawn, covers), 1u);
  EXPECT_EQ(covers[3].cluster, kNoCluster);
  // An overlap: the finest cut plus one cluster of depth 1 over some of the leaves.
  drawn = cut_at(r.hierarchy, 0.0f);
  const auto d1 = std::find(r.hierarchy.depth.begin(), r.hierarchy.depth.end(), 1);
  ASSERT_NE(d1, r.hierarchy.depth.end());
  drawn[static_cast<std::size_t>(d1 - r.hierarchy.depth.begin())] = 1;
  EXPECT_GE(cover.evaluate(drawn, covers), 2u) << "every leaf of the group below it is covered twice";
  // Wrong lengths: nothing is evaluated.
  EXPECT_EQ(cover.evaluate(std::span(drawn).first(drawn.size() - 1), covers), covers.size());
}

TEST(ClusterCover, RecordsThatLoopAreRefused) {
  // Two depth-1 clusters, each produced by the group the other was merged into.
  lod::ClusterHierarchy h;
  const auto add = [&](float self_r, float self_e, float parent_r, float parent_e) {
    for (auto* v : {&h.self_center_x_m, &h.self_center_y_m, &h.self_center_z_m, &h.parent_center_x_m,
                    &h.parent_center_y_m, &h.parent_center_z_m})
      v->push_back(0.0f);
    h.self_radius_m.push_back(self_r), h.self_error_m.push_back(self_e);
    h.parent_radius_m.push_back(parent_r), h.parent_error_m.push_back(parent_e);
    h.first_index.push_back(0), h.index_count.push_back(3), h.depth.push_back(1);
  };
  add(1.0f, 0.1f, 2.0f, 0.2f);
  add(2.0f, 0.2f, 1.0f, 0.1f);
  EXPECT_THROW(ClusterCover{h}, std::invalid_argument);
  h.depth.pop_back();
  EXPECT_THROW(ClusterCover{h}, std::invalid_argument);
}

}  // namespace
}  // namespace gazelod::cli
