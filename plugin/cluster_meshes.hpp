// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster meshes (LodPlugin::add_cluster_mesh): instances of shared hierarchies
// (lod::ClusterInstances: a mesh whose hierarchy equals, bit for bit, one registered before,
// as a glTF mesh placed by several nodes, shares it and costs a pose), each frame's perceptual
// cut (lod::ClusterSelector: each mesh in its own space through its hierarchy's bounding tree,
// in time proportional to the cut, on up to kClusterThreads threads; the same cut as
// lod::select_clusters_local) and the cut drawn after the switch policy
// (lod::apply_cluster_switch_policy), in arrays the plugin hands out as FrameDecisions::cluster_*.
// All allocation happens at registration (and in the first frames, while the cut's lists grow).
#pragma once

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

  std::span<const std::uint8_t> drawn() const { return policy_used_ ? drawn_ : perceptual_; }
  std::span<const std::uint8_t> perceptual() const { return perceptual_; }
  std::span<const std::uint8_t> limited_by() const { return limited_; }
  std::span<const std::uint8_t> held() const { return held_; }
  std::span<const std::uint32_t> first_cluster() const { return first_; }

 private:
  // The finest consistent cut (every source cluster) into out, clusters [first, first + out.size()).
  void draw_finest(std::span<std::uint8_t> out, std::size_t first) const;

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
};

}  // namespace gazelod::plugin
