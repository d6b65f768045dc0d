// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes (LodPlugin::add_cluster_mesh): their hierarchies in the base
// space (lod::ClusterStore), each frame's perceptual cut (lod::select_clusters) and the cut
// drawn after the switch policy (lod::apply_cluster_switch_policy), in arrays the plugin hands
// out as FrameDecisions::cluster_*. All allocation happens at registration.
#pragma once

#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/cluster/cluster_switch_policy.hpp"
#include "plugin/object_desc.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::plugin {

class ClusterMeshes {
 public:
  // Throws std::invalid_argument with the reason (nothing registered then).
  std::uint32_t add(const ClusterMeshDesc& desc);
  // LodPlugin::set_cluster_mesh_motion: the mesh's records re-posed from its own hierarchy.
  void set_motion(std::uint32_t id, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s);
  std::size_t mesh_count() const { return store_.mesh_count(); }
  std::size_t cluster_count() const { return store_.size(); }

  // One frame: the cut for `viewer`, then (with `policy`) the hysteresis at t_s. A refused
  // viewer or policy input draws the finest cut (every source cluster), never a guess.
  void update(const lod::Viewer& viewer, const lod::SwitchPolicyConfig* policy, double t_s, bool suppressed);

  std::span<const std::uint8_t> drawn() const { return policy_used_ ? drawn_ : perceptual_; }
  std::span<const std::uint8_t> perceptual() const { return perceptual_; }
  std::span<const std::uint8_t> limited_by() const { return limited_; }
  std::span<const std::uint8_t> held() const { return held_; }
  std::span<const std::uint32_t> first_cluster() const { return first_; }

 private:
  // The finest consistent cut (every source cluster) into out, clusters [first, first + out.size()).
  void draw_finest(std::span<std::uint8_t> out, std::size_t first) const;

  lod::ClusterStore store_;
  std::vector<lod::ClusterHierarchy> local_;  // per mesh, its own space: what set_motion re-poses
  std::vector<std::uint32_t> first_;
  std::vector<std::uint8_t> perceptual_, limited_, invisible_, drawn_, held_, record_held_;
  std::vector<std::uint32_t> record_flags_;  // the selection's scratch, one word per distinct record
  std::vector<double> self_window_s_, parent_window_s_;
  std::size_t new_from_ = 0;  // clusters [new_from_, size) have not had their first frame
  bool policy_used_ = false;
};

}  // namespace gazelod::plugin
