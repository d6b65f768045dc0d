// SPDX-License-Identifier: Apache-2.0
// Simplifying a cluster group across attribute seams (bake/cluster/cluster_build.hpp, `stuck_across_seams`).
// A seam is a position several vertices share with different normals or texture coordinates:
// a CAD part's hard edge, a UV island's rim. meshoptimizer 0.18 keeps such a seam intact (it
// collapses a seam vertex only along the seam, and not at all where seams meet), which on a
// CAD model stops the hierarchy at a third to half of the source (2CylinderEngine's largest
// parts). Simplified on welded positions instead, a group reaches its target; each new
// triangle's corners are then given back a copy of their position: the copy whose source
// triangles face the way the new triangle does (within kSameFacingCos) and, among those, lie
// nearest it (a UV seam on a smooth surface: the side the triangle is on). Where more than
// kAllCopiesUpTo vertices share the position (a flat-shaded fan's apex), only the copies the
// group's own triangles use are candidates, which keeps the work per corner bounded. Positions are
// unchanged, so the geometry, its measured error and its borders are the same as if the copies
// were one vertex; only which copy's attributes a corner shows is chosen here.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

class SeamCopies {
 public:
  // weld: vertex -> its position's representative (cluster_source.hpp, weld_positions);
  // source: the source triangle list (degenerate triangles are skipped).
  SeamCopies(std::span<const float> positions_xyz, std::span<const std::uint32_t> weld,
             std::span<const std::uint32_t> source);

  // Positions that more than one vertex of the source's triangles uses.
  std::size_t seam_positions() const { return seam_positions_; }
  // How many vertices of the source's triangles have representative `welded`'s position.
  std::uint32_t copies(std::uint32_t welded) const { return first_[welded + 1] - first_[welded]; }

  // The candidates: the copies `group` (a triangle list of source vertices) uses, as sorted
  // (representative << 32 | copy slot) pairs in `pairs` (replaced).
  void collect(std::span<const std::uint32_t> group, std::vector<std::uint64_t>& pairs) const;

  // triangles: a triangle list of welded representatives, rewritten in place to copies (of a
  // position with many, among `pairs`, collect(); none there: its first used vertex).
  void choose(std::span<std::uint32_t> triangles, std::span<const std::uint64_t> pairs) const;

 private:
  std::span<const float> pos_;
  std::span<const std::uint32_t> weld_;
  // Per representative: its used copies at copies_[first_[w]] .. first_[w + 1].
  std::vector<std::uint32_t> first_, copies_;
  std::vector<std::uint32_t> slot_;  // per vertex: its entry in copies_ (UINT32_MAX: unused)
  // Per entry of copies_: the area-weighted normal sum and the centroid sum (with count) of the
  // source triangles using that copy.
  std::vector<float> normal_sum_, centroid_sum_;
  std::vector<std::uint32_t> triangles_of_;
  std::size_t seam_positions_ = 0;
};

}  // namespace gazelod::bake
