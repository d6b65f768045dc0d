// SPDX-License-Identifier: Apache-2.0
// One unit of the bounding-hierarchy selection (cluster_selector.hpp runs them, on threads):
// the cut of one instance below one node of its hierarchy's tree (lod/cluster/cluster_bvh.hpp),
// in the instance's space (lod/cluster/cluster_local_view.hpp).
//
// The tree is walked breadth first, each level's nodes tested as one block of records by the
// float kernel (lod/cluster/cluster_select_kernel.hpp); a node whose record is invisible is
// skipped with every cluster below it (none of them drawn, both their records invisible); the
// clusters of the leaves left are evaluated exactly as select_clusters' linear pass over
// distinct records evaluates them (each record once, then every cluster from its two records'
// outcomes), so their outputs are bit for bit the linear pass's. See cluster_select_bvh.cpp for why a
// skipped node has no drawn cluster below it in the float kernel too.
#pragma once

#include "lod/cluster/cluster_bvh.hpp"
#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_select_kernel.hpp"
#include "lod/select.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::lod::detail {

// Node records are tested against the viewer with every velocity scaled by this (eye, mesh and
// both angular velocities): G(v) is then higher by at least 0.047 cycles/deg wherever it is on
// its slope, which covers the kernel's absolute slack in G where G falls towards 0.
inline constexpr double kBvhNodeVelocityFactor = 1.0 - 0x1p-8;

// One instance's kernel constants: its clusters' (select_clusters' own, in its space) and its
// nodes' (the same viewer with kBvhNodeVelocityFactor applied).
struct BvhFrames {
  ClusterFrame frame, node_frame;
  ClusterMeshFrame mesh, node_mesh;
};
// "" or why not (local_view's refusal). detail_scale: the instance's, in [1, 1e6] (1: the
// perceptual cut), applied to its nodes and clusters alike (ClusterMeshFrame::error_factor).
[[nodiscard]] std::string make_bvh_frames(const Viewer& world, const ClusterInstance& instance, double finest_error_m,
                                          BvhFrames& out, double detail_scale = 1.0);

// Per-cluster outputs indexed by global cluster id, each null or covering every cluster.
struct BvhBytes {
  std::uint8_t *drawn = nullptr, *limited_by = nullptr, *record_invisible = nullptr;
  bool any() const { return drawn != nullptr || limited_by != nullptr || record_invisible != nullptr; }
};

// One unit's results, reused from frame to frame (the vectors only grow).
struct BvhTaskOutput {
  std::vector<std::uint32_t> drawn;      // global cluster ids of the cut, in leaf order
  std::vector<std::uint8_t> limited_by;  // per entry of drawn (Criterion)
  // The leaf-order ranges evaluated, as begin, end pairs: the only clusters whose bytes differ
  // from a skipped cluster's (what an incremental frame resets).
  std::vector<std::uint32_t> runs;
  std::size_t nodes_tested = 0, clusters_evaluated = 0;
  std::string error;  // the instance's refusal, if any
};

// Per thread: the traversal's lists and the kernel's blocks.
struct BvhScratch {
  std::vector<std::uint32_t> frontier, next, leaves, rows, previous_runs;
  std::vector<std::uint32_t> flags;  // per record row of the hierarchy: its packed outcomes
  RecordBlock node_block, record_block;
  float node_x[kClusterBlock], node_y[kClusterBlock], node_z[kClusterBlock], node_r[kClusterBlock],
      node_e[kClusterBlock];
  std::uint32_t tested[kClusterBlock];
  std::uint8_t drawn[kClusterBlock], why[kClusterBlock], bits[kClusterBlock];
};

// The cut below `root` for one instance (clusters numbered from first_cluster) into out (its
// lists replaced, its runs replaced by this frame's). With bytes: the evaluated clusters'
// outputs written; every other cluster below root must already hold a skipped cluster's (drawn
// 0, Criterion::none, record_invisible 3), except, with previous_bytes, those of out.runs as
// passed in (the previous frame's), which are set back to it here where not evaluated again.
void select_bvh_subtree(const ClusterBvh& bvh, std::uint32_t root, const BvhFrames& frames, std::uint32_t first_cluster,
                        const BvhBytes& bytes, bool previous_bytes, BvhScratch& scratch, BvhTaskOutput& out);

// Every byte of a skipped cluster (see select_bvh_subtree) over clusters [begin, end).
void fill_skipped(const BvhBytes& bytes, std::size_t begin, std::size_t end);

}  // namespace gazelod::lod::detail
