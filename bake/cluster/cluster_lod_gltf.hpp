// SPDX-License-Identifier: Apache-2.0
// GAZELOD_cluster_lod: a mesh primitive's cluster hierarchy (lod/cluster/cluster_hierarchy.hpp) stored
// in glTF, written by `gazelod bake --clusters` (format: docs/bake.md). On the primitive:
//   "extensions": {"GAZELOD_cluster_lod": {
//     "version": 1, "clusterCount": N, "levelCount": L,
//     "indices":       accessor, SCALAR UNSIGNED_SHORT|UNSIGNED_INT: every cluster's triangles
//                      (all levels, triangle list) into the primitive's own vertices,
//     "ranges":        accessor, VEC2 UNSIGNED_INT, N: first index, index count in "indices",
//     "selfSpheres":   accessor, VEC4 FLOAT, N: centre x, y, z, radius (mesh units, metres),
//     "parentSpheres": accessor, VEC4 FLOAT, N,
//     "errors":        accessor, VEC2 FLOAT, N: self error, parent error (metres);
//                      3.4028235e38 (FLT_MAX) is "no parent" (kNoParentError; glTF accessors
//                      may not hold infinity),
//     "depths":        accessor, SCALAR UNSIGNED_BYTE, N: 0 for source clusters}}
// The name goes into extensionsUsed only, never extensionsRequired: a viewer that does not
// know it draws the primitive's own full-detail indices.
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <tiny_gltf.h>

#include <cfloat>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gazelod::bake {

inline constexpr char kClusterLodExtension[] = "GAZELOD_cluster_lod";
inline constexpr int kClusterLodVersion = 1;
inline constexpr float kStoredNoParentError = FLT_MAX;

// Appends the accessors to buffer 0 (the model must be packed, gltf_pack.hpp) and sets the
// extension on meshes[mesh].primitives[primitive]. `vertex_count` is the primitive's.
void write_cluster_lod(tinygltf::Model& model, int mesh, int primitive, const lod::ClusterHierarchy& hierarchy,
                       std::span<const std::uint32_t> indices, std::size_t vertex_count);

struct ClusterLod {
  lod::ClusterHierarchy hierarchy;
  std::vector<std::uint32_t> indices;
  std::uint32_t levels = 0;
  std::uint32_t vertex_count = 0;  // the primitive's
};

// nullopt when the primitive has no GAZELOD_cluster_lod. Throws BakeError
// "<file>: /meshes/M/primitives/P/extensions/GAZELOD_cluster_lod/<key>: ..." for one that is
// malformed or inconsistent (wrong accessor type or count, index or range out of bounds,
// values that are not finite, errors that are not monotone, a sphere not inside its parent).
std::optional<ClusterLod> read_cluster_lod(const tinygltf::Model& model, int mesh, int primitive,
                                           const std::string& file);

}  // namespace gazelod::bake
