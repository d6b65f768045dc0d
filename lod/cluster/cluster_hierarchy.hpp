// SPDX-License-Identifier: Apache-2.0
// One mesh's cluster hierarchy as plain data (structure of arrays, one entry per cluster), the
// form `gazelod bake --clusters` writes and the per-cluster selection (lod/cluster/cluster_select.hpp)
// reads. The hierarchy follows the cluster-DAG construction of Karis et al. 2021 (Nanite) and
// meshoptimizer's cluster-LOD demo: clusters of the source mesh are grouped with neighbours,
// each group is simplified with its outer border locked and split into new clusters, and so on
// to a root.
//
// Every cluster carries two bounds-with-error records:
//   self   - the group simplification that produced the cluster (shared by every cluster that
//            came out of it); error 0 and the cluster's own bounds for source clusters;
//   parent - the group the cluster was merged into and simplified (shared by every cluster of
//            that group); error kNoParentError for clusters no group simplified further.
// A cluster is in the drawn cut when its self error is invisible and its parent error is not.
// The cut is consistent (no cracks, no overlaps) when both errors and both bounds are the
// same for all members of a group and are monotone up the hierarchy:
//   self_error <= parent_error, and the parent sphere contains the self sphere.
// Positions and errors are in the mesh's own space (metres after the node's transform when the
// caller has applied it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace gazelod::lod {

// Parent error of a cluster no group simplified further: never invisible, so such a cluster
// is drawn whenever its self error is invisible.
inline constexpr float kNoParentError = std::numeric_limits<float>::infinity();

struct ClusterHierarchy {
  // self bounds (sphere) and error, metres
  std::vector<float> self_center_x_m, self_center_y_m, self_center_z_m, self_radius_m, self_error_m;
  // parent bounds (sphere) and error, metres; kNoParentError for the hierarchy's top
  std::vector<float> parent_center_x_m, parent_center_y_m, parent_center_z_m, parent_radius_m, parent_error_m;
  // The cluster's triangles: index_count indices from first_index in the mesh's index buffer
  // (triangle list, so index_count is a multiple of 3).
  std::vector<std::uint32_t> first_index, index_count;
  // 0 for clusters of the source mesh, +1 per simplification step (for tints and reports).
  std::vector<std::uint8_t> depth;

  std::size_t size() const { return self_error_m.size(); }
};

}  // namespace gazelod::lod
