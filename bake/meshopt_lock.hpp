// SPDX-License-Identifier: Apache-2.0
// Locking a vertex in meshoptimizer 0.18's simplifier, which has no per-vertex lock
// (vertex_lock came in 0.21): it never moves a position that three or more vertices share
// ("many wedges", Kind_Locked in its classifyVertices), unreferenced ones included, so two
// unused copies of a vertex's position appended to the simplifier's positions lock it. The
// copies must be dropped (positions resized back) before the positions are used otherwise.
#pragma once

#include <cstddef>
#include <vector>

namespace gazelod::bake {

inline void lock_position(std::vector<float>& positions_xyz, std::size_t vertex) {
  const float x = positions_xyz[3 * vertex], y = positions_xyz[3 * vertex + 1], z = positions_xyz[3 * vertex + 2];
  positions_xyz.insert(positions_xyz.end(), {x, y, z, x, y, z});
}

}  // namespace gazelod::bake
