// SPDX-License-Identifier: Apache-2.0
// A triangle primitive's positions and indices out of a glTF model, with every check the
// simplifier relies on (float VEC3 positions, in-range indices, no sparse accessors, triangles).
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake {

struct PrimitiveGeometry {
  std::vector<float> positions_xyz;    // 3 per vertex, as stored (mesh-local units, metres)
  std::vector<std::uint32_t> indices;  // triangle list; 0..n-1 for a non-indexed primitive
};

// glTF TRIANGLE_STRIP / TRIANGLE_FAN vertex order (glTF 2.0 spec 3.7.2.1) as a triangle list;
// fewer than 3 indices give none.
std::vector<std::uint32_t> strip_to_list(const std::vector<std::uint32_t>& strip);
std::vector<std::uint32_t> fan_to_list(const std::vector<std::uint32_t>& fan);

// "mesh 2 'Body'" and "mesh 2 'Body' primitive 1" - how errors and progress name them.
std::string mesh_label(const tinygltf::Model& model, int mesh);
std::string primitive_label(const tinygltf::Model& model, int mesh, int primitive);

// Whether a primitive's mode draws triangles (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN): what
// the bakes can simplify; points and lines cannot be.
bool draws_triangles(const tinygltf::Primitive& primitive);

// "mode 1 (LINES)": how messages name a primitive's mode.
std::string mode_label(int mode);

// TRIANGLE_STRIP and TRIANGLE_FAN primitives come out as triangle lists.
// Throws BakeError "<label>: ..." for: no POSITION, a non-float or non-VEC3 POSITION, a sparse
// accessor, a mode that is not triangles (points, lines), an accessor/bufferView outside its
// buffer, a non-finite position, an index out of range, or a list whose index count is not a
// multiple of 3.
PrimitiveGeometry extract_primitive(const tinygltf::Model& model, int mesh, int primitive);

// The accessors the bakes copy into their output unread (attributes other than POSITION,
// morph targets; a point or line primitive's indices): each in its buffer and of the
// primitive's vertex count, so that no bake writes a file that reads past its data (tinygltf
// checks neither). extract_primitive calls it; a bake that carries a primitive over
// unsimplified calls it itself. Throws BakeError "<label>: ...".
void check_carried_accessors(const tinygltf::Model& model, int mesh, int primitive);

// Triangles that cover an area: not two corners at one position (by index or coordinates).
// The cluster builder drops the others; a file with none left has nothing to bake, in either
// bake (kNothingLeftToBake, the message both give).
std::size_t count_area_triangles(const PrimitiveGeometry& geometry);
inline constexpr const char* kNothingLeftToBake =
    "nothing to bake: no triangle primitive has a triangle left once degenerate ones (two corners at one "
    "position) are dropped";

// Coordinates past this (metres, any axis) are refused where positions are read: beyond the
// Moon's orbit no LOD decision means anything, and squared distances and bounds of ~3e38
// overflow float (a bake wrote them out and `run --scene` then refused the file).
inline constexpr double kMaxPositionM = 1e9;

// Only the positions of accessor `accessor` (POSITION), with the same checks; `where` prefixes
// error messages. Used by the baked-scene loader for bounding spheres.
std::vector<float> read_positions(const tinygltf::Model& model, int accessor, const std::string& where);

// The unsigned byte/short/int SCALAR accessor `accessor` as 32-bit values, each checked
// < vertex_count; `where` prefixes error messages.
std::vector<std::uint32_t> read_index_accessor(const tinygltf::Model& model, int accessor, std::size_t vertex_count,
                                               const std::string& where);

// The elements of accessor `accessor` copied tightly packed (element_size bytes each, stride
// removed) after the same bounds checks; the caller checks componentType and type.
std::vector<unsigned char> read_accessor_bytes(const tinygltf::Model& model, int accessor, std::size_t element_size,
                                               const std::string& where);

}  // namespace gazelod::bake
