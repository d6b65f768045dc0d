// SPDX-License-Identifier: Apache-2.0
// One group's simplification in the cluster hierarchy build (bake/cluster/cluster_build.hpp, step 3)
// with meshoptimizer 0.18, on the group's own compact copy of its vertices:
//   - to about `simplify_ratio` of its triangles, at whatever error that takes;
//   - where meshopt gets there at no error (flat panels, a box's walls), on through every free
//     collapse, unless that folds wider than the step to the target did;
//   - where meshopt folds triangles over (bake/cluster_flips.hpp) wider than its own error
//     estimate, the same step again, up to `fold_retries` times, with the folds' surroundings
//     locked, kept while the widest fold narrows.
// Plain data in and out; the caller decides whether the result is a simplification at all
// (`stuck_ratio`) and splits it into clusters.
#pragma once

#include "bake/cluster_flips.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

struct GroupSimplifyOptions {
  double simplify_ratio = 0.5;  // the target share of the group's triangles
  double stuck_ratio = 0.85;    // a retry that keeps more than this share is not taken
  unsigned fold_retries = 2;
  bool lock_open_borders = false;  // meshopt_SimplifyLockBorder
};

// Buffers reused from group to group (one per thread).
struct GroupSimplifyScratch {
  std::vector<float> normals;
  std::vector<std::uint32_t> corners, kept;  // a retry's folded corners, the step before it
  std::vector<std::uint8_t> marks;
};

struct GroupSimplified {
  std::size_t index_count = 0;  // of `simplified`; 0: nothing simplified (too few triangles)
  Folds folds;                  // what the kept result folded over
};

// `indices`: the group's triangles over the first `vertex_count` vertices of positions_xyz (3
// floats each), after which any lock copies (bake/meshopt_lock.hpp) follow; retries append
// more, which the caller drops (resize to 3 * vertex_count) before using the positions again.
// `simplified` is resized to indices.size() and holds the result in its first index_count.
GroupSimplified simplify_group_triangles(std::vector<float>& positions_xyz, std::size_t vertex_count,
                                         std::span<const std::uint32_t> indices, const GroupSimplifyOptions& o,
                                         std::vector<std::uint32_t>& simplified, GroupSimplifyScratch& scratch);

}  // namespace gazelod::bake
