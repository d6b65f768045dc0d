// SPDX-License-Identifier: Apache-2.0
// One mesh's cluster hierarchy (lod/cluster/cluster_hierarchy.hpp) with meshoptimizer 0.18, after
// Karis et al. 2021 (Nanite) and meshoptimizer's cluster-LOD demo:
//   1. the source triangles are split into clusters (bake/cluster/cluster_split.hpp);
//   2. neighbouring clusters are grouped (bake/cluster/cluster_group.hpp);
//   3. each group's triangles are simplified to about half with every vertex another group of
//      the level also uses locked, so the border between groups stays vertex for vertex what
//      the neighbours see (no crack); the mesh's own open border (an edge one triangle uses: a
//      terrain's rim, a building's open base) is simplified along itself like any other detail,
//      unless `lock_open_borders`;
//   4. the result is split into new clusters, which go back to step 2;
// until one cluster is left or no group simplifies any more (a group that keeps more than
// `stuck_ratio` of its triangles, also across its attribute seams when `stuck_across_seams`, is
// not simplified: its clusters are the top of the hierarchy, parent error kNoParentError).
// Errors in the positions' units (metres), measured against the SOURCE, not summed per level:
// every vertex of a kept source triangle (one per welded position) is owned by one cluster of
// each level it reaches; a group owns what its members own and hands each vertex to the new
// cluster holding the triangle found for it (bake/cluster_distance.hpp: its nearest, or the
// first one no farther than the group's error so far). A group's error is the largest distance
// from its vertices to those triangles, raised to the largest self error of its members (so
// parent error >= every member's self error) and to the width of any triangle meshopt
// folded over (bake/cluster_flips.hpp), computed in double and rounded up to float.
// What it bounds: in any cut (clusters with self error <= t < parent error) every such source
// vertex lies within the largest self error of the drawn clusters, hence within t, of the drawn
// triangles. The source is sampled at its vertices (a source triangle's interior is not
// measured); meshopt's own error estimate (an area-weighted quadric mean, not a maximum, which
// fell below the true distance at fine levels) is not used. The group's sphere encloses every
// member's self sphere. Source clusters: their own sphere, error 0.
// The vertex buffer is the input's (simplification only drops vertices): `indices` refer to it.
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::bake {

inline constexpr unsigned kMaxFoldRetries = 8;

struct ClusterBuildOptions {
  std::size_t max_vertices = 64;    // per cluster, 3..255 (bake/cluster/cluster_split.hpp)
  std::size_t max_triangles = 124;  // per cluster, 4..512 and a multiple of 4 (meshopt 0.18)
  std::size_t group_size = 8;       // clusters per group, >= 2
  double simplify_ratio = 0.5;      // each group is simplified to this share of its triangles
  double stuck_ratio = 0.85;        // more than this share left: the group does not simplify
  unsigned threads = 0;             // source chunks, groups and slices in parallel; 0: all cores; same result for any
  // A group meshopt 0.18 folded is simplified again, up to this many times, with the folds'
  // surroundings locked (bake/cluster_flips.hpp, lock_around_folds); 0..kMaxFoldRetries.
  unsigned fold_retries = 2;
  // true: a group that does not simplify with its attribute seams kept (positions several
  // vertices share with different normals or UVs: meshopt 0.18 keeps them, which stopped CAD
  // parts' hierarchies at a third to half of their triangles) is simplified again across them,
  // each new corner taking back the copy from its triangle's side (bake/cluster/seam_copies.hpp).
  bool stuck_across_seams = true;
  // true: every open border stays at source resolution too (meshopt_SimplifyLockBorder), for
  // parts whose rims meet geometry the bake cannot see.
  bool lock_open_borders = false;
  // Empty, or one per input vertex: nonzero keeps that position at every level (a border
  // shared with another primitive: bake/cluster/shared_positions.hpp).
  std::span<const std::uint8_t> locked_vertices;
  std::string label = "mesh";  // names the mesh in error messages
};

struct ClusterBuildResult {
  lod::ClusterHierarchy hierarchy;
  // Every cluster's triangles, all levels, at hierarchy.first_index / index_count.
  std::vector<std::uint32_t> indices;
  // Per cluster: the group it was merged into and the group that produced it (-1: none, i.e.
  // top of the hierarchy / source cluster). Groups are numbered in build order.
  std::vector<std::int32_t> parent_group, source_group;
  std::size_t groups = 0;                // groups that were simplified
  std::size_t groups_across_seams = 0;   // of those, across their attribute seams (stuck_across_seams)
  std::uint32_t levels = 0;              // largest depth + 1; 0 for an empty mesh
  std::size_t source_triangles = 0;      // input triangles that were kept
  std::size_t degenerate_triangles = 0;  // dropped: two corners at the same position
  // Stored triangles of simplified levels that meshopt folded over (bake/cluster_flips.hpp):
  // a known meshoptimizer 0.18 defect, counted so that a bake says how much of it it holds; each
  // such group's error is at least the width of its folded triangles.
  std::size_t folded_triangles = 0;
  // Wall seconds per phase, for finding where a build's time goes (the bench prints them).
  struct Phases {
    double weld_s = 0.0;             // welding and cutting the source into chunks
    double source_clusters_s = 0.0;  // splitting the chunks into clusters
    double grouping_s = 0.0;         // every level's grouping (one thread)
    double shared_s = 0.0;           // every level's shared-vertex marks
    double groups_s = 0.0;           // simplifying, splitting and measuring the groups
    double sliced_measure_s = 0.0;   // of that, the few-group levels' measures in slices
  } phases;
};

// "" or a message naming the bad option.
std::string validate_cluster_options(const ClusterBuildOptions& options);

// positions_xyz: 3 floats per vertex; indices: a triangle list. Throws BakeError
// "<label>: ..." for bad options, a position that is not finite ("vertex 12 ..."), an index out
// of range ("index 7 is 40, but there are only 30 vertices"), an index count that is not a
// multiple of 3 or locked_vertices of the wrong size. Degenerate triangles are dropped and counted. No triangles left:
// an empty hierarchy. At most one cluster's worth: one cluster, depth 0, parent error kNoParentError.
ClusterBuildResult build_cluster_hierarchy(std::span<const float> positions_xyz, std::span<const std::uint32_t> indices,
                                           const ClusterBuildOptions& options = {});

}  // namespace gazelod::bake
