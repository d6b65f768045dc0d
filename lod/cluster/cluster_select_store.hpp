// SPDX-License-Identifier: Apache-2.0
// Cluster hierarchies into world space for select_clusters (lod/cluster/cluster_select.hpp): the
// instance transform (rotation, translation, uniform scale) applied to a hierarchy once, and
// ClusterStore, an owning builder of a ClusterSet over many meshes, validated at
// registration so the per-frame loop does not have to be.
//
// A moving mesh: give its world velocity (used for the retinal velocity, like ObjectSet's;
// its rotation is not modelled) and call set_pose in each frame it moves, which re-transforms
// its clusters in place (linear in its clusters, no allocation). A uniform scale keeps every
// ratio the rule uses (error over distance, angles), so scaled radii and errors are exact up
// to float rounding; both are rounded up (towards keeping detail).
#pragma once

#include "lod/cluster/cluster_hierarchy.hpp"
#include "lod/cluster/cluster_select.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::lod {

// world = translation_m + scale * (rotation * local).
struct InstanceTransform {
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // non-zero (normalised here)
  glm::dvec3 translation_m{0.0};
  double scale = 1.0;  // uniform, finite and > 0
};

// "" when finite, the rotation non-zero and the scale > 0, else which field.
[[nodiscard]] std::string validate_instance_transform(const InstanceTransform& xf);

// "" when one mesh's hierarchy (its own space) is consistent: validate_clusters on its records
// as one static mesh, and first_index, index_count, depth one per cluster with each cluster's
// triangles (index_count a multiple of 3) inside an index buffer of index_buffer_size.
[[nodiscard]] std::string validate_cluster_hierarchy(const ClusterHierarchy& hierarchy, std::size_t index_buffer_size);

// Applies xf to local's records into world (resized to local's size: no allocation once it
// has that size; triangle ranges and depth copied). "" or why not (an invalid transform;
// world untouched).
[[nodiscard]] std::string transform_hierarchy(const ClusterHierarchy& local, const InstanceTransform& xf,
                                              ClusterHierarchy& world);

// Owns the arrays behind a ClusterSet: meshes' clusters back to back in registration order,
// with the set's distinct records (ClusterSet::record_*: records equal bit for bit in a mesh's
// own space are one record, so equal in world space too).
class ClusterStore {
 public:
  // Validates local (validate_cluster_hierarchy), then its records in world space, and appends
  // it; returns the mesh id. Throws std::invalid_argument with the reason (store unchanged).
  std::uint32_t add_mesh(const ClusterHierarchy& local, const InstanceTransform& pose, const glm::dvec3& velocity_m_s,
                         std::size_t index_buffer_size);
  // A mesh moved: local must be the hierarchy it was registered with. Throws
  // std::invalid_argument (bad pose or velocity, cluster count differs) or std::out_of_range.
  void set_pose(std::uint32_t mesh, const ClusterHierarchy& local, const InstanceTransform& pose,
                const glm::dvec3& velocity_m_s);
  void reserve(std::size_t meshes, std::size_t clusters);
  std::size_t size() const { return self_error_.size(); }
  std::size_t mesh_count() const { return count_.size(); }
  std::size_t record_count() const { return rec_error_.size(); }
  std::uint32_t first_cluster(std::uint32_t mesh) const { return first_.at(mesh); }
  ClusterSet view() const;

 private:
  void write_records(std::size_t mesh, const ClusterHierarchy& local, const InstanceTransform& xf);
  void index_records(const ClusterHierarchy& local);  // appends the new last mesh's distinct records
  std::vector<float> self_x_, self_y_, self_z_, self_radius_, self_error_;
  std::vector<float> parent_x_, parent_y_, parent_z_, parent_radius_, parent_error_;
  std::vector<std::uint32_t> first_, count_;
  std::vector<double> vel_x_, vel_y_, vel_z_, finest_;
  std::vector<float> rec_x_, rec_y_, rec_z_, rec_radius_, rec_error_;  // distinct records
  std::vector<std::uint32_t> self_rec_, parent_rec_;                   // per cluster
  std::vector<std::uint32_t> rec_first_, rec_count_;                   // per mesh
  std::vector<std::uint64_t> rec_source_;  // per record: 2 x cluster (+1 for its parent record)
};

}  // namespace gazelod::lod
