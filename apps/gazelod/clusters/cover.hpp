// SPDX-License-Identifier: Apache-2.0
// Which cluster of a cut lies over each leaf (source cluster) of one cluster hierarchy
// (lod/cluster/cluster_hierarchy.hpp): what the per-cluster audit (clusters/audit.hpp) compares
// between the drawn cut and the oracle's, and the check that a cut covers every leaf exactly
// once (no crack, no overlap).
//
// The hierarchy stores no parent links, only two records per cluster; a record (bounds sphere
// and error) is shared bit for bit by the clusters of one group: as the parent record of the
// group's members and as the self record of the clusters its simplification produced
// (docs/bake.md). So groups are derived from record equality, once per mesh:
//   parent_group(c) = the group whose record is c's parent record (none at the top);
//   outputs(G)      = the clusters whose self record is G's record (depth > 0).
// The hierarchy is a DAG: the outputs of one group may go into different groups above. An
// upward path from a leaf L runs L, then any output of parent_group(L), then any output of that
// cluster's parent group, ... to a cluster without a parent. A cut (self record invisible,
// parent record not) is consistent exactly when every such path holds exactly one drawn
// cluster (along a path the invisible records form a prefix). The cluster "over" L is the
// coarsest drawn cluster on L's paths (largest self error; ties: the lowest index): a cut is
// no coarser than another over L when that error is no larger. Both need one pass over the
// groups per frame (parents before children), no allocation.
//
// Two groups with bit-identical records would be merged. The bake never writes one (a group
// that would repeat a member's record gets its radius one float step larger: bake/cluster/cluster_build.cpp);
// a file from another writer may: a cluster whose self record equals its parent record is
// never drawn (both records decide alike) and is left out of the graph.
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace gazelod::cli {

inline constexpr std::uint32_t kNoCluster = std::numeric_limits<std::uint32_t>::max();

// One leaf's cover in a cut.
struct LeafCover {
  std::uint32_t cluster = kNoCluster;  // the coarsest drawn cluster over the leaf; kNoCluster: none
  float self_error_m = -1.0f;          // its self error (mesh space); -1 when none
};

class ClusterCover {
 public:
  // Derives the group graph. Throws std::invalid_argument naming the cluster when the
  // hierarchy's arrays differ in length or its records do not form an acyclic graph.
  explicit ClusterCover(const lod::ClusterHierarchy& hierarchy);

  std::size_t cluster_count() const { return parent_group_.size(); }
  std::size_t group_count() const { return group_first_output_.size() - 1; }
  // The leaves (depth-0 clusters), ascending; leaf k of evaluate's outputs is cluster leaves()[k].
  std::span<const std::uint32_t> leaves() const { return leaves_; }
  // The derived group cluster c was merged into (0 .. group_count() - 1), -1 for none.
  std::int32_t parent_group(std::uint32_t c) const { return parent_group_.at(c); }

  // One cut: drawn[c] != 0 for the clusters drawn (this mesh's clusters only). Writes each
  // leaf's cover into `covers` (leaf_count() entries) and returns how many leaves are not
  // covered exactly once (0 for a consistent cut). Spans of other lengths: returns
  // leaf_count() and writes nothing. No allocation.
  std::size_t evaluate(std::span<const std::uint8_t> drawn, std::span<LeafCover> covers);

 private:
  struct Up {  // what lies above: the coarsest drawn cluster and the drawn count per path
    LeafCover cover;
    std::uint32_t min_drawn = 0, max_drawn = 0;
  };
  Up above(std::uint32_t cluster, std::span<const std::uint8_t> drawn) const;

  std::vector<float> self_error_;
  std::vector<std::int32_t> parent_group_;         // per cluster; -1: no parent (or left out)
  std::vector<std::uint32_t> group_first_output_;  // CSR over outputs_, group_count() + 1
  std::vector<std::uint32_t> outputs_;
  std::vector<std::uint32_t> order_;  // groups, every parent group before its children's
  std::vector<std::uint32_t> leaves_;
  std::vector<Up> group_up_;  // per frame, per group
};

}  // namespace gazelod::cli
