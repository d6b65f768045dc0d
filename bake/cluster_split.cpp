// Greedy cluster splitting with an incrementally scored frontier (cluster_split.hpp).
#include "bake/cluster_split.hpp"

#include <limits>

namespace gazelod::bake {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t kJumpScan = 512;

}  // namespace

void ClusterSplitter::split(std::span<const float> pos, std::size_t vertex_count,
                            std::span<const std::uint32_t> tris, std::size_t max_vertices,
                            std::size_t max_triangles, std::vector<std::uint32_t>& out,
                            std::vector<std::uint32_t>& index_count) {
  const std::size_t n = tris.size() / 3;
  if (n == 0) return;
  // Corner k of triangle t is distinct unless an earlier corner has the same vertex.
  auto distinct = [&](std::size_t t, int k) {
    const std::uint32_t v = tris[3 * t + k];
    return (k < 1 || tris[3 * t] != v) && (k < 2 || tris[3 * t + 1] != v);
  };
  first_.assign(vertex_count + 1, 0);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      if (distinct(t, k)) ++first_[tris[3 * t + k] + 1];
  for (std::size_t v = 1; v <= vertex_count; ++v) first_[v] += first_[v - 1];
  adjacent_.resize(first_[vertex_count]);
  in_cluster_.assign(first_.begin(), first_.end() - 1);  // fill cursor first, then the stamp
  centroid_.resize(3 * n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int k = 0; k < 3; ++k)
      if (distinct(t, k)) adjacent_[in_cluster_[tris[3 * t + k]]++] = static_cast<std::uint32_t>(t);
    for (int j = 0; j < 3; ++j)
      centroid_[3 * t + j] = (pos[3 * tris[3 * t] + j] + pos[3 * tris[3 * t + 1] + j] + pos[3 * tris[3 * t + 2] + j]) / 3.0f;
  }
  in_cluster_.assign(vertex_count, kNone);
  frontier_of_.assign(n, kNone);
  score_.assign(n, 0);
  done_.assign(n, 0);

  live_.assign(vertex_count, 0);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) live_[tris[3 * t + k]] += distinct(t, k);
  // In float: only an order among nearby triangles, and the hot loop of the scan (about a fifth
  // of a build in double).
  auto distance_sq = [&](std::uint32_t t, const float c[3]) {
    const float dx = centroid_[3 * t] - c[0], dy = centroid_[3 * t + 1] - c[1], dz = centroid_[3 * t + 2] - c[2];
    return dx * dx + dy * dy + dz * dz;
  };
  float last[3] = {0.0f, 0.0f, 0.0f};  // the previous cluster's centroid
  std::size_t cursor = 0, emitted = 0;
  for (std::uint32_t cluster = 0; emitted < n; ++cluster) {
    // Seed: of the triangles the previous cluster left on its frontier, the one nearest its
    // centroid (meshopt starts the next meshlet there too); else the first one left.
    std::uint32_t seed = kNone;
    float seed_sq = 0.0f;
    for (std::uint32_t t : frontier_)
      if (!done_[t]) {
        const float d_sq = distance_sq(t, last);
        if (seed == kNone || d_sq < seed_sq) seed = t, seed_sq = d_sq;
      }
    if (seed == kNone) {
      while (done_[cursor]) ++cursor;
      seed = static_cast<std::uint32_t>(cursor);
    }
    frontier_.clear();
    std::size_t vertices = 0, triangles = 0;
    double sum[3] = {0.0, 0.0, 0.0};
    auto add = [&](std::uint32_t t) {
      done_[t] = 1;
      ++triangles, ++emitted;
      for (int j = 0; j < 3; ++j) sum[j] += centroid_[3 * t + j];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = tris[3 * t + k];
        out.push_back(v);
        if (distinct(t, k)) --live_[v];
        if (in_cluster_[v] == cluster) continue;
        in_cluster_[v] = cluster;
        ++vertices;
        for (std::uint32_t i = first_[v]; i < first_[v + 1]; ++i) {
          const std::uint32_t u = adjacent_[i];
          if (done_[u]) continue;
          if (frontier_of_[u] == cluster) {
            --score_[u];
            continue;
          }
          frontier_of_[u] = cluster;
          frontier_.push_back(u);
          std::uint32_t fresh = 0;
          for (int c = 0; c < 3; ++c) fresh += distinct(u, c) && in_cluster_[tris[3 * u + c]] != cluster;
          score_[u] = fresh;
        }
      }
    };
    add(seed);
    while (triangles < max_triangles) {
      const float centre[3] = {float(sum[0] / double(triangles)), float(sum[1] / double(triangles)),
                               float(sum[2] / double(triangles))};
      std::uint32_t best = kNone, best_rank = 0;
      float best_sq = 0.0f;
      std::size_t kept = 0;
      for (std::uint32_t t : frontier_) {
        if (done_[t]) continue;
        frontier_[kept++] = t;  // drop the triangles already taken
        // meshopt's order: no new vertex, then a triangle that would be left dangling (a corner
        // no other triangle uses), then by new vertices.
        std::uint32_t rank = score_[t];
        if (rank > 0 && best != kNone && best_rank == 0) continue;
        if (rank > 0) {
          const bool dangling = live_[tris[3 * t]] == 1 || live_[tris[3 * t + 1]] == 1 || live_[tris[3 * t + 2]] == 1;
          rank = dangling ? 1 : rank + 1;
        }
        if (best != kNone && rank > best_rank) continue;
        const float d_sq = distance_sq(t, centre);
        if (best == kNone || rank < best_rank || d_sq < best_sq) best = t, best_rank = rank, best_sq = d_sq;
      }
      frontier_.resize(kept);
      if (best == kNone && emitted < n) {  // nothing touches the cluster: the nearest triangle left
        while (done_[cursor]) ++cursor;
        // At most kJumpScan triangles from the first one left: bounded work on a triangle soup.
        for (std::size_t t = cursor, seen = 0; t < n && seen < kJumpScan; ++t) {
          if (done_[t]) continue;
          ++seen;
          const float d_sq = distance_sq(static_cast<std::uint32_t>(t), centre);
          if (best == kNone || d_sq < best_sq) best = static_cast<std::uint32_t>(t), best_sq = d_sq;
        }
        std::uint32_t fresh = 0;
        for (int c = 0; c < 3; ++c) fresh += distinct(best, c) && in_cluster_[tris[3 * best + c]] != cluster;
        score_[best] = fresh;
      }
      if (best == kNone || vertices + score_[best] > max_vertices) break;
      add(best);
    }
    index_count.push_back(static_cast<std::uint32_t>(3 * triangles));
    for (int j = 0; j < 3; ++j) last[j] = float(sum[j] / double(triangles));
  }
  frontier_.clear();
}

}  // namespace gazelod::bake
