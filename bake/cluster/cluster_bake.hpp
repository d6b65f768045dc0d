// SPDX-License-Identifier: Apache-2.0
// gazelod bake --clusters: a glTF scene in, the same scene out with a cluster hierarchy
// (bake/cluster/cluster_build.hpp) on every primitive of every mesh a node uses, stored as
// GAZELOD_cluster_lod (bake/cluster/cluster_lod_gltf.hpp, docs/bake.md). Nothing else changes: no
// nodes, meshes or materials are added; buffers are packed into the GLB's one buffer
// (gltf_pack.hpp). Pipeline: gltf_load -> mesh_extract -> cluster_build -> cluster_lod_gltf ->
// glb_write.
#pragma once

#include "bake/gltf_load.hpp"
#include "bake/cluster/cluster_build.hpp"
#include "bake/mesh_extract.hpp"

#include <tiny_gltf.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gazelod::bake {

struct ClusterBakeOptions {
  ClusterBuildOptions build;                         // `label` is set per primitive
  std::function<void(const std::string&)> progress;  // one line per call; may be empty
  GltfLoadOptions load;                              // where external uris may point
};

struct ClusterPrimitiveReport {
  int mesh = -1, primitive = -1;
  std::string label;                 // "mesh 2 'Body' primitive 0"
  std::size_t source_triangles = 0;  // kept
  std::size_t degenerate_triangles = 0;
  std::size_t clusters = 0, groups = 0, top_clusters = 0, top_triangles = 0;
  std::size_t stored_triangles = 0;  // all levels
  std::uint32_t levels = 0;
  std::size_t shared_vertices = 0;      // where another primitive or instance meets it: locked
  std::size_t folded_triangles = 0;     // ClusterBuildResult's
  std::size_t groups_across_seams = 0;  // ClusterBuildResult's
  double build_seconds = 0.0;           // build_cluster_hierarchy alone
};

struct ClusterBakeReport {
  std::vector<ClusterPrimitiveReport> primitives;  // with a hierarchy, in mesh order
  std::vector<std::string> warnings;
  std::size_t meshes = 0;             // meshes used by at least one node
  std::uint64_t input_triangles = 0;  // of those meshes, degenerate ones included
  std::size_t shared_vertices = 0, folded_triangles = 0, groups_across_seams = 0;  // all primitives' sums
  double build_seconds = 0.0;                                                      // hierarchy builds, all primitives
  double seconds = 0.0;  // everything (with reading and writing for a file)
};

// Per mesh, per primitive, per vertex: 1 where the primitive's open border meets another
// primitive or instance of the scene (bake/cluster/shared_positions.hpp); the bake keeps those at every
// level unless build.lock_open_borders (then it keeps every open border). geometry[mesh]: the
// mesh's primitives, empty for a mesh the bake skips.
std::vector<std::vector<std::vector<std::uint8_t>>> meeting_vertices(
    const tinygltf::Model& model, const std::vector<std::vector<PrimitiveGeometry>>& geometry);

// Bakes a loaded model in place. Throws BakeError naming the mesh and primitive for geometry it
// cannot handle; the model is then unusable.
ClusterBakeReport bake_clusters_model(tinygltf::Model& model, const ClusterBakeOptions& options);

// Loads `in`, bakes, writes `out` atomically. Throws BakeError ("IN: ..."), OutputError for
// the output; `out` is untouched on failure.
ClusterBakeReport bake_clusters_file(const std::string& in, const std::string& out, const ClusterBakeOptions& options);

// Table per primitive, then totals with input triangles per second of the hierarchy build.
std::string format_cluster_summary(const ClusterBakeReport& report);

}  // namespace gazelod::bake
