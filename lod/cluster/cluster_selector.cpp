// SPDX-License-Identifier: Apache-2.0
// The frame's cut over shared hierarchies on a thread pool (see cluster_selector.hpp).
#include "lod/cluster/cluster_selector.hpp"

#include "lod/cluster/cluster_select.hpp"

#include <algorithm>
#include <thread>

namespace gazelod::lod {

ClusterSelector::ClusterSelector(unsigned threads, std::size_t parallel_min_clusters)
    : threads_(threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency())),
      parallel_min_clusters_(parallel_min_clusters) {}

ClusterSelector::~ClusterSelector() = default;

void ClusterSelector::plan(const ClusterInstances& instances) {
  tasks_.clear();
  for (std::uint32_t k = 0; k < instances.instance_count(); ++k)
    for (std::uint32_t root : instances.bvh(instances.instance(k).hierarchy).task_roots) tasks_.push_back({k, root});
  outputs_.resize(tasks_.size());
  for (detail::BvhTaskOutput& o : outputs_) o.runs.clear();
  planned_for_ = &instances;
  planned_generation_ = instances.layout_generation();
  bytes_valid_ = false;
}

std::string ClusterSelector::select(const Viewer& viewer, const ClusterInstances& instances,
                                    const ClusterCutBytes& bytes, std::span<const double> detail_scale) {
  last_incremental_ = false;  // until this frame succeeds
  if (std::string e = validate_viewer(viewer); !e.empty()) return "viewer: " + e;
  if (std::string e = check_detail_scales(detail_scale, instances.instance_count()); !e.empty()) return e;
  const std::size_t n = instances.size();
  for (std::span<std::uint8_t> s : {bytes.drawn, bytes.limited_by, bytes.record_invisible})
    if (!s.empty() && s.size() < n)
      return "decisions: a byte output is shorter than the cluster count (" + std::to_string(n) + ")";
  if (planned_for_ != &instances || planned_generation_ != instances.layout_generation()) plan(instances);

  const detail::BvhBytes b{bytes.drawn.empty() ? nullptr : bytes.drawn.data(),
                           bytes.limited_by.empty() ? nullptr : bytes.limited_by.data(),
                           bytes.record_invisible.empty() ? nullptr : bytes.record_invisible.data()};
  // Only the bytes that change, where the arrays are the ones written last frame.
  const bool incremental = bytes.incremental && bytes_valid_ && b.drawn == last_bytes_.drawn &&
                           b.limited_by == last_bytes_.limited_by && b.record_invisible == last_bytes_.record_invisible;
  const bool share = threads_ > 1 && tasks_.size() > 1 && n >= parallel_min_clusters_;
  if (share && !pool_) pool_ = std::make_unique<ClusterThreadPool>(threads_);
  const std::size_t scratches = share ? pool_->threads() : 1;
  while (scratch_.size() < scratches) scratch_.push_back(std::make_unique<detail::BvhScratch>());

  auto job = [&](std::size_t t, unsigned thread) {
    const Task task = tasks_[t];
    detail::BvhTaskOutput& out = outputs_[t];
    const ClusterInstance& inst = instances.instance(task.instance);
    const ClusterBvh& bvh = instances.bvh(inst.hierarchy);
    detail::BvhFrames frames;
    const double scale = detail_scale.empty() ? 1.0 : detail_scale[task.instance];
    out.error = detail::make_bvh_frames(viewer, inst, bvh.finest_error_m, frames, scale);
    if (!out.error.empty()) {
      out.drawn.clear(), out.limited_by.clear(), out.runs.clear();
      return;
    }
    detail::select_bvh_subtree(bvh, task.root, frames, inst.first_cluster, b, incremental, *scratch_[thread], out);
  };
  // Writing every byte: a skipped cluster's first (a fill, far cheaper than per cluster), then
  // only the evaluated ones.
  if (b.any() && !incremental) detail::fill_skipped(b, 0, n);
  if (share)
    pool_->run(tasks_.size(), job);
  else
    for (std::size_t t = 0; t < tasks_.size(); ++t) job(t, 0);

  std::size_t total = 0;
  nodes_tested_ = clusters_evaluated_ = 0;
  for (std::size_t t = 0; t < tasks_.size(); ++t) {
    const detail::BvhTaskOutput& o = outputs_[t];
    if (!o.error.empty()) {
      bytes_valid_ = false;
      return "instance " + std::to_string(tasks_[t].instance) + ": viewer: " + o.error;
    }
    total += o.drawn.size();
    nodes_tested_ += o.nodes_tested, clusters_evaluated_ += o.clusters_evaluated;
  }
  drawn_.resize(total), limited_.resize(total);
  std::size_t at = 0;
  for (const detail::BvhTaskOutput& o : outputs_) {
    std::copy(o.drawn.begin(), o.drawn.end(), drawn_.begin() + static_cast<std::ptrdiff_t>(at));
    std::copy(o.limited_by.begin(), o.limited_by.end(), limited_.begin() + static_cast<std::ptrdiff_t>(at));
    at += o.drawn.size();
  }
  last_bytes_ = b;
  bytes_valid_ = b.any();
  last_incremental_ = incremental;
  return {};
}

void ClusterSelector::append_evaluated(const ClusterInstances& instances, std::vector<std::uint32_t>& out) const {
  for (std::size_t t = 0; t < tasks_.size() && t < outputs_.size(); ++t) {
    const ClusterInstance& inst = instances.instance(tasks_[t].instance);
    const ClusterBvh& bvh = instances.bvh(inst.hierarchy);
    const std::vector<std::uint32_t>& runs = outputs_[t].runs;
    for (std::size_t r = 0; r + 1 < runs.size(); r += 2)
      for (std::uint32_t j = runs[r]; j < runs[r + 1]; ++j) out.push_back(inst.first_cluster + bvh.cluster_id[j]);
  }
}

}  // namespace gazelod::lod
