// SPDX-License-Identifier: Apache-2.0
// Procedural stand-in meshes for LOD levels: a latitude/longitude unit sphere whose triangle
// count approximates a level's `triangles` (lod::LodLevel), until `gazelod bake` provides real
// meshes. Vertices are unit positions, which are also the normals.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace gazelod::render {

struct MeshData {
  std::vector<glm::vec3> positions;    // on the unit sphere
  std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise seen from outside
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// Largest triangle count generated; bigger requests are clamped (memory stays bounded).
inline constexpr std::uint32_t kMaxSphereTriangles = 1u << 20;

// Stacks (latitude bands, >= 2) and slices (>= 3) whose 2 * slices * (stacks - 1) triangles
// come closest to `target_triangles` (at least 6 triangles, at most kMaxSphereTriangles).
struct SphereResolution {
  std::uint32_t stacks = 2;
  std::uint32_t slices = 3;
  std::uint32_t triangles() const { return 2u * slices * (stacks - 1u); }
};
SphereResolution sphere_resolution(std::uint32_t target_triangles);

MeshData make_sphere(SphereResolution resolution);

}  // namespace gazelod::render
