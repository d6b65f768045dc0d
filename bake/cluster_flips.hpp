// Folds left by a group's simplification (bake/cluster_build.hpp, step 4). meshoptimizer 0.18's
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
// vertices (positions_xyz, 3 floats each); `normals` is scratch.
struct Folds {
  std::size_t triangles = 0;
  double width_m = 0.0;  // the widest folded triangle's width, as above; 0: none
};
Folds find_folds(std::span<const float> positions_xyz, std::span<const std::uint32_t> before,
                 std::span<const std::uint32_t> after, std::vector<float>& normals);

}  // namespace gazelod::bake
