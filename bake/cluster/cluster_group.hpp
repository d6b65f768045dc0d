// SPDX-License-Identifier: Apache-2.0
// Grouping of neighbouring clusters for the cluster hierarchy (bake/cluster/cluster_build.hpp). Each
// group is later simplified as one piece with its border locked, so groups should be compact
// and share few border vertices with each other (Karis et al. 2021 partition with METIS;
// meshoptimizer 0.18 has no meshopt_partitionClusters). Here: greedy graph growing on the
// graph whose edge weights are the (welded) vertices two clusters share, seeded where the
// previous group left unassigned clusters behind; groups left small are merged into the
// neighbour they share most with, and what is still small (pieces with no neighbour, e.g.
// separate parts of a model) is merged along a Morton curve of the cluster centres.
#pragma once

#include "bake/cluster/cluster_sphere.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

struct GroupingInput {
  // The clusters to group: each one's distinct welded vertices (a vertex -> the first vertex
  // with its position), in the order its triangles first use them, at vertices[first[c]] on,
  // count[c] of them; and their bounds (centres break ties).
  std::span<const std::uint32_t> vertices, first, count;
  std::span<const Sphere> bounds;
};

// Keeps per-vertex scratch arrays between calls (one per hierarchy build).
class ClusterGrouper {
 public:
  explicit ClusterGrouper(std::size_t vertex_count);
  // Groups of about `group_size` (>= 2) clusters, as positions in `set`; every cluster is in
  // exactly one group. A set of at most `group_size` clusters is one group.
  std::vector<std::vector<std::uint32_t>> group(const GroupingInput& set, std::size_t group_size);

 private:
  struct Neighbour {
    std::uint32_t cluster, shared_vertices;
  };
  void build_adjacency(const GroupingInput& set);
  std::vector<std::uint32_t> owner_, seen_;  // per welded vertex (build_adjacency())
  std::uint32_t base_ = 1;
  std::vector<std::vector<Neighbour>> adjacency_;
};

}  // namespace gazelod::bake
