// SPDX-License-Identifier: Apache-2.0
// Reads a baked .glb/.gltf back as LOD chains for the selection: one object per scene node
// with a mesh (default scene, or every scene when none is default), its chain from the node's
// MSFT_lod ids and each level's extras.gazelod_lod, and its world-space bounding sphere; and
// every mesh primitive's cluster hierarchy (GAZELOD_cluster_lod, bake --clusters).
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"
#include "lod/lod_chain.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake {

// One LOD level's geometry: its mesh's triangle primitives merged into one triangle list
// (strips and fans as lists), positions in the mesh's own space (x, y, z per vertex).
struct BakedLevelMesh {
  std::vector<float> positions_xyz;
  std::vector<std::uint32_t> indices;
};

struct BakedObject {
  std::string name;          // node name, or "node N"
  int node = -1;             // glTF node index of the finest level
  int mesh = -1;             // glTF mesh index of the finest level
  glm::dvec3 center_m{0.0};  // world space (node transforms applied)
  double radius_m = 0.0;     // world space, encloses the full-detail mesh
  glm::dmat4 world{1.0};     // the node's world transform (mesh space -> glTF world), as glTF's column-major matrices
  // lods[0] is the full mesh; detail is removed cycles per diameter (0 at level 0), from the
  // geometric error (detail.hpp); passes lod::validate_chain.
  std::vector<lod::LodLevel> lods;
  // Per level, with BakedLoad::with_level_geometry (else empty): its mesh (the level's node's,
  // drawn with this node's `world`, as MSFT_lod replaces the mesh, not the transform).
  std::vector<BakedLevelMesh> level_meshes;
};

// One primitive's cluster hierarchy (bake/cluster/cluster_lod_gltf.hpp): cluster c is the triangle
// list indices[first_index[c] .. + index_count[c]) into the primitive's own vertices; bounds
// and errors in the mesh's own space (not the node's world space), as are the primitive's
// positions (x, y, z per vertex, vertex_count vertices) the indices point into.
struct BakedClusterPrimitive {
  int primitive = -1;
  std::uint32_t vertex_count = 0;
  std::uint32_t levels = 0;
  lod::ClusterHierarchy hierarchy;
  std::vector<std::uint32_t> indices;
  std::vector<float> positions_xyz;
};

struct BakedClusterMesh {
  int mesh = -1;
  std::string name;
  std::vector<BakedClusterPrimitive> primitives;  // those with GAZELOD_cluster_lod
};

struct BakedScene {
  std::vector<BakedObject> objects;
  std::vector<BakedClusterMesh> cluster_meshes;  // meshes with GAZELOD_cluster_lod, mesh order
  // The cluster hierarchies of an object's mesh; nullptr when it has none.
  const BakedClusterMesh* clusters_of(const BakedObject& object) const;
};

// Throws BakeError "PATH: /nodes/3/extras/gazelod_lod/triangles: ..." for a file that is not a
// gazelod bake output or is inconsistent (bad ids, missing extras, chain that fails validation,
// a malformed GAZELOD_cluster_lod; with level geometry, a level's mesh that is not triangles or
// holds a bad accessor: BakeError "PATH: mesh 2 'Body' primitive 0: ..."). A node whose mesh has cluster hierarchies
// needs no extras.gazelod_lod: its chain is then one level, the full mesh. What load_baked reads beside the chains,
// bounds and cluster hierarchies.
enum class BakedLoad { chains, with_level_geometry };
BakedScene load_baked(const std::string& path, BakedLoad what = BakedLoad::chains);
// load_baked(path).objects.
std::vector<BakedObject> load_baked_scene(const std::string& path);

}  // namespace gazelod::bake
