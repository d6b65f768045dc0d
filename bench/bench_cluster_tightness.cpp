// SPDX-License-Identifier: Apache-2.0
// How tight the cluster hierarchy's errors are (bake/cluster/cluster_build.hpp), on the generated terrain
// of `gazelod scene generate terrain` (bake/terrain_mesh.hpp, default options: 1,002,528
// triangles, +Y up). For each level of the plain simplification chain (bake/simplify_chain.hpp)
// the uniform cut of the hierarchy at the chain's error t (clusters with self error <= t <
// parent error) is compared with the chain's level:
//   chain_tri, cut_tri      triangles, and their share of the source;
//   chain_true, cut_true    the TRUE error: the largest distance from a source vertex to the
//                           drawn triangles (the measure cluster_build.hpp bounds);
//   cut_vert                the largest vertical distance, over the source's grid points,
//                           between the source height and the drawn surface above them (on a
//                           height field it bounds the distance to the surface from above);
//   cut_bound               the largest stored self error among the cut's clusters (<= t);
//   ok                      cut_true <= cut_bound, i.e. the stored error is a true bound;
//   vert_cut_tri            triangles of the cut when every group's error is the vertical error
//                           of its clusters (made monotone up the hierarchy): the slack's cost.
// Rows: t = each chain level's meshopt error, then t = each chain level's true error. Then per
// depth: clusters, triangles, the mean stored self error and the mean vertical error.
// Usage: bench_cluster_tightness [triangles] [threads]   (defaults 1000000, 2)
#include "bake/cluster/cluster_build.hpp"
#include "bake/cluster_distance.hpp"
#include "bake/simplify_chain.hpp"
#include "bake/terrain_mesh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace gazelod::bake {
namespace {

// Vertex ids of the terrain are grid points: v = j * (n + 1) + i.
struct HeightField {
  std::uint32_t n = 0;  // quads per side
  const std::vector<float>* pos = nullptr;

  double height(std::uint32_t v) const { return (*pos)[3 * v + 1]; }
  // Largest vertical distance at grid points covered by the triangles (one triangle list).
  double max_error(const std::uint32_t* tris, std::size_t index_count) const {
    double worst = 0.0;
    const std::int64_t side = n + 1;
    for (std::size_t t = 0; t + 2 < index_count; t += 3) {
      std::int64_t gi[3], gj[3];
      double y[3];
      for (int k = 0; k < 3; ++k) gi[k] = tris[t + k] % side, gj[k] = tris[t + k] / side, y[k] = height(tris[t + k]);
      const std::int64_t area = (gi[1] - gi[0]) * (gj[2] - gj[0]) - (gi[2] - gi[0]) * (gj[1] - gj[0]);
      if (area == 0) continue;
      const std::int64_t i0 = std::min({gi[0], gi[1], gi[2]}), i1 = std::max({gi[0], gi[1], gi[2]});
      const std::int64_t j0 = std::min({gj[0], gj[1], gj[2]}), j1 = std::max({gj[0], gj[1], gj[2]});
      for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t i = i0; i <= i1; ++i) {
          std::int64_t w[3];
          for (int k = 0; k < 3; ++k) {
            const int a = (k + 1) % 3, b = (k + 2) % 3;
            w[k] = (gi[b] - gi[a]) * (j - gj[a]) - (i - gi[a]) * (gj[b] - gj[a]);
          }
          const bool inside = area > 0 ? (w[0] >= 0 && w[1] >= 0 && w[2] >= 0) : (w[0] <= 0 && w[1] <= 0 && w[2] <= 0);
          if (!inside) continue;
          const double h = (double(w[0]) * y[0] + double(w[1]) * y[1] + double(w[2]) * y[2]) / double(area);
          worst = std::max(worst, std::abs(h - height(static_cast<std::uint32_t>(j * side + i))));
        }
    }
    return worst;
  }
};

// Largest distance from a source vertex to the triangles (a triangle list).
double surface_error(const std::vector<float>& pos, const std::vector<std::uint32_t>& tris) {
  TriangleGrid grid;
  grid.build(pos, tris);
  double worst = 0.0;
  for (std::size_t v = 0; v < pos.size() / 3; ++v) worst = std::max(worst, grid.nearest(&pos[3 * v]).distance_m);
  return worst;
}

struct CutStats {
  std::size_t triangles = 0;
  double true_m = 0.0, bound_m = 0.0;
  std::vector<std::uint32_t> indices;
};

CutStats cut_stats(const ClusterBuildResult& r, const std::vector<double>& self_m, const std::vector<double>& parent_m,
                   const std::vector<double>& true_m, double t) {
  CutStats s;
  const lod::ClusterHierarchy& h = r.hierarchy;
  for (std::size_t c = 0; c < h.size(); ++c)
    if (self_m[c] <= t && t < parent_m[c]) {
      s.triangles += h.index_count[c] / 3;
      s.indices.insert(s.indices.end(), r.indices.begin() + h.first_index[c],
                       r.indices.begin() + h.first_index[c] + h.index_count[c]);
      s.true_m = std::max(s.true_m, true_m[c]);
      s.bound_m = std::max(s.bound_m, self_m[c]);
    }
  return s;
}

int run(std::uint64_t triangles, unsigned threads) {
  TerrainOptions to;
  to.triangles = triangles;
  const std::vector<GeneratedMesh> meshes = terrain_meshes(to);
  const GeneratedMesh& m = meshes.at(0);
  const HeightField field{terrain_quads_per_side(to), &m.positions};
  const double source = static_cast<double>(m.triangles());
  std::printf("terrain: %zu triangles, %u quads per side\n", m.triangles(), field.n);

  const PrimitiveChain chain = simplify_chain(m.positions, m.indices, ChainOptions{});
  ClusterBuildOptions o;
  o.threads = threads;
  const auto t0 = std::chrono::steady_clock::now();
  const ClusterBuildResult r = build_cluster_hierarchy(m.positions, m.indices, o);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const lod::ClusterHierarchy& h = r.hierarchy;
  std::printf("hierarchy: %zu clusters, %zu groups, %u levels, build %.3f s (%u threads)\n", h.size(), r.groups,
              r.levels, build_s, threads);

  std::vector<double> true_m(h.size()), self_m(h.size()), parent_m(h.size());
  for (std::size_t c = 0; c < h.size(); ++c) {
    true_m[c] = field.max_error(r.indices.data() + h.first_index[c], h.index_count[c]);
    self_m[c] = h.self_error_m[c];
    parent_m[c] = h.parent_error_m[c];
  }
  // True group errors, monotone: groups are numbered in build order, members before parents.
  std::vector<double> group_m(r.groups, 0.0);
  for (std::size_t c = 0; c < h.size(); ++c)
    if (r.source_group[c] >= 0) group_m[r.source_group[c]] = std::max(group_m[r.source_group[c]], true_m[c]);
  std::vector<double> mono_m = group_m;
  std::vector<std::size_t> order(h.size());
  for (std::size_t c = 0; c < h.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h.depth[a] < h.depth[b]; });
  for (std::size_t c : order)
    if (r.parent_group[c] >= 0 && r.source_group[c] >= 0)
      mono_m[r.parent_group[c]] = std::max(mono_m[r.parent_group[c]], mono_m[r.source_group[c]]);
  std::vector<double> oself_m(h.size()), oparent_m(h.size());
  for (std::size_t c = 0; c < h.size(); ++c) {
    oself_m[c] = r.source_group[c] >= 0 ? mono_m[r.source_group[c]] : 0.0;
    oparent_m[c] = r.parent_group[c] >= 0 ? mono_m[r.parent_group[c]] : std::numeric_limits<double>::infinity();
  }
  std::printf("\n%8s %9s %7s %10s | %9s %7s %10s %10s %10s %3s | %12s %7s\n", "t_m", "chain_tri", "share", "chain_true",
              "cut_tri", "share", "cut_true", "cut_vert", "cut_bound", "ok", "vert_cut_tri", "share");
  std::vector<double> chain_true(chain.levels.size(), 0.0);
  for (std::size_t l = 1; l < chain.levels.size(); ++l)
    chain_true[l] = surface_error(m.positions, chain.levels[l].indices);
  bool all_ok = true;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t l = 1; l < chain.levels.size(); ++l) {
      const SimplifiedLevel& lv = chain.levels[l];
      const double t = pass == 0 ? lv.error_m : chain_true[l];
      const CutStats s = cut_stats(r, self_m, parent_m, true_m, t);
      const CutStats o2 = cut_stats(r, oself_m, oparent_m, true_m, t);
      const double cut_true = surface_error(m.positions, s.indices);
      const bool ok = cut_true <= s.bound_m;
      all_ok = all_ok && ok;
      std::printf("%8.4f %9zu %6.2f%% %10.4f | %9zu %6.2f%% %10.4f %10.4f %10.4f %3s | %12zu %6.2f%%\n", t,
                  lv.indices.size() / 3, 100.0 * double(lv.indices.size() / 3) / source, chain_true[l], s.triangles,
                  100.0 * double(s.triangles) / source, cut_true, s.true_m, s.bound_m, ok ? "yes" : "NO", o2.triangles,
                  100.0 * double(o2.triangles) / source);
    }

  std::printf("\n%5s %9s %10s %8s %13s %12s\n", "depth", "clusters", "triangles", "share", "mean_bound_m",
              "mean_vert_m");
  for (std::uint32_t d = 0; d < r.levels; ++d) {
    std::size_t n = 0, tris = 0;
    double bound = 0.0, truth = 0.0;
    for (std::size_t c = 0; c < h.size(); ++c)
      if (h.depth[c] == d) ++n, tris += h.index_count[c] / 3, bound += self_m[c], truth += true_m[c];
    std::printf("%5u %9zu %10zu %7.2f%% %13.4f %12.4f\n", d, n, tris, 100.0 * double(tris) / source,
                n ? bound / double(n) : 0.0, n ? truth / double(n) : 0.0);
  }
  return all_ok ? 0 : 1;
}

}  // namespace
}  // namespace gazelod::bake

int main(int argc, char** argv) {
  const std::uint64_t triangles = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1'000'000;
  const unsigned threads = argc > 2 ? static_cast<unsigned>(std::strtoul(argv[2], nullptr, 10)) : 2;
  if (triangles < 2 || triangles > gazelod::bake::kMaxGeneratedTriangles) {
    std::fprintf(stderr, "bench_cluster_tightness: triangles must be in [2, %llu], got %s\n",
                 static_cast<unsigned long long>(gazelod::bake::kMaxGeneratedTriangles), argc > 1 ? argv[1] : "");
    return 2;
  }
  return gazelod::bake::run(triangles, threads);
}
