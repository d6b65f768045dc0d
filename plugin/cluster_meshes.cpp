// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes (see cluster_meshes.hpp).
#include "plugin/cluster_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace gazelod::plugin {

ClusterMeshes::ClusterMeshes()
    : selector_(std::min(kClusterThreads, std::max(1u, std::thread::hardware_concurrency()))) {}

std::uint32_t ClusterMeshes::add(const ClusterMeshDesc& desc) {
  const std::size_t first = instances_.size();
  const std::uint32_t hierarchy = instances_.add_hierarchy(desc.hierarchy, desc.index_count);
  const std::uint32_t id = instances_.add_instance(hierarchy, desc.pose, desc.velocity_m_s);
  const std::size_t n = instances_.size();
  first_.push_back(static_cast<std::uint32_t>(first));
  for (auto* v : {&perceptual_, &limited_, &invisible_, &drawn_, &held_, &record_held_}) v->resize(n, 0);
  self_window_s_.resize(n, 0.0);
  parent_window_s_.resize(n, 0.0);
  bytes_incremental_ = false;  // new clusters, and the arrays may have moved
  const lod::ClusterHierarchy& h = instances_.hierarchy(hierarchy);
  // A new mesh starts at its finest cut with no coarsening window open; its first frame then
  // draws its perceptual cut (nothing was drawn before, so there is no switch to hide).
  const std::size_t count = n - first;
  const lod::ClusterSwitchState state{std::span(record_held_).subspan(first, count),
                                      std::span(self_window_s_).subspan(first, count),
                                      std::span(parent_window_s_).subspan(first, count)};
  // The errors in the mesh's own space: which are 0 does not depend on the pose.
  const std::string err = lod::reset_cluster_switch_state(state, h.self_error_m, h.parent_error_m);
  if (!err.empty()) throw std::invalid_argument("gazelod plugin: cluster mesh: " + err);
  draw_finest(std::span(drawn_).subspan(first, count), first);
  new_from_ = std::min(new_from_, first);
  return id;
}

void ClusterMeshes::set_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s) {
  if (id >= instances_.instance_count())
    throw std::out_of_range("gazelod plugin: cluster mesh " + std::to_string(id) + " is not registered (" +
                            std::to_string(instances_.instance_count()) + " are)");
  try {
    instances_.set_pose(id, pose, velocity_m_s);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("gazelod plugin: cluster mesh " + std::to_string(id) + ": " + e.what());
  }
}

void ClusterMeshes::draw_finest(std::span<std::uint8_t> out, std::size_t first) const {
  for (std::uint32_t k = 0; k < instances_.instance_count(); ++k) {
    const lod::ClusterInstance& inst = instances_.instance(k);
    const lod::ClusterHierarchy& h = instances_.hierarchy(inst.hierarchy);
    if (inst.first_cluster < first || inst.first_cluster + h.size() > first + out.size()) continue;
    std::uint8_t* to = out.data() + (inst.first_cluster - first);
    for (std::size_t i = 0; i < h.size(); ++i)
      to[i] = (h.self_error_m[i] == 0.0f && h.parent_error_m[i] != 0.0f) ? 1 : 0;
  }
}

void ClusterMeshes::update(const lod::Viewer& viewer, const lod::SwitchPolicyConfig* policy, double t_s,
                           bool suppressed) {
  const std::size_t n = instances_.size();
  policy_used_ = policy != nullptr;
  if (n == 0) return;
  const lod::ClusterCutBytes out{perceptual_, limited_, invisible_, bytes_incremental_};
  bytes_incremental_ = selector_.select(viewer, instances_, out).empty();
  if (!bytes_incremental_) {
    // The core refused this frame's viewer: the finest cut rather than a guess.
    draw_finest(perceptual_, 0);
    std::fill(limited_.begin(), limited_.end(), static_cast<std::uint8_t>(lod::Criterion::invalid_input));
    std::copy(perceptual_.begin(), perceptual_.end(), drawn_.begin());
    std::fill(held_.begin(), held_.end(), 0);
    return;
  }
  if (policy == nullptr) return;
  // Meshes registered since the last frame: their first cut is the perceptual one.
  for (std::size_t i = new_from_; i < n; ++i) {
    record_held_[i] = invisible_[i];
    self_window_s_[i] = parent_window_s_[i] = lod::kNoSwitchWindow;
  }
  new_from_ = n;
  const lod::ClusterSwitchState state{record_held_, self_window_s_, parent_window_s_};
  if (!lod::apply_cluster_switch_policy(*policy, t_s, suppressed, invisible_, state, drawn_, held_).empty()) {
    std::copy(perceptual_.begin(), perceptual_.end(), drawn_.begin());
    std::fill(held_.begin(), held_.end(), 0);
  }
}

}  // namespace gazelod::plugin
