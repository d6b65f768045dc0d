// SPDX-License-Identifier: Apache-2.0
// The viewer in an instance's space and the linear selection there (see cluster_local_view.hpp).
#include "lod/cluster/cluster_local_view.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace gazelod::lod {

namespace {

bool finite3(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::string local_view(const Viewer& world, const ClusterInstance& instance, LocalView& out) {
  const glm::dquat to_local = glm::conjugate(instance.pose.rotation);  // stored normalised
  const double inv_s = 1.0 / instance.pose.scale;                      // scale > 0, validated
  Viewer v = world;
  v.eye_position_m = to_local * (world.eye_position_m - instance.pose.translation_m) * inv_s;
  v.eye_velocity_m_s = to_local * world.eye_velocity_m_s * inv_s;
  v.gaze_direction = to_local * world.gaze_direction;
  v.head_angular_velocity_rad_s = to_local * world.head_angular_velocity_rad_s;
  v.gaze_angular_velocity_in_head_rad_s = to_local * world.gaze_angular_velocity_in_head_rad_s;
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(v.eye_position_m[k]) <= kMaxLocalEyeM))
      return "the eye lies beyond the float range of the instance's space (scale " +
             std::to_string(instance.pose.scale) + ")";
  // The rest of a valid viewer stays valid (rotated, or divided by a scale that kept the eye
  // finite), unless a velocity overflows: checked here, not by validate_viewer's message
  // building (a frame calls this per instance).
  if (!finite3(v.eye_velocity_m_s) || !finite3(v.gaze_direction) || !finite3(v.head_angular_velocity_rad_s) ||
      !finite3(v.gaze_angular_velocity_in_head_rad_s) || !finite3(instance.velocity_m_s * inv_s))
    return "a velocity overflows in the instance's space (scale " + std::to_string(instance.pose.scale) + ")";
  out.viewer = v;
  out.mesh_velocity = to_local * instance.velocity_m_s * inv_s;
  return {};
}

OneInstanceSet::OneInstanceSet(const ClusterHierarchy& h, const glm::dvec3& velocity_m_s, double finest_error_m,
                               double detail_scale)
    : count_(static_cast<std::uint32_t>(h.size())),
      vx_(velocity_m_s.x),
      vy_(velocity_m_s.y),
      vz_(velocity_m_s.z),
      finest_(finest_error_m),
      detail_scale_(detail_scale) {
  set_.self_center_x_m = h.self_center_x_m, set_.self_center_y_m = h.self_center_y_m;
  set_.self_center_z_m = h.self_center_z_m, set_.self_radius_m = h.self_radius_m;
  set_.self_error_m = h.self_error_m;
  set_.parent_center_x_m = h.parent_center_x_m, set_.parent_center_y_m = h.parent_center_y_m;
  set_.parent_center_z_m = h.parent_center_z_m, set_.parent_radius_m = h.parent_radius_m;
  set_.parent_error_m = h.parent_error_m;
  set_.mesh_first_cluster = {&first_, 1}, set_.mesh_cluster_count = {&count_, 1};
  set_.mesh_vel_x_m_s = {&vx_, 1}, set_.mesh_vel_y_m_s = {&vy_, 1}, set_.mesh_vel_z_m_s = {&vz_, 1};
  set_.mesh_finest_error_m = {&finest_, 1};
  set_.mesh_detail_scale = {&detail_scale_, 1};
}

LocalFrames local_frames(const LocalView& view, double finest_error_m, double detail_scale) {
  const ClusterHierarchy none;  // make_cluster_mesh_frame reads the mesh's velocity and finest error only
  const OneInstanceSet one(none, view.mesh_velocity, finest_error_m);
  return {detail::make_cluster_frame(view.viewer),
          detail::make_cluster_mesh_frame(view.viewer, one.set(), 0, detail_scale)};
}

std::string select_clusters_local(const Viewer& viewer, const ClusterInstances& instances, const ClusterDecisions& out,
                                  std::span<const double> detail_scale) {
  const std::size_t n = instances.size();
  const bool per_criterion =
      !out.drawn_size_only.empty() || !out.drawn_eccentricity_only.empty() || !out.drawn_velocity_only.empty();
  if (out.drawn.size() < n || out.limited_by.size() < n ||
      (per_criterion && (out.drawn_size_only.size() < n || out.drawn_eccentricity_only.size() < n ||
                         out.drawn_velocity_only.size() < n)) ||
      (!out.record_invisible.empty() && out.record_invisible.size() < n))
    return "decisions: an output is shorter than the cluster count (" + std::to_string(n) + ")";
  if (std::string e = validate_viewer(viewer); !e.empty()) return "viewer: " + e;
  if (std::string e = check_detail_scales(detail_scale, instances.instance_count()); !e.empty()) return e;
  const auto part = [](std::span<std::uint8_t> s, std::size_t first, std::size_t count) {
    return s.empty() ? s : s.subspan(first, count);
  };
  for (std::uint32_t k = 0; k < instances.instance_count(); ++k) {
    const ClusterInstance& inst = instances.instance(k);
    const ClusterHierarchy& h = instances.hierarchy(inst.hierarchy);
    LocalView view;
    if (std::string e = local_view(viewer, inst, view); !e.empty())
      return "instance " + std::to_string(k) + ": viewer: " + e;
    const OneInstanceSet one(h, view.mesh_velocity, instances.bvh(inst.hierarchy).finest_error_m,
                             detail_scale.empty() ? 1.0 : detail_scale[k]);
    const std::size_t first = inst.first_cluster, count = h.size();
    const ClusterDecisions mine{part(out.drawn, first, count),
                                part(out.limited_by, first, count),
                                part(out.drawn_size_only, first, count),
                                part(out.drawn_eccentricity_only, first, count),
                                part(out.drawn_velocity_only, first, count),
                                part(out.record_invisible, first, count),
                                {}};
    if (std::string e = select_clusters(view.viewer, one.set(), mine); !e.empty())
      return "instance " + std::to_string(k) + ": " + e;
  }
  return {};
}

}  // namespace gazelod::lod
