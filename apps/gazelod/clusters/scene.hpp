// SPDX-License-Identifier: Apache-2.0
// `gazelod run --scene F` where F has cluster hierarchies (gazelod bake --clusters): which of
// the scene's objects are drawn as cluster cuts, their poses in LOCAL space, their
// registration with the plugin (LodPlugin::add_cluster_mesh) and their triangle counts.
//
// Every node whose mesh has GAZELOD_cluster_lod becomes one cluster mesh per such primitive,
// posed by the node's world transform followed by the --scene-placement shift, and moved
// with its scenario object (an object_motion effect moves positions only: ClusterMotion). The plugin's pose is
// rotation, translation and a uniform scale; a node whose world transform has a non-uniform scale, a shear, a mirror or
// a projective row cannot be posed so and stays a plain object (its one-level chain), with a note saying why.
#pragma once

#include "bake/baked_scene.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::cli {

// Relative tolerance on the node's scale being uniform and its axes orthogonal.
inline constexpr double kUniformScaleTolerance = 1e-5;

// world (glTF column-major, mesh space -> glTF world) followed by a translation shift_m as an
// InstanceTransform. Returns "" or why it has none (non-finite, projective, sheared,
// non-uniformly scaled, mirrored or degenerate), leaving `out` untouched.
std::string instance_transform_of(const glm::dmat4& world, const glm::dvec3& shift_m, lod::InstanceTransform& out);

struct ClusterMesh {
  std::size_t object = 0;                                  // scenario (= baked) object index
  std::string label;                                       // "Terrain primitive 0"
  const bake::BakedClusterPrimitive* primitive = nullptr;  // owned by the BakedScene
  lod::InstanceTransform pose;                             // mesh space -> LOCAL
  std::uint64_t full_triangles = 0;                        // its leaves' (source) triangles
};

struct ClusterScene {
  std::vector<ClusterMesh> meshes;               // plugin cluster-mesh id = index
  std::vector<std::uint8_t> drawn_as_clusters;   // per scenario object: 1 when its meshes are here
  std::vector<std::uint32_t> first_cluster;      // per mesh, into the back-to-back cluster arrays
  std::vector<std::uint32_t> cluster_triangles;  // per cluster, meshes back to back
  std::uint64_t full_triangles = 0;              // every mesh at full detail (its leaves)
  std::vector<std::string> notes;                // objects left plain, and why

  std::size_t cluster_count() const { return cluster_triangles.size(); }
  bool empty() const { return meshes.empty(); }
  // The triangles of the clusters with drawn[i] != 0 (meshes back to back, as
  // FrameDecisions::cluster_drawn); clusters beyond the shorter span are ignored.
  std::uint64_t triangles_of(std::span<const std::uint8_t> drawn) const;
};

// The cluster meshes of a baked scene whose objects are the scenario's objects (in order),
// moved by shift_m (--scene-placement). `baked` must outlive the result.
ClusterScene make_cluster_scene(const bake::BakedScene& baked, const glm::dvec3& shift_m,
                                const sim::Scenario& scenario);

// Registers every mesh with the plugin, in order (ids 0, 1, ...), and checks that the plugin's
// cluster numbering matches first_cluster. Throws UsageError naming the mesh when the plugin
// refuses it (an inconsistent hierarchy).
void register_cluster_meshes(const ClusterScene& scene, LodPlugin& plugin);

// Where each cluster mesh is this frame: its pose translated by its scenario object's
// displacement from the scenario's own position, and the object's velocity.
class ClusterMotion {
 public:
  explicit ClusterMotion(const ClusterScene& scene);
  // The meshes whose displacement or velocity changed since the last call (all that moved
  // at all on the first), given every scenario object's state now; re-pose those (plugin,
  // audit) with pose(k) and velocity_m_s(k). No allocation after the first call.
  std::span<const std::size_t> update(const sim::Scenario& scenario, std::span<const sim::ObjectState> now);
  const lod::InstanceTransform& pose(std::size_t mesh) const { return pose_[mesh]; }
  const glm::dvec3& velocity_m_s(std::size_t mesh) const { return velocity_[mesh]; }
  std::span<const glm::dvec3> shift_m() const { return shift_; }  // per mesh, LOCAL (for the renderer)

 private:
  const ClusterScene& scene_;
  std::vector<lod::InstanceTransform> pose_;
  std::vector<glm::dvec3> shift_, velocity_;
  std::vector<std::size_t> changed_;
};

// Whether the plugin's FrameDecisions::cluster_first lays the clusters out as `scene` does.
bool same_cluster_layout(const ClusterScene& scene, std::span<const std::uint32_t> cluster_first);

}  // namespace gazelod::cli
