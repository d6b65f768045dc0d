// SPDX-License-Identifier: Apache-2.0
// build_cluster_hierarchy (bake/cluster/cluster_build.hpp): the hierarchy's invariants on a closed
// sphere, an open grid and separate pieces; stored errors against the true distance from the
// source; the nearest-triangle grid and the splitter it uses; small, empty and degenerate input;
// bad input.
#include "bake/bake_error.hpp"
#include "bake/city_mesh.hpp"
#include "bake/cluster/cluster_build.hpp"
#include "bake/cluster_distance.hpp"
#include "bake/cluster_flips.hpp"
#include "bake/cluster/cluster_split.hpp"
#include "bake/terrain_mesh.hpp"
#include "tests/bake/cluster_invariants.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <map>
#include <cstdio>
#include <limits>
#include <random>

namespace gazelod::bake {
namespace {

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

std::string build_error(const testing::TestMesh& m, const ClusterBuildOptions& o = {}) {
  try {
    build_cluster_hierarchy(m.positions, m.indices, o);
  } catch (const BakeError& e) {
    return e.what();
  }
  return "";
}

std::size_t top_triangles(const ClusterBuildResult& r) {
  const std::size_t n = testing::cut(r, std::numeric_limits<float>::max()).size() / 3;
  std::printf("  %zu source triangles -> %zu clusters, %zu groups, %u levels, top %zu triangles\n", r.source_triangles,
              r.hierarchy.size(), r.groups, r.levels, n);
  return n;
}

TEST(ClusterBuild, ClosedSphereStaysClosedAtEveryCut) {
  const testing::TestMesh m = testing::icosphere(5, 0.5);  // 20480 triangles
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices);
  ASSERT_TRUE(testing::open_edges(m.positions, m.indices).empty());
  testing::expect_hierarchy_invariants(r, m.positions, m.indices);
  EXPECT_GE(r.levels, 5u);
  EXPECT_GT(r.groups, 20u);
  EXPECT_LT(top_triangles(r), m.triangles() / 20) << "the top is coarse";
  // Errors grow with depth and stay below the sphere's size.
  for (std::size_t c = 0; c < r.hierarchy.size(); ++c)
    if (r.hierarchy.parent_error_m[c] != lod::kNoParentError) {
      EXPECT_LT(r.hierarchy.parent_error_m[c], 0.5f);
    }
}

// The grid's rim meets nothing: it is simplified along itself like the rest (meshopt 0.18's
// LockBorder would keep all 320 rim edges at every level), while what two groups share stays.
TEST(ClusterBuild, OpenGridSimplifiesItsRimWithoutCrack) {
  const testing::TestMesh m = testing::grid(80, 2.0, 0.2);  // 12800 triangles
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices);
  const std::size_t rim = testing::open_edges(m.positions, m.indices).size();
  EXPECT_EQ(rim, 320u);
  testing::expect_hierarchy_invariants(r, m.positions, m.indices);
  EXPECT_GE(r.levels, 4u);
  EXPECT_LT(top_triangles(r), m.triangles() / 8);
  const std::size_t top_rim = testing::open_edges(m.positions, testing::cut(r, FLT_MAX)).size();
  EXPECT_LT(top_rim, rim / 4) << "the top's rim is simplified too";
  EXPECT_GE(top_rim, 4u);
}

// --lock-borders, or every rim vertex flagged as meeting another primitive: the rim stays
// vertex for vertex at every cut (expect_hierarchy_invariants checks it exactly then).
TEST(ClusterBuild, LockedRimStaysAtEveryCut) {
  const testing::TestMesh m = testing::grid(80, 2.0, 0.2);
  const testing::OpenEdges rim = testing::open_edges(m.positions, m.indices);
  ClusterBuildOptions all;
  all.lock_open_borders = true;
  std::vector<std::uint8_t> flags(m.positions.size() / 3, 0);
  for (const auto& [e, count] : rim) flags[e.first] = flags[e.second] = 1;  // grid() has no duplicates
  ClusterBuildOptions flagged;
  flagged.locked_vertices = flags;
  for (const ClusterBuildOptions* o : {&all, &flagged}) {
    SCOPED_TRACE(o == &all ? "lock_open_borders" : "locked_vertices");
    const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices, *o);
    testing::expect_hierarchy_invariants(r, m.positions, m.indices, *o);
    EXPECT_TRUE(testing::open_edges(m.positions, testing::cut(r, FLT_MAX)) == rim);
    EXPECT_GE(r.levels, 3u);
  }
}

// A triangle facing against the surface it replaces is a fold; the same triangles are not.
TEST(ClusterBuild, FoldsAreTrianglesFacingAgainstTheirCorners) {
  const testing::TestMesh m = testing::grid(4, 1.0, 0.0);  // flat, 32 triangles
  std::vector<float> normals;
  EXPECT_EQ(find_folds(m.positions, m.indices, m.indices, normals).triangles, 0u);
  std::vector<std::uint32_t> turned = m.indices;
  std::swap(turned[1], turned[2]);    // triangle 0 turned over
  std::swap(turned[10], turned[11]);  // and triangle 3
  const Folds two = find_folds(m.positions, m.indices, turned, normals);
  EXPECT_EQ(two.triangles, 2u);
  EXPECT_NEAR(two.width_m, 0.25 / std::sqrt(2.0), 1e-6);  // half a 0.25 m quad: 2 * area / diagonal
  // A big triangle over the grid's corners faces the same way as the grid: no fold.
  const std::vector<std::uint32_t> big{m.indices[0], m.indices[1], m.indices[2]};
  EXPECT_EQ(find_folds(m.positions, m.indices, big, normals).width_m, 0.0);
  // The build counts what meshopt folds, per group, and each group's error covers its folds
  // (a generated terrain, where meshopt 0.18 folds some).
  TerrainOptions terrain;
  terrain.triangles = 20'000;
  const GeneratedMesh wavy = terrain_meshes(terrain).at(0);
  const ClusterBuildResult r = build_cluster_hierarchy(wavy.positions, wavy.indices);
  EXPECT_GT(r.folded_triangles, 0u) << "no fold to check the errors against";
  std::map<std::int32_t, std::vector<std::uint32_t>> members, products;
  for (std::uint32_t c = 0; c < r.hierarchy.size(); ++c) {
    if (r.parent_group[c] >= 0) members[r.parent_group[c]].push_back(c);
    if (r.source_group[c] >= 0) products[r.source_group[c]].push_back(c);
  }
  std::size_t folds = 0;
  for (const auto& [g, in] : members) {
    const Folds f =
        find_folds(wavy.positions, testing::triangles_of(r, in), testing::triangles_of(r, products[g]), normals);
    folds += f.triangles;
    EXPECT_GE(double(r.hierarchy.parent_error_m[in[0]]), f.width_m) << "group " << g;
  }
  EXPECT_EQ(r.folded_triangles, folds);
}

// Retrying a folded group with its folds' surroundings locked (ClusterBuildOptions::
// fold_retries, lock_around_folds) leaves fewer folds and narrower ones, and a valid hierarchy.
// One generated city block: panelled walls, where meshopt 0.18 folds most.
TEST(ClusterBuild, FoldRetriesLeaveFewerAndNarrowerFolds) {
  CityOptions city;
  city.triangles = 10'000;
  const GeneratedMesh block = city_meshes(city).at(0);
  ClusterBuildOptions once, retried;
  once.fold_retries = 0;
  retried.fold_retries = 2;
  const ClusterBuildResult r0 = build_cluster_hierarchy(block.positions, block.indices, once);
  const ClusterBuildResult r2 = build_cluster_hierarchy(block.positions, block.indices, retried);
  testing::expect_hierarchy_invariants(r2, block.positions, block.indices, retried);
  ASSERT_GT(r0.folded_triangles, 0u) << "no fold to retry";
  EXPECT_LT(r2.folded_triangles, r0.folded_triangles);
  // The widest fold of any group (what a fold adds to a group's error).
  const auto widest_fold = [&](const ClusterBuildResult& r) {
    std::map<std::int32_t, std::vector<std::uint32_t>> members, products;
    for (std::uint32_t c = 0; c < r.hierarchy.size(); ++c) {
      if (r.parent_group[c] >= 0) members[r.parent_group[c]].push_back(c);
      if (r.source_group[c] >= 0) products[r.source_group[c]].push_back(c);
    }
    std::vector<float> normals;
    double widest_m = 0.0;
    for (const auto& [g, in] : members)
      widest_m = std::max(widest_m, find_folds(block.positions, testing::triangles_of(r, in),
                                               testing::triangles_of(r, products[g]), normals)
                                        .width_m);
    return widest_m;
  };
  EXPECT_LE(widest_fold(r2), widest_fold(r0));
  std::printf("city block %zu triangles: folded %zu without retries, %zu with 2; widest fold %.3f / %.3f m\n",
              block.triangles(), r0.folded_triangles, r2.folded_triangles, widest_fold(r0), widest_fold(r2));
  ClusterBuildOptions bad;
  bad.fold_retries = kMaxFoldRetries + 1;
  EXPECT_NE(validate_cluster_options(bad).find("fold retries"), std::string::npos);
}

TEST(ClusterBuild, SeparatePiecesAreGroupedByPlace) {
  // 27 spheres of 320 triangles, none touching: no cluster has a neighbour across pieces.
  testing::TestMesh m;
  const testing::TestMesh s = testing::icosphere(2, 0.1);
  for (int i = 0; i < 27; ++i) {
    const auto base = static_cast<std::uint32_t>(m.positions.size() / 3);
    for (std::size_t k = 0; k < s.positions.size(); k += 3)
      m.positions.insert(m.positions.end(), {s.positions[k] + float(i % 3), s.positions[k + 1] + float(i / 3 % 3),
                                             s.positions[k + 2] + float(i / 9)});
    for (std::uint32_t v : s.indices) m.indices.push_back(base + v);
  }
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices);
  testing::expect_hierarchy_invariants(r, m.positions, m.indices);
  EXPECT_LT(top_triangles(r), m.triangles() / 4);
}

// Largest distance from a source vertex to the triangles, by brute force.
double max_source_distance(std::span<const float> pos, std::span<const std::uint32_t> tris) {
  double worst = 0.0;
  for (std::size_t v = 0; v < pos.size() / 3; ++v) {
    const double p[3] = {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]};
    double nearest = INFINITY;
    for (std::size_t t = 0; t < tris.size(); t += 3) {
      double c[9];
      for (int k = 0; k < 9; ++k) c[k] = pos[3 * tris[t + k / 3] + k % 3];
      nearest = std::min(nearest, point_triangle_distance(p, c, c + 3, c + 6));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

TEST(ClusterBuild, StoredErrorBoundsTheDistanceFromTheSource) {
  const testing::TestMesh m = testing::grid(32, 2.0, 0.3);  // a height field, 2048 triangles
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices);
  testing::expect_hierarchy_invariants(r, m.positions, m.indices);
  ASSERT_GE(r.groups, 4u);
  // Every cut the hierarchy has: at no error, at each group's error and at the top.
  std::vector<float> thresholds{0.0f, std::numeric_limits<float>::max()};
  for (float e : r.hierarchy.parent_error_m)
    if (e != lod::kNoParentError) thresholds.push_back(e);
  std::sort(thresholds.begin(), thresholds.end());
  thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());
  double top_bound_m = 0.0, top_true_m = 0.0;
  for (float t : thresholds) {
    const std::vector<std::uint32_t> drawn = testing::cut(r, t);
    double bound_m = 0.0;
    for (std::size_t c = 0; c < r.hierarchy.size(); ++c)
      if (r.hierarchy.self_error_m[c] <= t && t < r.hierarchy.parent_error_m[c])
        bound_m = std::max(bound_m, double(r.hierarchy.self_error_m[c]));
    const double true_m = max_source_distance(m.positions, drawn);
    EXPECT_LE(true_m, bound_m) << "cut at " << t << ": a source vertex is farther from the drawn surface";
    EXPECT_LE(bound_m, double(t)) << "cut at " << t;
    top_bound_m = bound_m, top_true_m = true_m;
  }
  std::printf("  %zu cuts; top: stored %.5f m, true %.5f m\n", thresholds.size(), top_bound_m, top_true_m);
  // Measured, not summed: the top's bound is the deviation of some source vertex from it.
  EXPECT_GT(top_true_m, 0.5 * top_bound_m);
}

TEST(ClusterBuild, TriangleGridFindsTheNearestTriangle) {
  const testing::TestMesh m = testing::icosphere(2, 1.0);  // 320 triangles
  TriangleGrid grid;
  grid.build(m.positions, m.indices);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.6f, 1.6f);
  for (int i = 0; i < 300; ++i) {
    const float p[3] = {u(rng), u(rng), u(rng)};
    const double pd[3] = {p[0], p[1], p[2]};
    double brute = INFINITY;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      double c[9];
      for (int k = 0; k < 9; ++k) c[k] = m.positions[3 * m.indices[t + k / 3] + k % 3];
      brute = std::min(brute, point_triangle_distance(pd, c, c + 3, c + 6));
    }
    EXPECT_NEAR(grid.nearest(p).distance_m, brute, 1e-9) << i;
    // Good enough: some triangle within the limit, never closer than the nearest.
    const NearestTriangle q = grid.nearest(p, brute + 0.1, static_cast<std::uint32_t>(i % 320));
    EXPECT_LE(q.distance_m, brute + 0.1 + 1e-9);
    EXPECT_GE(q.distance_m, brute - 1e-9);
  }
}

// A search's answers on one grid must not depend on what it answered on another before (the
// bake's threads each reuse one GridSearch for whichever groups they take).
TEST(ClusterBuild, GridSearchAnswersDoNotDependOnEarlierGrids) {
  const testing::TestMesh other = testing::icosphere(2, 1.0), sphere = testing::icosphere(3, 1.0);
  TriangleGrid a, b;
  a.build(other.positions, other.indices);
  b.build(sphere.positions, sphere.indices);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  std::vector<std::array<float, 3>> points(300);
  for (auto& p : points) p = {u(rng), u(rng), u(rng)};
  GridSearch fresh, used;
  for (int i = 0; i < 7; ++i) used.nearest(a, points[i].data());  // 7 answers: not a multiple of 4
  std::size_t same = 0;
  for (const auto& p : points) {
    // Far enough that several of the last answers qualify: which one comes first decides.
    const NearestTriangle x = fresh.nearest(b, p.data(), 0.6), y = used.nearest(b, p.data(), 0.6);
    same += x.triangle == y.triangle && x.distance_m == y.distance_m;
  }
  EXPECT_EQ(same, points.size());
}

TEST(ClusterBuild, SplitterKeepsLimitsAndEveryTriangleOnce) {
  // Full clusters but the last few: a grid's hold about 64 vertices (~90 triangles), a soup's
  // 21 triangles of 3 vertices each.
  const std::pair<testing::TestMesh, std::size_t> cases[] = {{testing::grid(30, 1.0, 0.1), 1800 / 70 + 3},
                                                             {testing::triangle_soup(700), 700 / 21 + 2}};
  for (const auto& [m, max_clusters] : cases) {
    ClusterSplitter splitter;
    std::vector<std::uint32_t> out, counts;
    splitter.split(m.positions, m.positions.size() / 3, m.indices, 64, 124, out, counts);
    ASSERT_EQ(out.size(), m.indices.size());
    std::size_t at = 0;
    for (std::uint32_t k : counts) {
      std::vector<std::uint32_t> v(out.begin() + at, out.begin() + at + k);
      std::sort(v.begin(), v.end());
      EXPECT_LE(k / 3, 124u);
      EXPECT_LE(std::unique(v.begin(), v.end()) - v.begin(), 64);
      at += k;
    }
    std::vector<std::array<std::uint32_t, 3>> a, b;
    for (std::size_t t = 0; t < out.size(); t += 3)
      a.push_back({out[t], out[t + 1], out[t + 2]}), b.push_back({m.indices[t], m.indices[t + 1], m.indices[t + 2]});
    std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
    EXPECT_LE(counts.size(), max_clusters) << m.triangles();
  }
}

TEST(ClusterBuild, SameHierarchyOnAnyThreadCount) {
  const testing::TestMesh m = testing::icosphere(4, 1.0);
  ClusterBuildOptions one, four;
  one.threads = 1, four.threads = 4;
  const ClusterBuildResult a = build_cluster_hierarchy(m.positions, m.indices, one);
  const ClusterBuildResult b = build_cluster_hierarchy(m.positions, m.indices, four);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.hierarchy.parent_error_m, b.hierarchy.parent_error_m);
  EXPECT_EQ(a.hierarchy.self_radius_m, b.hierarchy.self_radius_m);
  EXPECT_EQ(a.parent_group, b.parent_group);
}

// The few-group top levels measure their source vertices in slices (more than 16384 here):
// which thread takes which slice must not matter either.
TEST(ClusterBuild, SameHierarchyOnAnyThreadCountWithSlicedLevels) {
  TerrainOptions t;
  t.triangles = 100'000;
  const GeneratedMesh m = terrain_meshes(t).at(0);  // 50,721 vertices
  ClusterBuildOptions o;
  o.threads = 1;
  const ClusterBuildResult a = build_cluster_hierarchy(m.positions, m.indices, o);
  for (unsigned threads : {2u, 3u}) {
    o.threads = threads;
    const ClusterBuildResult b = build_cluster_hierarchy(m.positions, m.indices, o);
    EXPECT_EQ(a.indices, b.indices) << threads;
    EXPECT_EQ(a.hierarchy.self_error_m, b.hierarchy.self_error_m) << threads;
    EXPECT_EQ(a.hierarchy.parent_error_m, b.hierarchy.parent_error_m) << threads;
    EXPECT_EQ(a.parent_group, b.parent_group) << threads;
  }
  EXPECT_GT(a.phases.sliced_measure_s, 0.0);  // the sliced path ran
}

TEST(ClusterBuild, SmallMeshIsOneCluster) {
  const testing::TestMesh m = testing::icosphere(1, 1.0);  // 80 triangles, 42 vertices
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices);
  ASSERT_EQ(r.hierarchy.size(), 1u);
  EXPECT_EQ(r.levels, 1u);
  EXPECT_EQ(r.groups, 0u);
  EXPECT_EQ(r.hierarchy.index_count[0], m.indices.size());
  EXPECT_EQ(r.hierarchy.self_error_m[0], 0.0f);
  EXPECT_EQ(r.hierarchy.parent_error_m[0], lod::kNoParentError);
  EXPECT_EQ(r.hierarchy.depth[0], 0);
  EXPECT_NEAR(r.hierarchy.self_radius_m[0], 1.0f, 0.2f);
  testing::expect_hierarchy_invariants(r, m.positions, m.indices);

  testing::TestMesh one;
  one.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  one.indices = {0, 1, 2};
  const ClusterBuildResult r1 = build_cluster_hierarchy(one.positions, one.indices);
  ASSERT_EQ(r1.hierarchy.size(), 1u);
  testing::expect_hierarchy_invariants(r1, one.positions, one.indices);
}

TEST(ClusterBuild, DegenerateTrianglesAreDroppedAndCounted) {
  testing::TestMesh m = testing::grid(20, 1.0, 0.1);
  const auto v = static_cast<std::uint32_t>(m.positions.size() / 3);
  m.positions.insert(m.positions.end(), {m.positions[0], m.positions[1], m.positions[2]});  // = vertex 0
  m.indices.insert(m.indices.end(), {0, 0, 1, 5, 6, 5, 0, 1, v, 3, 3, 3});
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices);
  EXPECT_EQ(r.degenerate_triangles, 4u);
  EXPECT_EQ(r.source_triangles, 800u);
  testing::expect_hierarchy_invariants(r, m.positions, m.indices);

  testing::TestMesh all;
  all.positions = {0, 0, 0, 1, 0, 0};
  all.indices = {0, 0, 1, 1, 1, 1};
  const ClusterBuildResult e = build_cluster_hierarchy(all.positions, all.indices);
  EXPECT_EQ(e.hierarchy.size(), 0u);
  EXPECT_EQ(e.levels, 0u);
  EXPECT_EQ(e.degenerate_triangles, 2u);
  EXPECT_TRUE(build_cluster_hierarchy({}, {}).indices.empty());
}

TEST(ClusterBuild, BadInputNamesMeshAndPlace) {
  ClusterBuildOptions o;
  o.label = "mesh 3 'Rock'";
  testing::TestMesh m = testing::grid(2, 1.0, 0.0);  // 9 vertices, 8 triangles
  m.positions[3 * 5 + 1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_HAS(build_error(m, o), "mesh 3 'Rock': vertex 5 position (");
  EXPECT_HAS(build_error(m, o), ") is not finite");
  m.positions[3 * 5 + 1] = 0.0f;
  m.positions[3 * 7] = std::numeric_limits<float>::infinity();
  EXPECT_HAS(build_error(m, o), "mesh 3 'Rock': vertex 7 position (inf, ");
  m.positions[3 * 7] = 0.0f;
  m.indices[4] = 99;
  EXPECT_HAS(build_error(m, o), "mesh 3 'Rock': index 4 is 99, but there are only 9 vertices");
  m.indices[4] = 1;
  m.indices.push_back(0);
  EXPECT_HAS(build_error(m, o), "mesh 3 'Rock': 25 indices is not a whole number of triangles");
  m.indices.pop_back();
  EXPECT_EQ(build_error(m, o), "");
  const std::vector<std::uint8_t> flags(8, 1);
  o.locked_vertices = flags;
  EXPECT_HAS(build_error(m, o), "mesh 3 'Rock': 8 locked-vertex flags for 9 vertices");
  o.locked_vertices = {};
  o.max_triangles = 126;
  EXPECT_HAS(build_error(m, o), "max triangles per cluster must be a multiple of 4 in [4, 512], got 126");
  o.max_triangles = 124, o.max_vertices = 256;
  EXPECT_HAS(build_error(m, o), "max vertices per cluster must be in [3, 255], got 256");
  o.max_vertices = 64, o.simplify_ratio = 1.0;
  EXPECT_HAS(build_error(m, o), "simplify ratio must be in (0, 1), got 1");
  o.simplify_ratio = 0.5, o.group_size = 1;
  EXPECT_HAS(build_error(m, o), "clusters per group must be in [2, 64], got 1");
}

}  // namespace
}  // namespace gazelod::bake
