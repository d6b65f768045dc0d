// SPDX-License-Identifier: Apache-2.0
// How far one triangle mesh lies from another, for comparing simplifiers on equal terms (gazelod
// eval gltfpack): both a model's source and each simplified version as one world-space triangle
// soup (every mesh instance's triangle primitives through its node transforms), and the
// distances from one soup's vertices to the other's surface (bake/cluster_distance.hpp's grid,
// the measure the bake's own errors use).
#pragma once

#include <tiny_gltf.h>

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace gazelod::bake {

struct TriangleSoup {
  std::vector<float> positions_xyz;    // world space, metres
  std::vector<std::uint32_t> indices;  // triangle list
  std::size_t triangles() const { return indices.size() / 3; }
};

// Appends a primitive's triangles (mesh space) placed by `world`.
void append_placed(TriangleSoup& soup, const std::vector<float>& positions_xyz,
                   const std::vector<std::uint32_t>& indices, const glm::dmat4& world);

// Every triangle primitive of every mesh instance of the scene(s) a viewer sees (node_world.hpp),
// in world space; points and lines are left out. Throws BakeError as extract_primitive does.
TriangleSoup world_triangles(const tinygltf::Model& model);

// Distances from each vertex `from` uses to the nearest point of `to`'s triangles: largest,
// 99th percentile and mean (metres). `to` empty: every figure +inf. `from` empty: all 0.
struct SurfaceDeviation {
  double max_m = 0.0, p99_m = 0.0, mean_m = 0.0;
  std::size_t vertices = 0;
};
SurfaceDeviation surface_deviation(const TriangleSoup& from, const TriangleSoup& to, unsigned threads = 0);

// The largest extent of a soup's used vertices (the scale the relative figures use).
double soup_extent_m(const TriangleSoup& soup);

}  // namespace gazelod::bake
