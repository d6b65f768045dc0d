// SPDX-License-Identifier: Apache-2.0
// ns per cluster for select_clusters (lod/cluster/cluster_select.hpp) at 10k..1M clusters, beside
// select_lods per object at the same count in the same run (the baseline: bench/lod's scene,
// chains of 4 levels, a quarter of the objects moving).
// Clusters: terrain tiles around the viewer, each a quadtree hierarchy (a leaf cluster per
// 0.5 m grid cell, each node's sphere enclosing its four children, errors doubling per level),
// a quarter of the tiles moving; the viewer walks, turns its head at 60 deg/s and pursues a
// little (bench/lod's viewer). dense 0: errors of 4 mm at the first level (the cut at 0.04 % of
// the clusters at 1M); dense 1: errors 100 times larger, so that far more of each tile is
// visible (the cut at 9 %) and far fewer records are decided by size alone (the screen);
// mode 0: the frame's selection over every cluster's own two records (the set without its
// distinct records); 1: also the three per-criterion cuts, every record fully evaluated but
// those of error 0 or +inf; 2: mode 1 over the store's distinct records, each evaluated once
// (ClusterDecisions::record_flags); 3: mode 0 over the distinct records (what the plugin runs).
// Counters: records = distinct records; ns_per_cluster (or ns_per_object) = this
// thread's CPU time / (iterations x count); ratio_vs_select_lods = ns_per_cluster /
// ns_per_object at the same count (run first); drawn_pct = clusters in the cut;
// visible_parent_pct = clusters whose parent error is visible (about the share of records
// the size screen cannot decide).
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/select.hpp"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

Viewer viewer() {  // as bench/lod/bench_select.cpp
  Viewer vw;
  vw.eye_position_m = {0.0, 1.6, 0.0};
  vw.eye_velocity_m_s = {0.0, 0.0, -1.4};
  vw.gaze_direction = glm::normalize(glm::dvec3{0.2, -0.1, -1.0});
  vw.head_angular_velocity_rad_s = {0.0, 60.0 * M_PI / 180, 0.0};
  vw.gaze_angular_velocity_in_head_rad_s = {0.0, -0.2, 0.0};
  vw.xi_cpd = 10.75;  // Quest 3
  vw.tracker_error_deg = 1.5;
  return vw;
}

// A quadtree over 2^levels x 2^levels cells of cell_m in the tile's x-z plane, one cluster per
// node (a group of four simplified into one), leaves first.
ClusterHierarchy quadtree_tile(int levels, double cell_m, double error_scale) {
  struct Node {
    double x, y, z, r, e;
  };
  std::vector<std::vector<Node>> by_level;
  const int side = 1 << levels;
  std::vector<Node> leaves;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      leaves.push_back(
          {(i + 0.5) * cell_m, 0.05 * std::sin(i * 0.3) * std::cos(j * 0.2), (j + 0.5) * cell_m, 0.75 * cell_m, 0.0});
  by_level.push_back(leaves);
  for (int k = 1, n = side / 2; k <= levels; ++k, n /= 2) {
    const std::vector<Node>& below = by_level.back();
    std::vector<Node> up;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        Node p{0, 0, 0, 0, error_scale * 0.004 * cell_m * std::pow(2.0, k)};
        const int kids[4] = {(2 * i) * 2 * n + 2 * j, (2 * i) * 2 * n + 2 * j + 1, (2 * i + 1) * 2 * n + 2 * j,
                             (2 * i + 1) * 2 * n + 2 * j + 1};
        for (int c : kids) p.x += below[c].x / 4, p.y += below[c].y / 4, p.z += below[c].z / 4;
        for (int c : kids)
          p.r = std::max(p.r, std::hypot(below[c].x - p.x, below[c].y - p.y, below[c].z - p.z) + below[c].r);
        p.r *= 1.0001;  // float rounding must not break containment
        up.push_back(p);
      }
    by_level.push_back(up);
  }
  ClusterHierarchy h;
  for (int k = 0; k <= levels; ++k) {
    const int n = side >> k;
    for (int idx = 0; idx < n * n; ++idx) {
      const Node& self = by_level[k][idx];
      const bool top = k == levels;
      const Node& par = top ? self : by_level[k + 1][(idx / n / 2) * (n / 2) + (idx % n) / 2];
      h.self_center_x_m.push_back(float(self.x)), h.self_center_y_m.push_back(float(self.y));
      h.self_center_z_m.push_back(float(self.z)), h.self_radius_m.push_back(float(self.r));
      h.self_error_m.push_back(float(self.e));
      h.parent_center_x_m.push_back(float(par.x)), h.parent_center_y_m.push_back(float(par.y));
      h.parent_center_z_m.push_back(float(par.z)), h.parent_radius_m.push_back(float(par.r));
      h.parent_error_m.push_back(top ? kNoParentError : float(par.e));
      h.first_index.push_back(0), h.index_count.push_back(0);
      h.depth.push_back(static_cast<std::uint8_t>(k));
    }
  }
  return h;
}

// Tiles of the largest quadtree that gives at least four, until about n clusters.
const ClusterStore& cluster_scene(std::size_t n, bool dense = false) {
  static std::map<std::pair<std::size_t, bool>, std::unique_ptr<ClusterStore>> cache;
  if (auto it = cache.find({n, dense}); it != cache.end()) return *it->second;
  int levels = 1;
  const auto tree = [](int l) { return ((std::size_t{1} << (2 * l + 2)) - 1) / 3; };
  while (tree(levels + 1) * 4 <= n) ++levels;
  const ClusterHierarchy tile = quadtree_tile(levels, 0.5, dense ? 100.0 : 1.0);
  const std::size_t tiles = std::max<std::size_t>(1, (n + tree(levels) / 2) / tree(levels));
  const double tile_m = 0.5 * (1 << levels);
  const int per_row = static_cast<int>(std::ceil(std::sqrt(double(tiles))));
  auto store = std::make_unique<ClusterStore>();
  store->reserve(tiles, tiles * tile.size());
  for (std::size_t t = 0; t < tiles; ++t) {
    InstanceTransform xf;
    xf.translation_m = {(int(t) % per_row - per_row / 2.0) * tile_m, 0.0, (int(t) / per_row - per_row / 2.0) * tile_m};
    const glm::dvec3 vel = t % 4 == 1 ? glm::dvec3{0.5, 0.0, -1.0} : glm::dvec3{0.0};
    store->add_mesh(tile, xf, vel, 0);
  }
  return *cache.emplace(std::make_pair(n, dense), std::move(store)).first->second;
}

std::vector<LodLevel> chain(int variant) {  // bench/lod's chains
  if (variant % 2)
    return {{3928, 0, DetailKind::removed_cycles_per_diameter, 0.0},
            {834, 0, DetailKind::removed_cycles_per_diameter, 400.0},
            {254, 0, DetailKind::removed_cycles_per_diameter, 120.0},
            {76, 0, DetailKind::removed_cycles_per_diameter, 30.0}};
  return {{1000, 0, DetailKind::geometric_error_m, 0.0},
          {300, 0, DetailKind::geometric_error_m, 0.002},
          {80, 0, DetailKind::geometric_error_m, 0.01},
          {20, 0, DetailKind::geometric_error_m, 0.05}};
}

const ObjectStore& object_scene(std::size_t n) {  // bench/lod's scene
  static std::map<std::size_t, std::unique_ptr<ObjectStore>> cache;
  if (auto it = cache.find(n); it != cache.end()) return *it->second;
  auto s = std::make_unique<ObjectStore>();
  std::mt19937_64 rng(n);
  std::uniform_real_distribution<double> u(-1, 1);
  s->reserve(n, 4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 c{u(rng) * 100, u(rng) * 10 + 1.6, u(rng) * 100};
    const double r = std::pow(10.0, u(rng) - 0.5);
    const glm::dvec3 v = (i % 4 == 0) ? glm::dvec3{u(rng) * 3, 0, u(rng) * 3} : glm::dvec3{0.0};
    s->add(c, r, v, chain(static_cast<int>(i)));
  }
  return *cache.emplace(n, std::move(s)).first->second;
}

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

std::map<std::size_t, double>& object_ns() {  // filled by BM_SelectLodsBaseline
  static std::map<std::size_t, double> m;
  return m;
}

void BM_SelectLodsBaseline(benchmark::State& state) {
  const std::size_t target = static_cast<std::size_t>(state.range(0));
  const std::size_t n = cluster_scene(target).size();  // the same count as the clusters
  const ObjectSet os = object_scene(n).view();
  std::vector<std::uint8_t> lod(n), why(n), s(n), e(n), v(n);
  const Decisions out{lod, why, s, e, v, {}, {}, {}};
  const Viewer vw = viewer();
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    benchmark::DoNotOptimize(select_lods(vw, os, out));
    benchmark::ClobberMemory();
  }
  const double ns = (thread_cpu_ns() - t0) / (double(state.iterations()) * double(n));
  object_ns()[target] = ns;
  state.counters["objects"] = double(n);
  state.counters["ns_per_object"] = ns;
}

void BM_SelectClusters(benchmark::State& state) {
  const std::size_t target = static_cast<std::size_t>(state.range(0));
  const bool dense = state.range(1) != 0, per_criterion = state.range(2) == 1 || state.range(2) == 2,
             by_record = state.range(2) >= 2;  // the modes above
  ClusterSet cs = cluster_scene(target, dense).view();
  const std::size_t n = cs.size(), records = cs.record_count();
  std::vector<std::uint8_t> drawn(n), why(n), s(n), e(n), v(n);
  std::vector<std::uint32_t> flags(records);
  ClusterDecisions out{drawn, why, {}, {}, {}, {}};
  if (per_criterion) out.drawn_size_only = s, out.drawn_eccentricity_only = e, out.drawn_velocity_only = v;
  if (by_record) out.record_flags = flags;
  if (!by_record) {  // the set without its distinct records: every cluster's own two
    cs.record_center_x_m = {}, cs.record_center_y_m = {}, cs.record_center_z_m = {}, cs.record_radius_m = {};
    cs.record_error_m = {}, cs.self_record = {}, cs.parent_record = {};
    cs.mesh_first_record = {}, cs.mesh_record_count = {};
  }
  const Viewer vw = viewer();
  if (const std::string err = validate_clusters(cs); !err.empty()) state.SkipWithError(err.c_str());
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    benchmark::DoNotOptimize(select_clusters(vw, cs, out));
    benchmark::ClobberMemory();
  }
  const double ns = (thread_cpu_ns() - t0) / (double(state.iterations()) * double(n));
  std::size_t in_cut = 0, parent_visible = 0;
  for (auto d : drawn) in_cut += d;
  std::vector<std::uint8_t> bits(n);
  if (const std::string err = select_clusters(vw, cs, {drawn, why, {}, {}, {}, bits}); !err.empty())
    state.SkipWithError(err.c_str());
  for (auto b : bits) parent_visible += (b & 2) == 0;
  state.counters["clusters"] = double(n);
  state.counters["records"] = double(records);
  state.counters["visible_parent_pct"] = 100.0 * double(parent_visible) / double(n);
  state.counters["ns_per_cluster"] = ns;
  if (auto it = object_ns().find(target); it != object_ns().end())
    state.counters["ratio_vs_select_lods"] = ns / it->second;
  state.counters["drawn_pct"] = 100.0 * double(in_cut) / double(n);
}

BENCHMARK(BM_SelectLodsBaseline)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SelectClusters)
    ->Args({10000, 0, 0})
    ->Args({100000, 0, 0})
    ->Args({1000000, 0, 0})
    ->Args({1000000, 1, 0})
    ->Args({1000000, 0, 1})
    ->Args({1000000, 0, 2})
    ->Args({10000, 0, 3})
    ->Args({100000, 0, 3})
    ->Args({1000000, 0, 3})
    ->Args({1000000, 1, 3})
    ->ArgNames({"clusters", "dense", "mode"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gazelod::lod

BENCHMARK_MAIN();
