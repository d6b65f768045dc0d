// SPDX-License-Identifier: Apache-2.0
// Which vertices of a scene's primitives lie where another primitive, or another instance of
// the same one, also has a vertex: the borders where separately baked meshes meet (terrain
// tiles, parts of a model). A cluster bake keeps those positions at every level
// (ClusterBuildOptions::locked_vertices), so that neighbouring meshes drawn at different
// levels still meet without a gap, while each mesh's free open border is simplified.
#pragma once

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

struct PlacedPrimitive {
  std::span<const float> positions_xyz;    // 3 floats per vertex, mesh space
  std::span<const std::uint32_t> indices;  // triangle list
  std::vector<glm::dmat4> world;           // one per instance; none: the primitive is not placed
};

// Per primitive, per vertex: 1 where the vertex lies on the primitive's own open border (an
// edge, positions welded, that is not used by exactly two of its triangles) and its world
// position (transformed in double, rounded to float, compared bit for bit) is also a vertex
// position of another primitive or instance, else 0. Only borders can open a gap: coinciding
// surface interiors are not flagged, and a position repeated within one instance (an attribute
// seam) is not a meeting.
std::vector<std::vector<std::uint8_t>> shared_positions(std::span<const PlacedPrimitive> primitives);

}  // namespace gazelod::bake
