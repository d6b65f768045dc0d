// SPDX-License-Identifier: Apache-2.0
// Checks the cluster-hierarchy tests share (unit and integration): the open edges of a set of
// triangles with positions welded, the cut at an error threshold, and every invariant
// build_cluster_hierarchy promises (cluster_build.hpp), as gtest expectations.
#pragma once

#include "bake/cluster/cluster_build.hpp"

#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

namespace gazelod::bake::testing {

// Signed count per undirected welded edge (a < b): +1 per half-edge a->b, -1 per b->a, zero
// entries dropped. Empty for a closed, consistently oriented surface; two triangle sets with
// the same map have the same open border.
using OpenEdges = std::map<std::pair<std::uint32_t, std::uint32_t>, int>;
OpenEdges open_edges(std::span<const float> positions, std::span<const std::uint32_t> triangles);

// The triangles of the clusters drawn at threshold t: self_error <= t < parent_error.
std::vector<std::uint32_t> cut(const ClusterBuildResult& r, float t);
// The triangles of the given clusters.
std::vector<std::uint32_t> triangles_of(const ClusterBuildResult& r, std::span<const std::uint32_t> clusters);

// bake::meeting_vertices for every mesh a node uses: what bake_clusters_model locks, so a test
// can rebuild a stored primitive's hierarchy directly.
std::vector<std::vector<std::vector<std::uint8_t>>> meeting_vertices_of(const tinygltf::Model& model);

// Every invariant, against the source mesh: monotone errors, shared records per group, parent
// spheres containing self spheres, leaves covering the source exactly once, cluster size limits,
// each group's border with other groups unchanged by its simplification (only the mesh's own
// open border, where not locked, may change, along itself), and cuts at no error, at every group
// error and at the top having the source's open border off that free outline (no crack).
void expect_hierarchy_invariants(const ClusterBuildResult& r, std::span<const float> positions,
                                 std::span<const std::uint32_t> source, const ClusterBuildOptions& options = {});

}  // namespace gazelod::bake::testing
