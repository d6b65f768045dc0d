// SPDX-License-Identifier: Apache-2.0
// One primitive's LOD chain with meshoptimizer (0.18 on Debian 12): every coarser level is
// simplified from the full-detail indices, so its error is measured against the original.
// meshopt 0.18 has no meshopt_simplifyWithAttributes: simplification is position-only, but it
// keeps attribute seams (vertices sharing a position with different UVs/normals) intact.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::bake {

struct ChainOptions {
  // Triangle ratio of each coarser level against level 0, strictly decreasing in (0, 1).
  std::vector<double> ratios{0.25, 0.0625, 0.015625};
  // Cap on meshopt's own error estimate, relative to the mesh extent (meshopt_simplifyScale);
  // 1 = the whole extent, i.e. no limit: the triangle ratio alone decides. The estimate is a
  // quadric mean: the measured error_m of a level can exceed the cap several times over.
  double target_error_rel = 1.0;
  // meshopt_SimplifyLockBorder: open borders (where a mesh's primitives meet, the rim of a
  // sheet) stay in place, so primitives do not crack apart; levels this blocks fall back to
  // meshopt_simplifySloppy, which does not keep them.
  bool lock_borders = false;
};

struct SimplifiedLevel {
  std::vector<std::uint32_t> indices;  // triangle list into the original vertices
  std::uint32_t vertices = 0;          // distinct vertices the indices use
  // The largest distance from a source vertex to the level's triangles, or the width of a
  // triangle meshopt folded over if larger (bake/cluster_flips.hpp), in the positions' units (a
  // running maximum over levels; the whole extent for an empty level), and over scale_m.
  double error_m = 0.0;
  double error_rel = 0.0;
  bool sloppy = false;               // reached with meshopt_simplifySloppy
  std::size_t folded_triangles = 0;  // facing against the source they replace
};

struct PrimitiveChain {
  double scale_m = 0.0;  // meshopt_simplifyScale: the largest extent of the positions
  // ratios.size() + 1 levels; level 0 is the input. A level that cannot get below the previous
  // one repeats it; a level may be empty when sloppy simplification removes everything.
  std::vector<SimplifiedLevel> levels;
};

// Validates the options; returns "" or a message naming the bad value.
std::string validate_chain_options(const ChainOptions& options);

// positions_xyz: 3 floats per vertex, all finite; indices: a triangle list (size % 3 == 0) with
// every index < vertex count. The caller checks both (mesh_extract does).
PrimitiveChain simplify_chain(std::span<const float> positions_xyz, std::span<const std::uint32_t> indices,
                              const ChainOptions& options);

}  // namespace gazelod::bake
