// SPDX-License-Identifier: Apache-2.0
// Folds left by a group's simplification (bake/cluster/cluster_build.hpp, step 4). meshoptimizer 0.18's
// flip check misses some collapses on flat-shaded, panelled geometry: simplifying one city block
// (14,538 triangles of walls and roofs) to half with meshopt_simplify alone leaves 32 triangles
// facing against the wall or roof they lie in, overlapping a neighbour and leaving a hole
// beside it; a 200 k-triangle terrain halved leaves about 1 in 1000 facing down. The distance to
// the source cannot see that (every source vertex can still lie on the surface), so the build
// counts them and raises the group's error to the widest of its folded triangles, seen along
// the surface's normal (projected across its corners' normal: the smallest altitude, twice the
// area over the longest edge): the hole a fold leaves beside it has about its shape, and the
// selection then draws that level only where a gap that wide is invisible.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

// Triangles of `after` whose normal points against the summed area-weighted normals that
// `before`'s triangles give its three corners (a triangle turned over, or one spanning a crease
// so far that it faces away from every corner's surface). Both are triangle lists over the same
// vertices (positions_xyz, 3 floats each); `normals` is scratch. With `folded_corners`, the
// folded triangles' corners are appended to it.
struct Folds {
  std::size_t triangles = 0;
  double width_m = 0.0;  // the widest folded triangle's width, as above; 0: none
};
Folds find_folds(std::span<const float> positions_xyz, std::span<const std::uint32_t> before,
                 std::span<const std::uint32_t> after, std::vector<float>& normals,
                 std::vector<std::uint32_t>* folded_corners = nullptr);

// For a retry of the simplification that folded: locks the positions around the folds, the
// folded triangles' corners (`corners`, vertices of `before`) and every vertex of a `before`
// triangle touching one, so that nothing collapses into or across them: lock_position
// (meshopt_lock.hpp) on `positions_xyz`, whose first `vertex_count` vertices are `before`'s.
// `marks` is scratch. Returns the vertices locked.
std::size_t lock_around_folds(std::vector<float>& positions_xyz, std::size_t vertex_count,
                              std::span<const std::uint32_t> before, std::span<const std::uint32_t> corners,
                              std::vector<std::uint8_t>& marks);

}  // namespace gazelod::bake
