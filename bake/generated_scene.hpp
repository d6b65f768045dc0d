// SPDX-License-Identifier: Apache-2.0
// Generated test scenes (`gazelod scene generate`: bake/terrain_mesh.hpp, bake/city_mesh.hpp)
// as glTF: one node per mesh, each mesh one triangle-list primitive with POSITION, NORMAL and
// 32-bit indices, every array in the GLB's one buffer, +Y up, metres. Written atomically with
// bake/glb_write.hpp, so `gazelod bake` (with or without --clusters) reads them like any model.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake {

struct GeneratedMesh {
  std::string name;                    // the node's and the mesh's name
  std::vector<float> positions;        // xyz, metres
  std::vector<float> normals;          // xyz, unit length, one per vertex
  std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise seen from outside
  std::size_t triangles() const { return indices.size() / 3; }
};

// What a generator made, for its summary line.
struct GeneratedStats {
  std::uint64_t triangles = 0, vertices = 0;
  std::size_t meshes = 0;
  double min_m[3] = {0.0, 0.0, 0.0}, max_m[3] = {0.0, 0.0, 0.0};  // bounds of all positions
};

GeneratedStats generated_stats(const std::vector<GeneratedMesh>& meshes);

// Throws std::invalid_argument naming the mesh for inconsistent arrays (lengths, an index out
// of range, a non-finite value) or a mesh too large for one buffer (2 GiB).
tinygltf::Model generated_model(const std::vector<GeneratedMesh>& meshes);

// generated_model, then write_glb_atomic: throws OutputError "PATH: ..." (nothing is left
// behind on failure) or std::invalid_argument as above.
void write_generated_glb(const std::vector<GeneratedMesh>& meshes, const std::string& path);

}  // namespace gazelod::bake
