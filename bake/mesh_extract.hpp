// A triangle primitive's positions and indices out of a glTF model, with every check the
// simplifier relies on (float VEC3 positions, in-range indices, no sparse accessors, triangles).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake {

struct PrimitiveGeometry {
  std::vector<float> positions_xyz;      // 3 per vertex, as stored (mesh-local units, metres)
  std::vector<std::uint32_t> indices;    // triangle list; 0..n-1 for a non-indexed primitive
};

// "mesh 2 'Body' primitive 1" - how errors and progress name a primitive.
std::string primitive_label(const tinygltf::Model& model, int mesh, int primitive);

// Throws BakeError "<label>: ..." for: no POSITION, a non-float or non-VEC3 POSITION, a sparse
// accessor, a mode other than TRIANGLES, an accessor/bufferView outside its buffer, a
// non-finite position, an index out of range, or an index count not a multiple of 3.
PrimitiveGeometry extract_primitive(const tinygltf::Model& model, int mesh, int primitive);

// Only the positions of accessor `accessor` (POSITION), with the same checks; `where` prefixes
// error messages. Used by the baked-scene loader for bounding spheres.
std::vector<float> read_positions(const tinygltf::Model& model, int accessor,
                                  const std::string& where);

}  // namespace gazelod::bake
