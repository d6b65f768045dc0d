// SPDX-License-Identifier: Apache-2.0
// Scenes of cluster instances and the comparison with the linear pass (see cluster_instance_scene.hpp).
#include "tests/lod/cluster_instance_scene.hpp"

#include "bake/cluster/cluster_build.hpp"
#include "bake/terrain_mesh.hpp"
#include "lod/cluster/cluster_local_view.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::lod::test {

ClusterHierarchy baked_terrain(std::uint64_t triangles, double size_m, double relief_m) {
  bake::TerrainOptions o;
  o.triangles = triangles;
  o.size_m = size_m;
  o.relief_m = relief_m;
  o.wavelength_m = size_m / 3.0;
  o.path_half_width_m = 0.0;
  const bake::GeneratedMesh mesh = bake::terrain_meshes(o).at(0);
  bake::ClusterBuildOptions b;
  b.threads = 1;
  return bake::build_cluster_hierarchy(mesh.positions, mesh.indices, b).hierarchy;
}

std::vector<Placement> scatter(std::size_t count, std::uint32_t hierarchies, double spacing_m, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(count))));
  std::vector<Placement> out;
  for (std::size_t k = 0; k < count; ++k) {
    Placement p;
    p.hierarchy = static_cast<std::uint32_t>(k % hierarchies);
    const glm::dvec3 axis = k % 3 == 0 ? glm::dvec3{0, 1, 0} : glm::dvec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
    p.pose.rotation = glm::angleAxis(2.0 * std::numbers::pi * u(rng),
                                     glm::length(axis) > 0.0 ? glm::normalize(axis) : glm::dvec3{0, 1, 0});
    p.pose.scale = k % 2 == 0 ? 1.0 : std::pow(10.0, 2.6 * u(rng) - 1.3);
    p.pose.translation_m = {(double(k % side) - 0.5 * double(side)) * spacing_m, 0.3 * (u(rng) - 0.5),
                            (double(k / side) - 0.5 * double(side)) * spacing_m};
    if (k % 4 == 1) p.velocity_m_s = {2.0 * (u(rng) - 0.5), 0.2 * (u(rng) - 0.5), 2.0 * (u(rng) - 0.5)};
    out.push_back(p);
  }
  return out;
}

Viewer walk_viewer(std::size_t frame, std::size_t frames, double extent_m, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 1'000'003 + frame);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double t = double(frame) / double(std::max<std::size_t>(frames, 2) - 1);  // 0..1 along the walk
  const double ts = double(frame) / 90.0;                                         // seconds at 90 Hz
  Viewer v;
  v.eye_position_m = {extent_m * (t - 0.5), 1.7 + 0.5 * std::sin(7.0 * t), 0.25 * extent_m * std::sin(5.0 * t)};
  v.eye_velocity_m_s = {1.4, 0.1 * std::cos(7.0 * t), 0.3 * std::cos(5.0 * t)};
  const double yaw = 0.6 * std::sin(2.0 * std::numbers::pi * ts / 6.0) - std::numbers::pi / 2.0;
  const double pitch = -0.25 + 0.1 * std::sin(2.0 * std::numbers::pi * ts / 4.0);
  v.gaze_direction = {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
  double yaw_rate = 0.6 * 2.0 * std::numbers::pi / 6.0 * std::cos(2.0 * std::numbers::pi * ts / 6.0);
  if (frame % 40 < 6) yaw_rate = 0.5 + 0.6 * double(frame % 40);  // a fast turn, through G = 0 (2.1 rad/s)
  v.head_angular_velocity_rad_s = {0.0, yaw_rate, 0.05 * std::sin(ts)};
  if (frame % 23 < 3) {  // a saccade
    const glm::dvec3 axis{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
    v.gaze_angular_velocity_in_head_rad_s = 8.0 * u(rng) * axis;
  } else {  // VOR: the eye counter-rotates a little
    v.gaze_angular_velocity_in_head_rad_s = -0.8 * v.head_angular_velocity_rad_s;
  }
  v.xi_cpd = 8.0 + 52.0 * u(rng);
  v.tracker_error_deg = frame % 5 == 0 ? 0.0 : 3.0 * u(rng);
  v.scale = 0.4 + 0.6 * u(rng);
  v.use_velocity = frame % 11 != 5;
  v.use_eccentricity = frame % 13 != 3;
  v.use_size = frame % 17 != 7;
  return v;
}

Viewer scenario_viewer(sim::Simulator& simulator, std::int64_t t_ns, double xi_cpd) {
  constexpr std::int64_t kHalfStepNs = 1'000'000;
  const auto world_gaze = [&](std::int64_t t) {
    return simulator.head_at(t).orientation * simulator.true_gaze_at(t).direction;
  };
  const glm::dvec3 before = world_gaze(t_ns - kHalfStepNs), after = world_gaze(t_ns + kHalfStepNs);
  const glm::dvec3 axis = glm::cross(before, after);
  const double sin_angle = glm::length(axis);
  const glm::dvec3 omega =
      sin_angle > 0.0 ? axis / sin_angle * (std::atan2(sin_angle, glm::dot(before, after)) / (2e-9 * kHalfStepNs))
                      : glm::dvec3(0.0);
  const sim::HeadState head = simulator.head_at(t_ns);
  Viewer v;
  v.eye_position_m = head.position_m;
  v.eye_velocity_m_s = head.linear_velocity_m_s;
  v.gaze_direction = head.orientation * simulator.true_gaze_at(t_ns).direction;
  v.head_angular_velocity_rad_s = head.angular_velocity_rad_s;
  v.gaze_angular_velocity_in_head_rad_s = omega - head.angular_velocity_rad_s;
  v.xi_cpd = xi_cpd;
  return v;
}

void Disagreement::add(const CutBytes& local, const CutBytes& world) {
  for (std::size_t c = 0; c < local.drawn.size(); ++c) {
    drawn_differ += local.drawn[c] != world.drawn[c];
    for (int bit = 0; bit < 2; ++bit) {
      const bool l = (local.bits[c] >> bit) & 1, w = (world.bits[c] >> bit) & 1;
      local_coarser += l && !w;
      local_finer += w && !l;
    }
  }
  decisions += 2 * local.drawn.size();
  ++frames;
}

std::string compare_with_linear(const Viewer& viewer, const ClusterInstances& instances, ClusterSelector& selector,
                                CutBytes& bytes, CutBytes& linear) {
  const std::size_t n = instances.size();
  linear = CutBytes(n);
  if (std::string e = select_clusters_local(viewer, instances, {linear.drawn, linear.why, {}, {}, {}, linear.bits});
      !e.empty())
    return "linear pass: " + e;
  if (std::string e = selector.select(viewer, instances, {bytes.drawn, bytes.why, bytes.bits, true}); !e.empty())
    return "selector: " + e;
  for (std::size_t i = 0; i < n; ++i)
    if (bytes.drawn[i] != linear.drawn[i] || bytes.why[i] != linear.why[i] || bytes.bits[i] != linear.bits[i])
      return "cluster " + std::to_string(i) + ": drawn/why/bits " + std::to_string(bytes.drawn[i]) + "/" +
             std::to_string(bytes.why[i]) + "/" + std::to_string(bytes.bits[i]) + ", linear pass " +
             std::to_string(linear.drawn[i]) + "/" + std::to_string(linear.why[i]) + "/" +
             std::to_string(linear.bits[i]);
  std::vector<std::uint32_t> listed(selector.drawn().begin(), selector.drawn().end());
  for (std::size_t k = 0; k < listed.size(); ++k)
    if (listed[k] >= n || selector.drawn_limited_by()[k] != linear.why[listed[k]])
      return "list entry " + std::to_string(k) + ": cluster or its criterion differs";
  std::sort(listed.begin(), listed.end());
  std::size_t at = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!linear.drawn[i]) continue;
    if (at >= listed.size() || listed[at] != i) return "the list misses cluster " + std::to_string(i);
    ++at;
  }
  return at == listed.size() ? std::string() : "the list holds a cluster not drawn";
}

}  // namespace gazelod::lod::test
