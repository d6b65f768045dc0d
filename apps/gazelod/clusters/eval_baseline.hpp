// SPDX-License-Identifier: Apache-2.0
// The same-rule baseline of `gazelod eval clusters`: per-object LOD judged by the rule the
// clusters are judged by. The plugin's object rule (lod/select.hpp) and its cluster rule
// (lod/cluster/cluster_select.hpp) differ on a large mesh: an object's level is one removed frequency
// in cycles per object diameter, seen over the object's whole angular size (a mesh the viewer
// stands in spans 180 deg, so a 0.1 m error there counts as fine detail), while a cluster's
// error is seen from the nearest point of its sphere. To compare granularity alone, each
// primitive's LOD chain (bake/simplify_chain.hpp with `gazelod bake`'s default ratios) is also
// stored as a cluster hierarchy with one cluster per level (self error = the level's, parent
// error = the next level's, every sphere the primitive's bounding sphere): `gazelod run` then
// draws exactly one level of each mesh with the cluster rule, and its cluster audit judges
// that with the cluster oracle (leaves = the meshes at full detail).
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::cli {

// One primitive's chain as a one-cluster-per-level hierarchy. level_indices[k]: level k's
// triangle list into the primitive's vertices; error_m[k]: its error in metres, non-decreasing,
// 0 at level 0. Empty levels are skipped (the level before then has no parent). `indices`
// receives the levels back to back.
lod::ClusterHierarchy chain_hierarchy(std::span<const float> positions_xyz,
                                      const std::vector<std::vector<std::uint32_t>>& level_indices,
                                      std::span<const double> error_m, std::vector<std::uint32_t>& indices);

// Loads `in`, gives every primitive of every mesh a node uses such a hierarchy
// (GAZELOD_cluster_lod, as `gazelod bake --clusters` stores it), writes `out` atomically.
// Throws UsageError naming the file (and mesh) for bad input, exit status 2, or an unwritable
// output, 1. Returns the number of primitives.
std::size_t bake_chain_as_clusters(const std::string& in, const std::string& out);

}  // namespace gazelod::cli
