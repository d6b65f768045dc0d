// SPDX-License-Identifier: Apache-2.0
// Puts baked LOD chains into a model as glTF MSFT_lod: for each node with a mesh, the coarser
// levels become extra nodes (same transform, mesh "<name>_lod<k>", not in any scene) listed in
// the node's extensions.MSFT_lod.ids, finest first. Every level's node carries
//   extras.gazelod_lod = {level, triangles, vertices, error_relative, error_m, diameter_m,
//                         detail_cycles_per_diameter[, rendered_cycles_per_diameter]}
// (error_m and diameter_m in the mesh's own units; detail = diameter / (2 error), detail.hpp;
// rendered = Reddy's rendered profile, profile_render.hpp, only when the bake profiled).
// Coarser meshes share the original vertex accessors; only index accessors are added.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace gazelod::bake {

struct MeshLevel {
  std::uint32_t triangles = 0;
  std::uint32_t vertices = 0;
  double error_relative = 0.0;  // error_m / the mesh's extent (meshopt_simplifyScale)
  double error_m = 0.0;
  bool sloppy = false;
  // Removed cycles per diameter from the rendered profile; < 0 when not profiled.
  double rendered_cycles_per_diameter = -1.0;
  // Per original primitive; an empty list drops that primitive at this level. Unused at level 0.
  std::vector<std::vector<std::uint32_t>> primitive_indices;
};

struct MeshChain {
  double diameter_m = 0.0;        // bounding-sphere diameter of the full mesh
  std::vector<MeshLevel> levels;  // levels[0] is the input mesh
};

// `chains` has one entry per model mesh (an empty `levels` leaves that mesh untouched).
// Throws BakeError when a node's extras exist but are not a JSON object.
void write_msft_lod(tinygltf::Model& model, const std::vector<MeshChain>& chains);

// The extras object written for one level (exposed for tests and the loader's checks).
tinygltf::Value lod_extras(int level, const MeshLevel& l, double diameter_m);

}  // namespace gazelod::bake
