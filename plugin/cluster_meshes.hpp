// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes (LodPlugin::add_cluster_mesh): instances of shared hierarchies
// (lod::ClusterInstances: a mesh whose hierarchy equals, bit for bit, one registered before,
// as a glTF mesh placed by several nodes, shares it and costs a pose), each frame's perceptual
// cut (lod::ClusterSelector: each mesh in its own space through its hierarchy's bounding tree,
// in time proportional to the cut, on up to kClusterThreads threads; the same cut as
// lod::select_clusters_local) and the cut drawn after the switch policy
// (lod::apply_cluster_switch_policy_listed: only the clusters the selector evaluated this frame
// or the last and those still held back are stepped, so the frame stays proportional to the
// cut), in arrays the plugin hands out as FrameDecisions::cluster_*.
// All allocation happens at registration (and in the first frames, while the cut's lists grow).
//
// With a frame budget (docs/cluster-budget.md), each mesh is an item of the budget's MCKP: after
// update(), measure() counts each mesh's triangles and budget_view() predicts every coarsening
// step's (budget/cluster_cut_cost.hpp, from the mesh's hierarchy); apply_steps() then selects,
// in the same frame, the meshes the budget coarsened at their detail scale, and drawn() is that
// cut (every other mesh keeps update()'s).
#pragma once

#include "budget/cluster_cut_cost.hpp"
#include "budget/frame_budget.hpp"
#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_selector.hpp"
#include "lod/cluster/cluster_switch_policy.hpp"
#include "plugin/object_desc.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::plugin {

// Threads for a frame's cut, the caller's among them (fewer where the machine has fewer): the
// pool starts only once the meshes hold lod::kClusterParallelMinClusters clusters.
inline constexpr unsigned kClusterThreads = 4;

class ClusterMeshes {
 public:
  ClusterMeshes();

  // Throws std::invalid_argument with the reason (nothing registered then).
  std::uint32_t add(const ClusterMeshDesc& desc);
  // LodPlugin::set_cluster_mesh_motion: the mesh's new pose and velocity (constant time).
  void set_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s);
  std::size_t mesh_count() const { return instances_.instance_count(); }
  std::size_t cluster_count() const { return instances_.size(); }

  // One frame: the cut for `viewer`, then (with `policy`) the hysteresis at t_s. A refused
  // viewer or policy input draws the finest cut (every source cluster), never a guess.
  void update(const lod::Viewer& viewer, const lod::SwitchPolicyConfig* policy, double t_s, bool suppressed);

  // After apply_steps() with a step > 0: the budgeted cut (and its reasons; held 0 for a
  // coarsened mesh, whose cut is the budget's, not the policy's).
  std::span<const std::uint8_t> drawn() const { return budget_used_ ? final_drawn_ : update_drawn(); }
  std::span<const std::uint8_t> perceptual() const { return perceptual_; }
  std::span<const std::uint8_t> limited_by() const { return budget_used_ ? final_limited_ : limited_; }
  std::span<const std::uint8_t> held() const { return budget_used_ ? final_held_ : held_; }
  std::span<const std::uint32_t> first_cluster() const { return first_; }
  // The last update()'s switch-policy work: clusters stepped (all of them in a full pass).
  std::size_t policy_clusters_stepped() const { return policy_stepped_; }

  // Frame budget, after update(): per mesh, the triangles of this frame's perceptual cut and of
  // the cut update() drew (the switch policy's), by one pass over the cluster bytes.
  void measure();
  // Mesh m's budget item: its projected area (the bounding sphere's, in pixels at px_per_deg,
  // at most max_px: a mesh around the eye fills the view, not more) and the predicted
  // triangles of every step (ClusterCutCost::predict_steps of its hierarchy).
  budget::BudgetClusterView budget_view(std::uint32_t mesh, const glm::dvec3& eye_m, double px_per_deg,
                                        double max_px) const;
  // Selects the meshes with steps[m] > 0 at detail scale kClusterStepScale[steps[m]] (lod::
  // ClusterSelector with per-instance scales, into arrays of its own), so that drawn() is the
  // budgeted cut, and counts their triangles. All steps 0 (or steps not one per mesh): drawn()
  // stays update()'s, bit for bit. A refused selection keeps update()'s cut and returns why.
  [[nodiscard]] std::string apply_steps(const lod::Viewer& viewer, std::span<const std::uint8_t> steps);
  // No budget this frame: drawn() is update()'s.
  void clear_steps();
  std::span<const double> perceptual_triangles() const { return perceptual_tris_; }
  // The triangles each mesh draws (after apply_steps: the budgeted cut's).
  std::span<const double> drawn_triangles() const { return drawn_tris_; }
  std::span<const std::uint8_t> steps() const { return steps_; }
  std::span<const float> detail_scale() const { return scale_f_; }

 private:
  std::span<const std::uint8_t> update_drawn() const { return policy_used_ ? drawn_ : perceptual_; }
  // Triangles of the clusters of mesh m set in bytes.
  double triangles_of(std::uint32_t mesh, std::span<const std::uint8_t> bytes) const;
  // The finest consistent cut (every source cluster) into out, clusters [first, first + out.size()).
  void draw_finest(std::span<std::uint8_t> out, std::size_t first) const;
  // The switch policy over this frame's invisible_ into drawn_ and held_ (see the .cpp).
  [[nodiscard]] std::string apply_policy(const lod::SwitchPolicyConfig& policy, double t_s, bool suppressed);

  lod::ClusterInstances instances_;
  lod::ClusterSelector selector_;
  std::vector<std::uint32_t> first_;
  std::vector<std::uint8_t> perceptual_, limited_, invisible_, drawn_, held_, record_held_;
  std::vector<double> self_window_s_, parent_window_s_;
  // perceptual_, limited_ and invisible_ hold the selector's last frame, untouched since: it
  // then rewrites only what changed (lod::ClusterCutBytes::incremental).
  bool bytes_incremental_ = false;
  std::size_t new_from_ = 0;  // clusters [new_from_, size) have not had their first frame
  bool policy_used_ = false;
  // The switch policy in time proportional to the change: the clusters the selector evaluated
  // this frame and the last, those with a coarsening still held back, and the list stepped
  // (deduplicated by listed_mark_, all 0 between frames). policy_state_valid_: last frame
  // stepped the policy over the selector's cut.
  std::vector<std::uint32_t> evaluated_, previous_evaluated_, pending_, next_pending_, listed_;
  std::vector<std::uint8_t> listed_mark_;
  bool policy_state_valid_ = false;
  std::size_t policy_stepped_ = 0;

  // Frame budget: per hierarchy its cut-cost ladder and bounding sphere (its own space); per
  // mesh the triangles, step and scale; the second selector and its cut.
  struct Bound {
    glm::dvec3 center{0.0};
    double radius = 0.0;
  };
  std::vector<budget::ClusterCutCost> cut_cost_;
  std::vector<budget::ClusterStepElasticity> elasticity_;  // per mesh
  std::vector<Bound> bound_;
  std::vector<double> perceptual_tris_, update_tris_, drawn_tris_, scale_;
  std::vector<std::uint8_t> steps_;
  std::vector<float> scale_f_;
  lod::ClusterSelector budget_selector_;
  std::vector<std::uint8_t> budget_drawn_, budget_limited_, budget_invisible_;
  std::vector<std::uint8_t> final_drawn_, final_limited_, final_held_;
  bool budget_bytes_incremental_ = false;
  bool budget_used_ = false;
};

}  // namespace gazelod::plugin
