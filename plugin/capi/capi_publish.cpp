// SPDX-License-Identifier: Apache-2.0
// A decided frame, published for readers (plugin/capi/capi_publish.hpp).
#include "plugin/capi/capi_publish.hpp"

#include "auxiliary/angles.hpp"
#include "lod/acuity.hpp"
#include "plugin/capi/capi_convert.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::capi {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

// Normalised image coordinate of a tangent between two edge tangents.
double along(double tan_at, double tan_low, double tan_high) {
  return (tan_at - tan_low) / (tan_high - tan_low);
}

// The extent (in normalised units) of +-a around angle c, on an axis with the given edges.
double extent(double c, double a, double lo, double hi) {
  const double a0 = std::clamp(c - a, -kHalfPi + 1e-6, kHalfPi - 1e-6);
  const double a1 = std::clamp(c + a, -kHalfPi + 1e-6, kHalfPi - 1e-6);
  return 0.5 * (std::tan(a1) - std::tan(a0)) / (std::tan(hi) - std::tan(lo));
}

}  // namespace

gzl_foveal_cone cone_in_view(const glm::dvec3& gaze_base, const glm::dquat& head, const plugin::ViewInput& view,
                             double fovea_deg, double uncertainty_deg) {
  gzl_foveal_cone c{};
  c.type = GZL_TYPE_FOVEAL_CONE;
  const glm::dvec3 d = glm::conjugate(view.orientation_in_head) * (glm::conjugate(head) * gaze_base);
  c.direction_in_view = to_gzl(d);
  c.fovea_deg = fovea_deg;
  c.uncertainty_deg = uncertainty_deg;
  c.half_angle_deg = std::min(180.0, fovea_deg + uncertainty_deg);
  const lod::FovRad& f = view.fov;
  // Angles of the gaze about the view's y (left/right) and x (up/down) axes, from atan2.
  const double ax = std::atan2(d.x, -d.z), ay = std::atan2(d.y, -d.z);
  const double a = c.half_angle_deg / aux::kDegPerRad;
  if (d.z < 0.0) {
    c.center_u = along(std::tan(ax), std::tan(f.angle_left_rad), std::tan(f.angle_right_rad));
    c.center_v = along(std::tan(ay), std::tan(f.angle_up_rad), std::tan(f.angle_down_rad));
    c.radius_u = extent(ax, a, f.angle_left_rad, f.angle_right_rad);
    c.radius_v = extent(ay, a, f.angle_down_rad, f.angle_up_rad);
    c.in_view = ax >= f.angle_left_rad && ax <= f.angle_right_rad && ay >= f.angle_down_rad && ay <= f.angle_up_rad;
  } else {
    // Behind the view: no centre on its image.
    c.center_u = c.center_v = 0.5;
    c.radius_u = c.radius_v = 0.0;
    c.in_view = 0;
  }
  return c;
}

void publish(gzl_plugin p, const FrameDecisions& d, std::int64_t t_ns) {
  plugin::LodCore& core = p->core();
  const FrameDiagnostics& diag = core.diagnostics();
  std::lock_guard lock(p->out_mu);
  Published& pub = p->pub;
  if (p->dense && p->disabled == 0) {
    std::copy(d.lod.begin(), d.lod.end(), pub.level_by_row.begin());
    std::fill(pub.decided_by_row.begin(), pub.decided_by_row.end(), std::uint8_t{1});
  } else {
    for (std::size_t s = 0; s < d.lod.size(); ++s) {
      const std::uint32_t row = p->row_of_slot[s];
      pub.level_by_row[row] = core.object_enabled(static_cast<std::uint32_t>(s)) ? d.lod[s] : GZL_LEVEL_DISABLED;
      pub.decided_by_row[row] = 1;
    }
  }
  ++p->frames;
  gzl_frame_info& i = pub.info;
  i.frame_index = p->frames;
  i.display_time_ns = t_ns;
  i.object_count = static_cast<std::uint32_t>(d.lod.size());
  i.gaze_source = d.gaze_source == GazeSourceKind::openxr   ? GZL_GAZE_SOURCE_OPENXR
                  : d.gaze_source == GazeSourceKind::pushed ? GZL_GAZE_SOURCE_PUSHED
                                                            : GZL_GAZE_SOURCE_HEAD_FIXED;
  i.eye_motion = static_cast<gzl_eye_motion>(diag.eye_motion);
  i.gaze_suppressed = diag.gaze_suppressed;
  i.head_valid = diag.head_valid;
  i.gaze_direction_base = to_gzl(diag.gaze_direction_world);
  i.eye_position_base_m = to_gzl(diag.eye_position_world);
  i.head_angular_velocity_rad_s = to_gzl(diag.head_angular_velocity_rad_s);
  i.head_linear_velocity_m_s = to_gzl(diag.head_linear_velocity_m_s);
  i.gaze_angular_velocity_in_head_rad_s = to_gzl(diag.gaze_angular_velocity_in_head_rad_s);
  i.gaze_uncertainty_deg = diag.gaze_error_deg;
  i.xi_cpd = diag.xi_cpd;

  const plugin::HeadMotion& head = core.head();
  const glm::dquat q = head.valid ? head.orientation : glm::dquat(1.0, 0.0, 0.0, 0.0);
  for (std::uint32_t v = 0; v < core.view_count(); ++v)
    pub.cones[v] =
        cone_in_view(diag.gaze_direction_world, q, core.views()[v], lod::kEccentricitySeamDeg, diag.gaze_error_deg);

  gzl_frame_record& r = pub.record;
  r.display_time_ns = t_ns;
  r.head = to_gzl_head(head);
  r.view_count = core.view_count();
  for (std::uint32_t v = 0; v < r.view_count; ++v) r.views[v] = to_gzl_view(core.views()[v]);
  // Replaying this frame through data mode means pushing what the gaze input gave: the sample,
  // or (it gave none) an invalid one at the last sample's time, so the replay has none either.
  const plugin::GazeRead& g = core.gaze_read();
  if (g.present) {
    r.has_gaze_sample = 1;
    r.gaze_sample = to_gzl_sample(g);
  } else if (r.has_gaze_sample) {
    r.gaze_sample.flags &= ~static_cast<std::uint32_t>(GZL_GAZE_SAMPLE_VALID);
  }
}

}  // namespace gazelod::capi
