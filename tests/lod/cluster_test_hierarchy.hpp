// SPDX-License-Identifier: Apache-2.0
// Synthetic cluster hierarchies for the cluster-selection tests, built the way a bake would:
// source clusters (error 0, their own spheres) over a line or a grid, grouped by 2 (line) or
// 4 (grid) per level, each group's record enclosing its members' spheres with an error no
// smaller than theirs, and each group producing one or more clusters that carry the group's
// record as self and the record of the group they join as parent. Plus the coverage check of
// a cut over that tree.
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace gazelod::lod::test {

struct TreeSpec {
  int levels = 6;                   // groups above the source clusters
  bool grid = false;                // 4 per group over a square grid, else 2 per group over a line
  int outputs_per_group = 1;        // clusters a group produces (source clusters: always 1)
  double spacing_m = 0.4;           // between source clusters
  double leaf_error_m = 0.0005;     // scale of the first group's error
  double equal_error_chance = 0.1;  // a group's error equal to its largest member's
};

struct TestTree {
  ClusterHierarchy h;
  // Node n (a source cluster or a group): its parent node (-1 at the top), its clusters.
  std::vector<int> node_parent;
  std::vector<std::vector<std::uint32_t>> node_clusters;
  std::vector<int> cluster_node;
  std::vector<int> leaves;  // the source nodes
};

TestTree make_tree(const TreeSpec& spec, std::uint64_t seed);

// "" when drawn is a consistent cut of the tree: every node's clusters agree, and exactly one
// node on every leaf's path to the top is drawn; else the first leaf or node at fault.
std::string check_cut(const TestTree& tree, std::span<const std::uint8_t> drawn);

// Per leaf, the level (0 = the source cluster) of the node drawn over it; -1 if none.
std::vector<int> cut_levels(const TestTree& tree, std::span<const std::uint8_t> drawn);

}  // namespace gazelod::lod::test
