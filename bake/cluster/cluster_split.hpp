// SPDX-License-Identifier: Apache-2.0
// Splitting a simplified group back into clusters (bake/cluster/cluster_build.hpp). meshopt 0.18's
// meshopt_buildMeshlets rescores every triangle around every vertex of the growing cluster for
// each triangle it adds, which made it the largest cost of the build; this greedy builder keeps
// each frontier triangle's count of vertices not yet in the cluster up to date instead, and adds
// the frontier triangle needing no new vertex, else one that would be left dangling, else the
// one needing fewest (ties: nearest the cluster's centroid), as meshopt does without its cone
// term; when nothing touches the cluster, the nearest triangle left. The frontier is kept in
// buckets by that rank, so a step compares only the best rank's triangles. A cluster ends when
// the next triangle would pass a limit; the next one starts at a triangle the last one left on
// its frontier.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

// Keeps its arrays between calls (one per thread).
class ClusterSplitter {
 public:
  // triangles: a triangle list into `vertex_count` vertices (positions_xyz: 3 floats each).
  // Appends the triangles cluster by cluster to `out` and each cluster's index count to
  // `index_count`; every cluster has at most max_vertices distinct vertices and max_triangles
  // triangles.
  void split(std::span<const float> positions_xyz, std::size_t vertex_count, std::span<const std::uint32_t> triangles,
             std::size_t max_vertices, std::size_t max_triangles, std::vector<std::uint32_t>& out,
             std::vector<std::uint32_t>& index_count);

 private:
  std::vector<std::uint32_t> first_, adjacent_, in_cluster_, frontier_, score_, frontier_of_, live_;
  // Frontier triangles by rank (split()); per triangle, its place in the order it joined the
  // cluster's frontier.
  std::vector<std::uint32_t> bucket_[5], arrival_, skip_;
  std::vector<float> centroid_;
  std::vector<std::uint8_t> done_, dangling_;
};

}  // namespace gazelod::bake
