// SPDX-License-Identifier: Apache-2.0
// Greedy cluster splitting with an incrementally scored frontier (cluster_split.hpp).
#include "bake/cluster/cluster_split.hpp"

#include <limits>

namespace gazelod::bake {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t kJumpScan = 512;
constexpr std::uint32_t kRanks = 5;  // a frontier triangle's rank, 0 to 4 (split())

}  // namespace

void ClusterSplitter::split(std::span<const float> pos, std::size_t vertex_count, std::span<const std::uint32_t> tris,
                            std::size_t max_vertices, std::size_t max_triangles, std::vector<std::uint32_t>& out,
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
      centroid_[3 * t + j] =
          (pos[3 * tris[3 * t] + j] + pos[3 * tris[3 * t + 1] + j] + pos[3 * tris[3 * t + 2] + j]) / 3.0f;
  }
  in_cluster_.assign(vertex_count, kNone);
  frontier_of_.assign(n, kNone);
  score_.assign(n, 0);
  arrival_.resize(n);
  done_.assign(n, 0);

  live_.assign(vertex_count, 0);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) live_[tris[3 * t + k]] += distinct(t, k);
  // A frontier triangle's rank, the order meshopt takes them in: no new vertex (0), one that
  // would be left dangling (1: the last triangle left using one of its corners), then by new
  // vertices (2 to 4). A rank only falls while a cluster grows; each frontier triangle is in
  // the bucket of every rank it has had in this cluster (the earlier ones stale).
  auto rank_of = [&](std::uint32_t t) -> std::uint32_t {
    return score_[t] == 0 ? 0 : dangling_[t] ? 1 : score_[t] + 1;
  };
  for (auto& b : bucket_) b.clear();
  std::uint32_t cluster = 0;
  dangling_.assign(n, 0);
  auto flag_last = [&](std::uint32_t v) {
    for (std::uint32_t i = first_[v]; i < first_[v + 1]; ++i)
      if (const std::uint32_t u = adjacent_[i]; !done_[u]) {
        if (dangling_[u]) return;
        dangling_[u] = 1;
        if (frontier_of_[u] == cluster && score_[u] > 0) bucket_[1].push_back(u);
        return;
      }
  };
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    if (live_[v] == 1) flag_last(v);
  // In float: only an order among nearby triangles, and the hot loop of the scan (about a fifth
  // of a build in double).
  auto distance_sq = [&](std::uint32_t t, const float c[3]) {
    const float dx = centroid_[3 * t] - c[0], dy = centroid_[3 * t + 1] - c[1], dz = centroid_[3 * t + 2] - c[2];
    return dx * dx + dy * dy + dz * dz;
  };
  // The first triangle from t on not yet taken (n if none), along skip_ links that jump over
  // taken ones (shortened on the way, so a scan past taken triangles is paid once).
  skip_.resize(n);
  for (std::size_t t = 0; t < n; ++t) skip_[t] = static_cast<std::uint32_t>(t + 1);
  auto alive_from = [&](std::size_t t) {
    std::size_t r = t;
    while (r < n && done_[r]) r = skip_[r];
    while (t < r) {
      const std::size_t next = skip_[t];
      skip_[t] = static_cast<std::uint32_t>(r);
      t = next;
    }
    return r;
  };
  float last[3] = {0.0f, 0.0f, 0.0f};  // the previous cluster's centroid
  std::size_t cursor = 0, emitted = 0;
  for (; emitted < n; ++cluster) {
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
      cursor = alive_from(cursor);
      seed = static_cast<std::uint32_t>(cursor);
    }
    frontier_.clear();
    for (auto& b : bucket_) b.clear();
    std::uint32_t arrivals = 0;
    std::size_t vertices = 0, triangles = 0;
    double sum[3] = {0.0, 0.0, 0.0};
    auto add = [&](std::uint32_t t) {
      done_[t] = 1;
      ++triangles, ++emitted;
      for (int j = 0; j < 3; ++j) sum[j] += centroid_[3 * t + j];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = tris[3 * t + k];
        out.push_back(v);
        if (distinct(t, k) && --live_[v] == 1) flag_last(v);
        if (in_cluster_[v] == cluster) continue;
        in_cluster_[v] = cluster;
        ++vertices;
        for (std::uint32_t i = first_[v]; i < first_[v + 1]; ++i) {
          const std::uint32_t u = adjacent_[i];
          if (done_[u]) continue;
          if (frontier_of_[u] == cluster) {
            const std::uint32_t was = rank_of(u);
            --score_[u];
            if (const std::uint32_t r = rank_of(u); r != was) bucket_[r].push_back(u);
            continue;
          }
          frontier_of_[u] = cluster;
          frontier_.push_back(u);
          arrival_[u] = arrivals++;
          std::uint32_t fresh = 0;
          for (int c = 0; c < 3; ++c) fresh += distinct(u, c) && in_cluster_[tris[3 * u + c]] != cluster;
          score_[u] = fresh;
          bucket_[rank_of(u)].push_back(u);
        }
      }
    };
    add(seed);
    while (triangles < max_triangles) {
      const float centre[3] = {float(sum[0] / double(triangles)), float(sum[1] / double(triangles)),
                               float(sum[2] / double(triangles))};
      std::uint32_t best = kNone;
      float best_sq = 0.0f;
      // The lowest rank first, then the nearest to the centroid, then the earliest on the
      // frontier: the first non-empty bucket decides.
      for (std::uint32_t r = 0; r < kRanks && best == kNone; ++r) {
        std::vector<std::uint32_t>& b = bucket_[r];
        std::size_t kept = 0;
        for (std::uint32_t t : b) {
          if (done_[t] || rank_of(t) != r) continue;  // taken, or fallen to a lower rank
          b[kept++] = t;
          const float d_sq = distance_sq(t, centre);
          if (best == kNone || d_sq < best_sq || (d_sq == best_sq && arrival_[t] < arrival_[best]))
            best = t, best_sq = d_sq;
        }
        b.resize(kept);
      }
      if (best == kNone && emitted < n) {  // nothing touches the cluster: the nearest triangle left
        cursor = alive_from(cursor);
        // At most kJumpScan triangles from the first one left: bounded work on a triangle soup.
        for (std::size_t t = cursor, seen = 0; t < n && seen < kJumpScan; t = alive_from(t + 1), ++seen) {
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
