// SPDX-License-Identifier: Apache-2.0
// A bounding hierarchy over one cluster hierarchy's groups, so that a frame's selection visits
// work in proportion to its cut instead of every cluster (lod/cluster/cluster_select_bvh.hpp).
//
// The idea is Nanite's (Karis et al. 2021, "culling the DAG"): the cut is decided per cluster
// by its two records alone, so the clusters can be put in any spatial tree; a tree node that
// proves every cluster below it undrawn lets the traversal skip them all. Here a cluster is
// drawn iff its self record is invisible and its parent record is visible
// (lod/cluster/cluster_select.hpp), and a parent record invisible implies the self record
// invisible (the nesting). So each node carries a sphere enclosing every PARENT sphere of the
// clusters below it and the largest parent error below it: by the rule's monotonicity (a
// containing sphere has a nearer nearest point, a nearer nearest-point eccentricity and no faster
// slowest point; a larger error is harder to hide) a node whose record is invisible has every
// parent record below it invisible, so no cluster below it is drawn (cluster_select_bvh.cpp has
// the margins that make this hold for the float kernel too).
//
// Layout, as Nanite's: the groups (a group = the clusters sharing one parent record) are split
// into bands of similar error (a power of two; error 0 and kNoParentError apart), a tree is
// built over each band's groups by median splits along the longest axis (up to 8 children per
// node, up to kBvhLeafGroups groups per leaf), and one root holds the bands' trees. Nodes of one
// band have similar errors and sizes, so a node's largest error is close to every error below
// it and its sphere is not much larger than theirs: the test stays tight. Built once per
// distinct hierarchy, in the hierarchy's own space (instances share it).
//
// The clusters are listed in depth-first leaf order (each node's clusters are one range), each
// group's members together, with their records in a table laid out the same way: per group its
// parent record, then its members' distinct self records (equal self records of one group, the
// outputs of one simplification, stored once), so that a node's records are one range too and a
// visited leaf evaluates each of its records once (select_clusters' distinct-record path).
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::lod {

inline constexpr std::size_t kBvhLeafGroups = 4;  // groups per leaf, at most
inline constexpr std::size_t kBvhTaskClusters = 1
                                                << 18;  // clusters per unit of parallel work, at most (see task_roots)
// A node's error is its largest parent error times this, rounded up (cluster_select_bvh.cpp says
// why 1 % covers the float kernel's rounding).
inline constexpr double kBvhNodeErrorMargin = 1.01;

struct ClusterBvh {
  // Per cluster in leaf order: its index in the hierarchy and its two records' rows in the table.
  std::vector<std::uint32_t> cluster_id, self_record, parent_record;
  // The records (local space), group by group in leaf order.
  std::vector<float> record_center_x_m, record_center_y_m, record_center_z_m, record_radius_m, record_error_m;
  // Per node (node 0 is the root): a sphere enclosing every parent sphere below, the largest
  // parent error below times kBvhNodeErrorMargin (rounded up; +inf where a cluster below has no
  // parent), its children (nodes [child_first, + child_count), none for a leaf), its clusters
  // (leaf order [first_cluster, + cluster_count)) and their records (rows [first_record, +
  // record_count)).
  std::vector<float> node_center_x_m, node_center_y_m, node_center_z_m, node_radius_m, node_error_m;
  std::vector<std::uint32_t> node_child_first, node_child_count, node_first_cluster, node_cluster_count;
  std::vector<std::uint32_t> node_first_record, node_record_count;
  // Nodes whose cluster ranges tile every cluster, in leaf order, each at most task_clusters
  // (build_cluster_bvh) clusters or a leaf: the units a frame's selection hands to threads (the root alone for a
  // hierarchy of at most kBvhTaskClusters clusters).
  std::vector<std::uint32_t> task_roots;
  double finest_error_m = 0.0;  // finest_cluster_error_m of the hierarchy

  std::size_t size() const { return cluster_id.size(); }
  std::size_t record_count() const { return record_error_m.size(); }
  std::size_t node_count() const { return node_error_m.size(); }
  bool is_leaf(std::uint32_t node) const { return node_child_count[node] == 0; }
  std::size_t memory_bytes() const;  // capacity of every array
};

// The tree over a hierarchy that validate_cluster_hierarchy accepts (not checked here: the
// nesting the skip relies on is what it validates). Linear in clusters times the tree's depth.
// task_clusters: the task roots' size limit (kBvhTaskClusters; smaller in tests).
ClusterBvh build_cluster_bvh(const ClusterHierarchy& hierarchy, std::size_t task_clusters = kBvhTaskClusters);

// "" when every node's sphere contains (in double) the parent spheres of its clusters, its error
// is no smaller than theirs, the children's ranges tile their parent's, the leaf order is a
// permutation of the clusters with their records, and the task roots tile the clusters; else
// the first fault. For tests.
[[nodiscard]] std::string check_cluster_bvh(const ClusterBvh& bvh, const ClusterHierarchy& hierarchy);

}  // namespace gazelod::lod
