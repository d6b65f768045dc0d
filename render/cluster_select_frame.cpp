// SPDX-License-Identifier: Apache-2.0
// The compute pass's frame and mesh constants (cluster_select_frame.hpp).
#include "render/cluster_select_frame.hpp"

#include "lod/cluster/cluster_select_kernel.hpp"
#include "render/render_error.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gazelod::render {
namespace {

// x as hi + lo, hi the float nearest x: c - hi - lo keeps float precision (as the CPU's eye).
void split(double x, float& hi, float& lo) {
  hi = static_cast<float>(x);
  lo = static_cast<float>(x - static_cast<double>(hi));
}

void unit_plane(double a, double b, float* out) {
  const glm::dvec2 p = glm::dvec2(a, b) / std::sqrt(a * a + b * b);
  out[0] = static_cast<float>(p.x);
  out[1] = static_cast<float>(p.y);
}

}  // namespace

gzl_cluster_select_frame make_cluster_select_frame(const lod::Viewer& viewer, const EyeView* cull_view) {
  const lod::detail::ClusterFrame f = lod::detail::make_cluster_frame(viewer);
  gzl_cluster_select_frame g{};
  std::copy_n(f.eye_hi_m, 3, g.eye_hi_m);
  std::copy_n(f.eye_lo_m, 3, g.eye_lo_m);
  std::copy_n(f.gaze_unit, 3, g.gaze_unit);
  std::copy_n(f.gaze_omega_rad_s, 3, g.gaze_omega_rad_s);
  g.ecc_offset_rad = f.ecc_offset_rad;
  g.scale = f.scale;
  g.scale_xi_cpd = f.scale_xi_cpd;
  // Size off is a0 = +inf on the CPU (by_size never holds): a flag here.
  g.use_size = std::isinf(f.static_limit_cpd) ? 0u : 1u;
  g.static_limit_cpd = g.use_size != 0u ? f.static_limit_cpd : 0.0f;
  g.error_factor = f.error_factor;
  g.on_eccentricity = f.on_eccentricity;
  g.on_velocity = f.on_velocity;
  // geometry_loop's expressions, in float as there.
  g.lip_w = (1.0f + lod::detail::kVelocitySlack) * f.gaze_omega_norm_rad_s;
  g.slack_w = lod::detail::kVelocitySlack * f.gaze_omega_norm_rad_s;
  if (cull_view == nullptr) return g;

  (void)projection_matrix(cull_view->fov, cull_view->near_m, cull_view->far_m);  // throws if degenerate
  g.cull = 1u;
  const glm::dmat4 m = view_matrix(cull_view->pose);
  for (int k = 0; k < 3; ++k) {
    split(cull_view->pose.position_m[k], g.view_hi_m[k], g.view_lo_m[k]);
    g.view_row_x[k] = static_cast<float>(m[k][0]);  // glm: m[column][row]
    g.view_row_y[k] = static_cast<float>(m[k][1]);
    g.view_row_z[k] = static_cast<float>(m[k][2]);
  }
  g.near_m = static_cast<float>(cull_view->near_m);
  g.far_m = static_cast<float>(cull_view->far_m);
  // ViewCuller's side planes: inside the left one x >= tan(left) depth, and so on.
  const double l = std::tan(cull_view->fov.angle_left), r = std::tan(cull_view->fov.angle_right);
  const double u = std::tan(cull_view->fov.angle_up), d = std::tan(cull_view->fov.angle_down);
  unit_plane(1.0, -l, g.side_x);
  unit_plane(-1.0, r, g.side_x + 2);
  unit_plane(-1.0, u, g.side_y);
  unit_plane(1.0, -d, g.side_y + 2);
  return g;
}

gzl_cluster_select_mesh make_cluster_select_mesh(const lod::Viewer& viewer, const lod::ClusterSet& clusters,
                                                 std::size_t mesh, double detail_scale) {
  const lod::detail::ClusterMeshFrame mf = lod::detail::make_cluster_mesh_frame(viewer, clusters, mesh, detail_scale);
  gzl_cluster_select_mesh g{};
  std::copy_n(mf.rel_vel_m_s, 3, g.rel_vel_m_s);
  g.lip_v = 2.0f * (1.0f + lod::detail::kVelocitySlack) * mf.rel_speed_m_s;
  g.slack_v = lod::detail::kVelocitySlack * mf.rel_speed_m_s;
  // +inf (size on, or no finite error): no finite distance reaches FLT_MAX either.
  g.cap_combined_m = std::isinf(mf.cap_combined_m) ? std::numeric_limits<float>::max() : mf.cap_combined_m;
  g.error_factor = mf.error_factor;
  return g;
}

}  // namespace gazelod::render
