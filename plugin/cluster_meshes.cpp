// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes (see cluster_meshes.hpp).
#include "plugin/cluster_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gazelod::plugin {

std::uint32_t ClusterMeshes::add(const ClusterMeshDesc& desc) {
  const std::size_t first = store_.size();
  const std::uint32_t id = store_.add_mesh(desc.hierarchy, desc.pose, desc.velocity_m_s, desc.index_count);
  const std::size_t n = store_.size();
  first_.push_back(static_cast<std::uint32_t>(first));
  local_.push_back(desc.hierarchy);
  for (auto* v : {&perceptual_, &limited_, &invisible_, &drawn_, &held_, &record_held_}) v->resize(n, 0);
  record_flags_.resize(store_.record_count(), 0);
  self_window_s_.resize(n, 0.0);
  parent_window_s_.resize(n, 0.0);
  const lod::ClusterSet set = store_.view();
  // A new mesh starts at its finest cut with no coarsening window open; its first frame then
  // draws its perceptual cut (nothing was drawn before, so there is no switch to hide).
  const std::size_t count = n - first;
  const lod::ClusterSwitchState state{std::span(record_held_).subspan(first, count),
                                      std::span(self_window_s_).subspan(first, count),
                                      std::span(parent_window_s_).subspan(first, count)};
  const std::string err = lod::reset_cluster_switch_state(state, set.self_error_m.subspan(first, count),
                                                          set.parent_error_m.subspan(first, count));
  if (!err.empty()) throw std::invalid_argument("gazelod plugin: cluster mesh: " + err);
  draw_finest(std::span(drawn_).subspan(first, count), first);
  new_from_ = std::min(new_from_, first);
  return id;
}

void ClusterMeshes::set_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s) {
  if (id >= local_.size())
    throw std::out_of_range("gazelod plugin: cluster mesh " + std::to_string(id) + " is not registered (" +
                            std::to_string(local_.size()) + " are)");
  try {
    store_.set_pose(id, local_[id], pose, velocity_m_s);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("gazelod plugin: cluster mesh " + std::to_string(id) + ": " + e.what());
  }
}

void ClusterMeshes::draw_finest(std::span<std::uint8_t> out, std::size_t first) const {
  const lod::ClusterSet set = store_.view();
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = (set.self_error_m[first + i] == 0.0f && set.parent_error_m[first + i] != 0.0f) ? 1 : 0;
}

void ClusterMeshes::update(const lod::Viewer& viewer, const lod::SwitchPolicyConfig* policy, double t_s,
                           bool suppressed) {
  const std::size_t n = store_.size();
  policy_used_ = policy != nullptr;
  if (n == 0) return;
  const lod::ClusterSet set = store_.view();
  const lod::ClusterDecisions out{perceptual_, limited_, {}, {}, {}, invisible_, record_flags_};
  if (!lod::select_clusters(viewer, set, out).empty()) {
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
