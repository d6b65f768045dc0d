// SPDX-License-Identifier: Apache-2.0
// Source-side steps of the cluster hierarchy build (bake/cluster/cluster_build.hpp): welding vertices by
// position, and cutting the source triangles into spatially coherent chunks that are split into
// clusters in parallel.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

// vertex -> the first vertex with bit-identical position (-0 counted as +0).
std::vector<std::uint32_t> weld_positions(std::span<const float> positions_xyz);

// Triangle ids of `triangles` (a triangle list) in Morton order of their centroid's cell, cut
// into chunks of about 65536 triangles at cell boundaries; one chunk when the mesh is smaller.
std::vector<std::vector<std::uint32_t>> source_chunks(std::span<const float> positions_xyz,
                                                      std::span<const std::uint32_t> triangles);

}  // namespace gazelod::bake
