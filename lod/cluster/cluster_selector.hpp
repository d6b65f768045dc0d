// SPDX-License-Identifier: Apache-2.0
// The frame's cluster cut over shared hierarchies (lod/cluster/cluster_instances.hpp), in time
// proportional to the cut: each instance is evaluated in its own space through its hierarchy's
// bounding tree (lod/cluster/cluster_select_bvh.hpp), which skips every subtree it proves
// undrawn, on a fixed pool of threads.
//
//   ClusterInstances instances;  ... add_hierarchy / add_instance at registration
//   ClusterSelector selector(threads);
//   per frame: std::string err = selector.select(viewer, instances, bytes);  // "" on success
//              for (std::uint32_t id : selector.drawn()) draw cluster id;
//
// The cut is select_clusters_local's (cluster_local_view.hpp) bit for bit: the same clusters
// drawn, the same limiting criterion, the same record bits, on any number of threads (the
// work is split into units, each instance below one of its tree's task roots, whose outputs are
// concatenated in a fixed order). It has no per-criterion cuts: callers that need them run
// select_clusters_local.
//
// Outputs: drawn() lists the cut (global cluster ids, instance by instance in registration
// order, within an instance in its tree's leaf order, not ascending) with drawn_limited_by();
// both stay valid until the next select. Optionally per-cluster bytes, as ClusterDecisions'
// drawn, limited_by and record_invisible (each empty or covering every cluster): writing every
// byte is linear in the clusters (a memory fill), so a caller that passes the same arrays frame
// after frame and writes nothing into them may say so (ClusterCutBytes::incremental): then only
// the bytes that can change are written (the clusters evaluated now or in the previous frame).
// A frame after a new instance, a refusal, or with other arrays writes them all anyway.
// Per frame: no allocation once the lists have grown to the cut's size.
#pragma once

#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_select_bvh.hpp"
#include "lod/cluster/cluster_thread_pool.hpp"
#include "lod/select.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace gazelod::lod {

struct ClusterCutBytes {
  std::span<std::uint8_t> drawn, limited_by, record_invisible;
  // The arrays of the previous select (the same data pointers), nothing written into them since.
  bool incremental = false;
};

// Below this many clusters a frame runs on the calling thread only (waking the pool costs more).
inline constexpr std::size_t kClusterParallelMinClusters = 100'000;

class ClusterSelector {
 public:
  // threads: how many run a frame's selection, the caller's among them (0: one per hardware
  // thread); the extra threads start at the first frame that shares its work (one with at least
  // parallel_min_clusters clusters and two units), and live as long as the selector.
  explicit ClusterSelector(unsigned threads = 1, std::size_t parallel_min_clusters = kClusterParallelMinClusters);
  ~ClusterSelector();
  ClusterSelector(const ClusterSelector&) = delete;
  ClusterSelector& operator=(const ClusterSelector&) = delete;

  // One frame. Refuses (with a message) an invalid viewer, byte spans shorter than the cluster
  // count, or an instance whose space cannot hold the eye (cluster_local_view.hpp); after a
  // refusal the outputs are unspecified (the next frame writes every byte).
  // detail_scale: empty (every instance's perceptual cut) or one value in [1, 1e6] per instance
  // (ClusterSet::mesh_detail_scale: a frame budget's coarsening step; refused otherwise); the
  // cut is then select_clusters_local's with the same scales, bit for bit.
  [[nodiscard]] std::string select(const Viewer& viewer, const ClusterInstances& instances,
                                   const ClusterCutBytes& bytes = {}, std::span<const double> detail_scale = {});

  std::span<const std::uint32_t> drawn() const { return drawn_; }
  // Whether the last select() wrote only what changed (ClusterCutBytes::incremental honoured):
  // then its byte outputs differ from the frame before only at the clusters it evaluated and
  // those the frame before evaluated (append_evaluated's lists of the two frames).
  bool last_select_incremental() const { return last_incremental_; }
  // Appends the global ids of the clusters the last select() evaluated (in time proportional to
  // them); `instances` as passed to it.
  void append_evaluated(const ClusterInstances& instances, std::vector<std::uint32_t>& out) const;
  std::span<const std::uint8_t> drawn_limited_by() const { return limited_; }
  // The last frame's work: node records tested and clusters evaluated.
  std::size_t nodes_tested() const { return nodes_tested_; }
  std::size_t clusters_evaluated() const { return clusters_evaluated_; }
  unsigned threads() const { return threads_; }

 private:
  struct Task {
    std::uint32_t instance, root;
  };
  void plan(const ClusterInstances& instances);

  unsigned threads_;
  std::size_t parallel_min_clusters_;
  std::unique_ptr<ClusterThreadPool> pool_;
  std::vector<std::unique_ptr<detail::BvhScratch>> scratch_;  // one per thread
  std::vector<Task> tasks_;
  std::vector<detail::BvhTaskOutput> outputs_;  // one per task
  std::vector<std::uint32_t> drawn_;
  std::vector<std::uint8_t> limited_;
  std::size_t nodes_tested_ = 0, clusters_evaluated_ = 0;
  // What the task list and the bytes were made for.
  const ClusterInstances* planned_for_ = nullptr;
  std::uint64_t planned_generation_ = 0;
  detail::BvhBytes last_bytes_;
  bool bytes_valid_ = false;
  bool last_incremental_ = false;
};

}  // namespace gazelod::lod
