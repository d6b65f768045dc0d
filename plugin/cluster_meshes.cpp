// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes (see cluster_meshes.hpp).
#include "plugin/cluster_meshes.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>

namespace gazelod::plugin {

ClusterMeshes::ClusterMeshes()
    : selector_(std::min(kClusterThreads, std::max(1u, std::thread::hardware_concurrency()))),
      budget_selector_(std::min(kClusterThreads, std::max(1u, std::thread::hardware_concurrency()))) {}

std::uint32_t ClusterMeshes::add(const ClusterMeshDesc& desc) {
  const std::size_t first = instances_.size();
  const std::uint32_t hierarchy = instances_.add_hierarchy(desc.hierarchy, desc.index_count);
  const std::uint32_t id = instances_.add_instance(hierarchy, desc.pose, desc.velocity_m_s);
  const std::size_t n = instances_.size();
  first_.push_back(static_cast<std::uint32_t>(first));
  for (auto* v : {&perceptual_, &limited_, &invisible_, &drawn_, &held_, &record_held_, &budget_drawn_,
                  &budget_limited_, &budget_invisible_, &final_drawn_, &final_limited_, &final_held_})
    v->resize(n, 0);
  budget_bytes_incremental_ = false;
  if (hierarchy == cut_cost_.size()) {  // a new hierarchy: its budget ladder and bound, once
    const lod::ClusterHierarchy& local = instances_.hierarchy(hierarchy);
    cut_cost_.emplace_back(local);
    Bound b;
    if (local.size() > 0) {
      constexpr double kInf = std::numeric_limits<double>::infinity();
      glm::dvec3 lo(kInf), hi(-kInf);
      for (std::size_t i = 0; i < local.size(); ++i) {
        const glm::dvec3 c(local.self_center_x_m[i], local.self_center_y_m[i], local.self_center_z_m[i]);
        lo = glm::min(lo, c - double(local.self_radius_m[i]));
        hi = glm::max(hi, c + double(local.self_radius_m[i]));
      }
      b.center = 0.5 * (lo + hi);
      for (std::size_t i = 0; i < local.size(); ++i) {
        const glm::dvec3 c(local.self_center_x_m[i], local.self_center_y_m[i], local.self_center_z_m[i]);
        b.radius = std::max(b.radius, glm::length(c - b.center) + double(local.self_radius_m[i]));
      }
    }
    bound_.push_back(b);
  }
  const std::size_t meshes = instances_.instance_count();
  for (auto* v : {&perceptual_tris_, &update_tris_, &drawn_tris_}) v->resize(meshes, 0.0);
  scale_.resize(meshes, 1.0);
  scale_f_.resize(meshes, 1.0f);
  steps_.resize(meshes, 0);
  elasticity_.resize(meshes);
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
    policy_state_valid_ = false;
    return;
  }
  if (policy == nullptr) {
    policy_state_valid_ = false;
    return;
  }
  // Meshes registered since the last frame: their first cut is the perceptual one.
  for (std::size_t i = new_from_; i < n; ++i) {
    record_held_[i] = invisible_[i];
    self_window_s_[i] = parent_window_s_[i] = lod::kNoSwitchWindow;
  }
  new_from_ = n;
  evaluated_.clear();
  selector_.append_evaluated(instances_, evaluated_);
  const std::string err = apply_policy(*policy, t_s, suppressed);
  std::swap(previous_evaluated_, evaluated_);
  policy_state_valid_ = err.empty();
  if (!err.empty()) {
    std::copy(perceptual_.begin(), perceptual_.end(), drawn_.begin());
    std::fill(held_.begin(), held_.end(), 0);
  }
}

// In time proportional to the change (the switch policy must not undo what the selector's
// bounding tree saves): a cluster's policy step changes nothing while its record bits equal its
// held bits, so only the clusters whose bits the selector may have rewritten (those it evaluated
// this frame or the last) and those left pending (a coarsening still held back) are stepped
// (lod::apply_cluster_switch_policy_listed). The full pass where that is not known: the first
// frame, after a refusal or a frame without the policy, or when the selector wrote every byte.
std::string ClusterMeshes::apply_policy(const lod::SwitchPolicyConfig& policy, double t_s, bool suppressed) {
  const lod::ClusterSwitchState state{record_held_, self_window_s_, parent_window_s_};
  const std::size_t n = instances_.size();
  if (!policy_state_valid_ || !selector_.last_select_incremental()) {
    std::string err = lod::apply_cluster_switch_policy(policy, t_s, suppressed, invisible_, state, drawn_, held_);
    policy_stepped_ = n;
    pending_.clear();
    for (std::size_t i = 0; i < n && err.empty(); ++i)
      if ((invisible_[i] & 3 & ~record_held_[i]) != 0) pending_.push_back(static_cast<std::uint32_t>(i));
    return err;
  }
  listed_mark_.resize(n, 0);  // all 0 between frames
  listed_.clear();
  for (const std::vector<std::uint32_t>* from : {&evaluated_, &previous_evaluated_, &pending_})
    for (std::uint32_t i : *from)
      if (i < n && listed_mark_[i] == 0) listed_mark_[i] = 1, listed_.push_back(i);
  for (std::uint32_t i : listed_) listed_mark_[i] = 0;
  next_pending_.clear();
  policy_stepped_ = listed_.size();
  std::string err = lod::apply_cluster_switch_policy_listed(policy, t_s, suppressed, invisible_, state, drawn_, held_,
                                                            listed_, next_pending_);
  std::swap(pending_, next_pending_);
  return err;
}

double ClusterMeshes::triangles_of(std::uint32_t mesh, std::span<const std::uint8_t> bytes) const {
  const lod::ClusterInstance& inst = instances_.instance(mesh);
  const lod::ClusterHierarchy& h = instances_.hierarchy(inst.hierarchy);
  const std::uint8_t* b = bytes.data() + inst.first_cluster;
  std::uint64_t indices = 0;
  for (std::size_t i = 0; i < h.size(); ++i) indices += b[i] != 0 ? h.index_count[i] : 0u;
  return static_cast<double>(indices / 3);
}

void ClusterMeshes::measure() {
  for (std::uint32_t m = 0; m < instances_.instance_count(); ++m) {
    perceptual_tris_[m] = triangles_of(m, perceptual_);
    update_tris_[m] = policy_used_ ? triangles_of(m, drawn_) : perceptual_tris_[m];
    drawn_tris_[m] = update_tris_[m];
  }
}

budget::BudgetClusterView ClusterMeshes::budget_view(std::uint32_t mesh, const glm::dvec3& eye_m, double px_per_deg,
                                                     double max_px) const {
  const lod::ClusterInstance& inst = instances_.instance(mesh);
  const Bound& b = bound_[inst.hierarchy];
  const glm::dvec3 center = inst.pose.translation_m + inst.pose.rotation * (b.center * inst.pose.scale);
  const double radius = b.radius * inst.pose.scale, d = glm::length(center - eye_m);
  // Angular radius of the bounding sphere; 90 degrees from inside it.
  const double radius_deg = d > radius ? std::asin(radius / d) * (180.0 / std::numbers::pi) : 90.0;
  const double r_px = radius_deg * px_per_deg;
  budget::BudgetClusterView v;
  const double px = std::numbers::pi * r_px * r_px;
  v.size_px = std::isfinite(px) ? std::min(px, max_px) : 0.0;
  v.importance = 1.0;
  cut_cost_[inst.hierarchy].predict_steps(perceptual_tris_[mesh], update_tris_[mesh], v.triangles,
                                          elasticity_[mesh].value);
  return v;
}

void ClusterMeshes::clear_steps() {
  budget_used_ = false;
  std::fill(steps_.begin(), steps_.end(), 0);
  std::fill(scale_.begin(), scale_.end(), 1.0);
  std::fill(scale_f_.begin(), scale_f_.end(), 1.0f);
  std::copy(update_tris_.begin(), update_tris_.end(), drawn_tris_.begin());
}

std::string ClusterMeshes::apply_steps(const lod::Viewer& viewer, std::span<const std::uint8_t> steps) {
  const std::size_t meshes = instances_.instance_count();
  clear_steps();
  if (steps.size() != meshes)
    return "cluster budget: " + std::to_string(steps.size()) + " steps for " + std::to_string(meshes) + " meshes";
  bool any = false;
  for (std::size_t m = 0; m < meshes; ++m) {
    const std::uint8_t k = std::min<std::uint8_t>(steps[m], budget::kClusterSteps - 1);
    steps_[m] = k;
    scale_[m] = budget::kClusterStepScale[k];
    scale_f_[m] = static_cast<float>(scale_[m]);
    any = any || k > 0;
  }
  if (!any) return {};
  const lod::ClusterCutBytes out{budget_drawn_, budget_limited_, budget_invisible_, budget_bytes_incremental_};
  std::string err = budget_selector_.select(viewer, instances_, out, scale_);
  budget_bytes_incremental_ = err.empty();
  if (!err.empty()) {
    clear_steps();  // update()'s cut rather than a guess
    return err;
  }
  // The final cut: update()'s for the meshes at step 0, the budget's for the others.
  const std::span<const std::uint8_t> kept = update_drawn();
  std::copy(kept.begin(), kept.end(), final_drawn_.begin());
  std::copy(limited_.begin(), limited_.end(), final_limited_.begin());
  std::copy(held_.begin(), held_.end(), final_held_.begin());
  for (std::uint32_t m = 0; m < meshes; ++m) {
    if (steps_[m] == 0) continue;
    const lod::ClusterInstance& inst = instances_.instance(m);
    const std::size_t first = inst.first_cluster, count = instances_.hierarchy(inst.hierarchy).size();
    std::copy_n(budget_drawn_.begin() + first, count, final_drawn_.begin() + first);
    std::copy_n(budget_limited_.begin() + first, count, final_limited_.begin() + first);
    std::fill_n(final_held_.begin() + first, count, 0);
    drawn_tris_[m] = triangles_of(m, budget_drawn_);
    // What this frame's cut says about how the mesh coarsens (for the next frames' prediction).
    elasticity_[m].update(
        cut_cost_[inst.hierarchy].observed_elasticity(perceptual_tris_[m], steps_[m], drawn_tris_[m]));
  }
  budget_used_ = true;
  return {};
}

}  // namespace gazelod::plugin
