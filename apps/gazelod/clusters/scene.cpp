// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/scene.hpp"

#include "apps/gazelod/commands/command.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gazelod::cli {
namespace {

bool finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

}  // namespace

std::string instance_transform_of(const glm::dmat4& world, const glm::dvec3& shift_m, lod::InstanceTransform& out) {
  if (!finite(world) || !std::isfinite(shift_m.x) || !std::isfinite(shift_m.y) || !std::isfinite(shift_m.z))
    return "its world transform is not finite";
  if (world[0][3] != 0.0 || world[1][3] != 0.0 || world[2][3] != 0.0 || world[3][3] != 1.0)
    return "its world transform is projective (last row not 0 0 0 1)";
  const glm::dvec3 axis[3] = {glm::dvec3(world[0]), glm::dvec3(world[1]), glm::dvec3(world[2])};
  double lo = glm::length(axis[0]), hi = lo;
  for (const glm::dvec3& a : axis) lo = std::min(lo, glm::length(a)), hi = std::max(hi, glm::length(a));
  if (!(lo > 0.0) || !std::isfinite(hi)) return "its world transform is degenerate (an axis of length 0)";
  if (hi - lo > kUniformScaleTolerance * hi)
    return "its world transform scales non-uniformly (axis lengths " + std::to_string(lo) + " to " +
           std::to_string(hi) + "); cluster bounds need a uniform scale";
  glm::dmat3 rotation;
  for (int c = 0; c < 3; ++c) rotation[c] = axis[c] / glm::length(axis[c]);
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b)
      if (std::abs(glm::dot(rotation[a], rotation[b])) > kUniformScaleTolerance)
        return "its world transform shears (axes not orthogonal)";
  if (glm::determinant(rotation) < 0.0) return "its world transform mirrors (negative determinant)";
  out.rotation = glm::normalize(glm::quat_cast(rotation));
  out.translation_m = glm::dvec3(world[3]) + shift_m;
  out.scale = hi;  // the largest axis: bounds and errors rounded towards keeping detail
  return "";
}

std::uint64_t ClusterScene::triangles_of(std::span<const std::uint8_t> drawn) const {
  std::uint64_t n = 0;
  const std::size_t count = std::min(drawn.size(), cluster_triangles.size());
  for (std::size_t i = 0; i < count; ++i)
    if (drawn[i] != 0) n += cluster_triangles[i];
  return n;
}

ClusterScene make_cluster_scene(const bake::BakedScene& baked, const glm::dvec3& shift_m,
                                const sim::Scenario& scenario) {
  ClusterScene scene;
  scene.drawn_as_clusters.assign(scenario.objects.size(), 0);
  const std::size_t n = std::min(scenario.objects.size(), baked.objects.size());
  for (std::size_t i = 0; i < n; ++i) {
    const bake::BakedObject& o = baked.objects[i];
    const bake::BakedClusterMesh* clusters = baked.clusters_of(o);
    if (clusters == nullptr || clusters->primitives.empty()) continue;
    lod::InstanceTransform pose;
    if (const std::string why = instance_transform_of(o.world, shift_m, pose); !why.empty()) {
      scene.notes.push_back("'" + o.name + "' drawn whole, not as clusters: " + why);
      continue;
    }
    scene.drawn_as_clusters[i] = 1;
    for (const bake::BakedClusterPrimitive& p : clusters->primitives) {
      ClusterMesh m;
      m.object = i;
      m.label = o.name + " primitive " + std::to_string(p.primitive);
      m.primitive = &p;
      m.pose = pose;
      scene.first_cluster.push_back(static_cast<std::uint32_t>(scene.cluster_triangles.size()));
      for (std::size_t c = 0; c < p.hierarchy.size(); ++c) {
        const std::uint32_t tris = p.hierarchy.index_count[c] / 3;
        scene.cluster_triangles.push_back(tris);
        if (p.hierarchy.depth[c] == 0) m.full_triangles += tris;
      }
      scene.full_triangles += m.full_triangles;
      scene.meshes.push_back(std::move(m));
    }
  }
  return scene;
}

ClusterMotion::ClusterMotion(const ClusterScene& scene)
    : scene_(scene), shift_(scene.meshes.size(), glm::dvec3(0.0)), velocity_(scene.meshes.size(), glm::dvec3(0.0)) {
  for (const ClusterMesh& m : scene.meshes) pose_.push_back(m.pose);
  changed_.reserve(scene.meshes.size());
}

std::span<const std::size_t> ClusterMotion::update(const sim::Scenario& scenario,
                                                   std::span<const sim::ObjectState> now) {
  changed_.clear();
  for (std::size_t k = 0; k < scene_.meshes.size(); ++k) {
    const ClusterMesh& m = scene_.meshes[k];
    if (m.object >= now.size() || m.object >= scenario.objects.size()) continue;
    const glm::dvec3 shift = now[m.object].position_m - scenario.objects[m.object].position_m;
    const glm::dvec3 velocity = now[m.object].velocity_m_s;
    if (shift == shift_[k] && velocity == velocity_[k]) continue;  // still: nothing to re-pose
    shift_[k] = shift, velocity_[k] = velocity;
    pose_[k].translation_m = m.pose.translation_m + shift;
    changed_.push_back(k);
  }
  return changed_;
}

void register_cluster_meshes(const ClusterScene& scene, LodPlugin& plugin) {
  for (std::size_t k = 0; k < scene.meshes.size(); ++k) {
    const ClusterMesh& m = scene.meshes[k];
    ClusterMeshDesc d;
    d.hierarchy = m.primitive->hierarchy;
    d.index_count = m.primitive->indices.size();
    d.pose = m.pose;
    try {
      const std::uint32_t id = plugin.add_cluster_mesh(d);
      if (id != k)
        throw UsageError("--scene: cluster mesh '" + m.label + "' got plugin id " + std::to_string(id) + ", expected " +
                             std::to_string(k),
                         1);
    } catch (const std::invalid_argument& e) {
      throw UsageError("--scene: cluster mesh '" + m.label + "': " + e.what());
    }
  }
}

bool same_cluster_layout(const ClusterScene& scene, std::span<const std::uint32_t> cluster_first) {
  if (cluster_first.size() < scene.first_cluster.size()) return false;
  return std::equal(scene.first_cluster.begin(), scene.first_cluster.end(), cluster_first.begin());
}

}  // namespace gazelod::cli
