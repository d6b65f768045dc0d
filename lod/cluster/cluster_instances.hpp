// SPDX-License-Identifier: Apache-2.0
// Cluster meshes as instances of shared hierarchies: each distinct hierarchy is stored once, in
// its own space, with its bounding hierarchy (lod/cluster/cluster_bvh.hpp); an instance is a
// hierarchy id, a pose and a velocity. The frame's selection (cluster_selector.hpp, or the
// linear select_clusters_local of cluster_local_view.hpp) evaluates each instance in its own
// space by moving the viewer there instead of moving the records to world space, so hundreds
// of instances of one baked mesh cost one hierarchy's memory plus a pose each (ClusterStore,
// lod/cluster/cluster_select_store.hpp, copies every record per instance).
//
// Cluster numbering matches ClusterStore's: instance k owns the clusters [first_cluster(k),
// + its hierarchy's size), in the hierarchy's own order, instances back to back in
// registration order.
#pragma once

#include "lod/cluster/cluster_bvh.hpp"
#include "lod/cluster/cluster_hierarchy.hpp"
#include "lod/cluster/cluster_select_store.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace gazelod::lod {

struct ClusterInstance {
  std::uint32_t hierarchy = 0;
  std::uint32_t first_cluster = 0;
  InstanceTransform pose;        // local -> world (the rotation stored normalised)
  glm::dvec3 velocity_m_s{0.0};  // world
};

class ClusterInstances {
 public:
  // task_clusters: the size limit of the trees' units of parallel work (build_cluster_bvh).
  explicit ClusterInstances(std::size_t task_clusters = kBvhTaskClusters);
  // Validates local (validate_cluster_hierarchy, throws std::invalid_argument with the reason,
  // nothing registered) and returns its id; a hierarchy equal bit for bit to one registered
  // before (index_buffer_size included) returns that one's id, and builds nothing.
  std::uint32_t add_hierarchy(const ClusterHierarchy& local, std::size_t index_buffer_size);
  // A new instance of a registered hierarchy; returns its id. Throws std::invalid_argument (a
  // bad pose or velocity; more than 2^32 - 1 clusters in all) or std::out_of_range.
  std::uint32_t add_instance(std::uint32_t hierarchy, const InstanceTransform& pose, const glm::dvec3& velocity_m_s);
  // An instance moved (constant time). Throws as add_instance.
  void set_pose(std::uint32_t instance, const InstanceTransform& pose, const glm::dvec3& velocity_m_s);

  std::size_t size() const { return clusters_; }  // clusters of all instances
  std::size_t instance_count() const { return instances_.size(); }
  std::size_t hierarchy_count() const { return hierarchies_.size(); }
  const ClusterInstance& instance(std::uint32_t k) const { return instances_.at(k); }
  const ClusterHierarchy& hierarchy(std::uint32_t h) const { return hierarchies_.at(h)->local; }
  const ClusterBvh& bvh(std::uint32_t h) const { return hierarchies_.at(h)->bvh; }
  // A value no other store's layout ever had, new whenever an instance is added (not when one
  // moves): what a caller caching the layout compares.
  std::uint64_t layout_generation() const { return generation_; }
  // Capacity of everything stored: the hierarchies, their trees and the instances.
  std::size_t memory_bytes() const;

 private:
  struct Stored {
    ClusterHierarchy local;
    std::size_t index_buffer_size = 0;
    std::uint64_t hash = 0;
    ClusterBvh bvh;
  };
  std::vector<std::unique_ptr<Stored>> hierarchies_;
  std::vector<ClusterInstance> instances_;
  std::size_t clusters_ = 0;
  std::size_t task_clusters_;
  std::uint64_t generation_;
};

}  // namespace gazelod::lod
