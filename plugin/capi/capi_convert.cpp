// SPDX-License-Identifier: Apache-2.0
// Conversions between the C ABI's structs and the engine's types (plugin/capi/capi_convert.hpp).
#include "plugin/capi/capi_convert.hpp"

#include "lod/display.hpp"
#include "plugin/capi/capi_errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gazelod::capi {
namespace {

Refusal invalid(const std::string& m) {
  return Refusal{GZL_ERROR_INVALID_ARGUMENT, "gazelod: " + m};
}

bool finite(double v) {
  return std::isfinite(v);
}

// A zero (or unset) value means the default; otherwise finite and in range.
// %g: std::to_string's %f printed 1e-310 (a unit slip) as "0.000000", as if 0 were refused.
std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

double or_default(double v, double def, double lo, double hi, const char* field) {
  if (v == 0.0) return def;
  if (!finite(v) || v < lo || v > hi)
    throw invalid(std::string("config->") + field + " = " + number(v) + " is outside [" + number(lo) + ", " +
                  number(hi) + "] (0 means the default)");
  return v;
}

}  // namespace

PluginConfig to_plugin_config(const gzl_config* c) {
  PluginConfig p;
  if (c == nullptr) return p;
  need_struct(c, GZL_TYPE_CONFIG, "config");
  if (c->disabled_criteria & ~7u)
    throw invalid("config->disabled_criteria has bits other than GZL_CRITERION_SIZE | ECCENTRICITY | VELOCITY");
  p.criteria.size = !(c->disabled_criteria & GZL_CRITERION_SIZE);
  p.criteria.eccentricity = !(c->disabled_criteria & GZL_CRITERION_ECCENTRICITY);
  p.criteria.velocity = !(c->disabled_criteria & GZL_CRITERION_VELOCITY);
  p.switch_policy = c->disable_switch_policy == 0;
  if (!finite(c->frame_budget_ms) || c->frame_budget_ms < 0.0 || c->frame_budget_ms > 1000.0)
    throw invalid("config->frame_budget_ms must be 0 (no budget) or in (0, 1000] ms");
  p.budget_ms = c->frame_budget_ms;
  p.openxr_gaze_error_deg = or_default(c->gaze_accuracy_deg, p.openxr_gaze_error_deg, 0.01, 45.0, "gaze_accuracy_deg");
  p.head_fixed_cone_deg = or_default(c->head_fixed_cone_deg, p.head_fixed_cone_deg, 0.0, 180.0, "head_fixed_cone_deg");
  p.gaze_silence_timeout_s =
      or_default(c->gaze_silence_timeout_s, p.gaze_silence_timeout_s, 0.01, 3600.0, "gaze_silence_timeout_s");
  p.max_pushed_sample_age_s =
      or_default(c->max_gaze_sample_age_s, p.max_pushed_sample_age_s, 0.001, 1.0, "max_gaze_sample_age_s");
  if (c->hmd_preset != nullptr) p.hmd_override = c->hmd_preset;
  return p;
}

OpenXrOptions to_openxr_options(const gzl_openxr_create_info& info) {
  OpenXrOptions o;
  switch (info.view_configuration_type) {
    case 0:
      o.view_configuration = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
      break;
    case XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO:
    case XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO:
    case XR_VIEW_CONFIGURATION_TYPE_PRIMARY_QUAD_VARJO:
      o.view_configuration = static_cast<XrViewConfigurationType>(info.view_configuration_type);
      break;
    default:
      throw invalid("info->view_configuration_type " + std::to_string(info.view_configuration_type) +
                    " is not PRIMARY_MONO (1), PRIMARY_STEREO (2) or PRIMARY_QUAD_VARJO (1000037000)");
  }
  switch (enum_value(info.gaze_input)) {
    case GZL_GAZE_INPUT_APP_SPACE:
      // gaze_space may come later (gzl_set_gaze_space).
      o.gaze_input = OpenXrGazeInput::app_space;
      o.gaze_space = from_handle<XrSpace>(info.gaze_space);
      o.gaze_action = from_handle<XrAction>(info.gaze_action);
      break;
    case GZL_GAZE_INPUT_MERGE_BINDING:
      o.gaze_input = OpenXrGazeInput::merge_binding;
      break;
    case GZL_GAZE_INPUT_PUSHED:
      o.gaze_input = OpenXrGazeInput::pushed;
      break;
    case GZL_GAZE_INPUT_PLUGIN_ACTIONS:
      o.gaze_input = OpenXrGazeInput::plugin_actions;
      break;
    case GZL_GAZE_INPUT_NONE:
      o.gaze_input = OpenXrGazeInput::none;
      break;
    default:
      throw invalid("info->gaze_input " + std::to_string(enum_value(info.gaze_input)) +
                    " is not a gzl_gaze_input value");
  }
  return o;
}

std::uint32_t check_views(std::uint32_t count, const gzl_view* views, const char* what, bool optional) {
  if (count == 0 && optional) return 0;
  if (count != 1 && count != 2 && count != 4)
    throw invalid(std::string(what) + ": view_count " + std::to_string(count) + " (gazelod takes 1, 2 or 4 views)");
  if (views == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, std::string("gazelod: ") + what + " is NULL"};
  for (std::uint32_t i = 0; i < count; ++i) {
    const gzl_view& v = views[i];
    const std::string at = std::string(what) + "[" + std::to_string(i) + "]";
    lod::ViewSpec spec;
    spec.width_px = static_cast<int>(std::min<std::uint32_t>(v.width_px, 1u << 20));
    spec.height_px = static_cast<int>(std::min<std::uint32_t>(v.height_px, 1u << 20));
    spec.fov = {v.fov.angle_left, v.fov.angle_right, v.fov.angle_up, v.fov.angle_down};
    if (v.width_px == 0 || v.height_px == 0 || v.width_px > 65536 || v.height_px > 65536)
      throw invalid(at + ": width_px and height_px must be 1..65536 (the resolution rendered)");
    if (const std::string e = lod::validate_view(spec); !e.empty()) throw invalid(at + ".fov: " + e);
    (void)to_vec(v.position_in_head_m, (at + ".position_in_head_m").c_str());
    const gzl_quat& q = v.orientation_in_head;
    if (!(q.x == 0 && q.y == 0 && q.z == 0 && q.w == 0)) (void)to_quat(q, (at + ".orientation_in_head").c_str());
  }
  return count;
}

plugin::ViewInput to_view_input(const gzl_view& v) {
  plugin::ViewInput out;
  out.fov = {v.fov.angle_left, v.fov.angle_right, v.fov.angle_up, v.fov.angle_down};
  const gzl_quat& q = v.orientation_in_head;
  if (!(q.x == 0 && q.y == 0 && q.z == 0 && q.w == 0)) out.orientation_in_head = to_quat(q, "view orientation");
  out.position_in_head_m = {v.position_in_head_m.x, v.position_in_head_m.y, v.position_in_head_m.z};
  out.width_px = static_cast<int>(v.width_px);
  out.height_px = static_cast<int>(v.height_px);
  return out;
}

gzl_view to_gzl_view(const plugin::ViewInput& v) {
  gzl_view out{};
  out.fov = {v.fov.angle_left_rad, v.fov.angle_right_rad, v.fov.angle_up_rad, v.fov.angle_down_rad};
  out.orientation_in_head = to_gzl(v.orientation_in_head);
  out.position_in_head_m = to_gzl(v.position_in_head_m);
  out.width_px = static_cast<std::uint32_t>(v.width_px);
  out.height_px = static_cast<std::uint32_t>(v.height_px);
  return out;
}

glm::dvec3 to_vec(const gzl_vec3& v, const char* what) {
  if (!finite(v.x) || !finite(v.y) || !finite(v.z)) throw invalid(std::string(what) + " is not finite");
  return {v.x, v.y, v.z};
}

glm::dquat to_quat(const gzl_quat& q, const char* what) {
  // The norm scaled by the largest component: the plain sum of squares overflows past ~1e154
  // and refused a finite quaternion as "not finite".
  const double m = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), std::abs(q.w)});
  double n = 0.0;
  if (finite(m) && m > 0.0)
    n = m * std::sqrt((q.x / m) * (q.x / m) + (q.y / m) * (q.y / m) + (q.z / m) * (q.z / m) + (q.w / m) * (q.w / m));
  if (!finite(n) || n < 1e-6) throw invalid(std::string(what) + " must be a finite, non-zero quaternion");
  // A unit quaternion (a recorded pose) stays bit for bit what it was.
  const double s = std::abs(n - 1.0) > 1e-9 ? 1.0 / n : 1.0;
  return glm::dquat(q.w * s, q.x * s, q.y * s, q.z * s);
}

gzl_vec3 to_gzl(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}
gzl_quat to_gzl(const glm::dquat& q) {
  return {q.x, q.y, q.z, q.w};
}

std::vector<lod::LodLevel> to_levels(const gzl_object_desc& d, int view_height_px) {
  if (d.level_count == 0 || d.level_count > 255) throw invalid("desc->level_count must be 1..255");
  if (d.levels == nullptr) throw Refusal{GZL_ERROR_NULL_POINTER, "gazelod: desc->levels is NULL"};
  const std::int32_t metric = enum_value(d.metric);
  const bool engine = metric == GZL_LEVEL_SCREEN_HEIGHT_SHARE || metric == GZL_LEVEL_PIXELS_AT_FULL_HEIGHT;
  if (metric != GZL_LEVEL_GEOMETRIC_ERROR_M && metric != GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER && !engine)
    throw invalid("desc->metric " + std::to_string(metric) + " is not a gzl_level_metric value");
  if (engine && !(d.radius_m > 0.0))
    throw invalid("desc->radius_m must be > 0 for screen-size levels (they are converted with the object's size)");
  if (engine && view_height_px <= 0) throw invalid("no view resolution known to convert screen-size levels");
  std::vector<lod::LodLevel> out(d.level_count);
  const double diameter_m = 2.0 * d.radius_m, h_px = static_cast<double>(view_height_px);
  for (std::uint32_t k = 0; k < d.level_count; ++k) {
    const double v = d.levels[k].value;
    out[k].triangles = d.levels[k].triangles;
    out[k].detail_kind = metric == GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER ? lod::DetailKind::removed_cycles_per_diameter
                                                                         : lod::DetailKind::geometric_error_m;
    if (k == 0) continue;  // full detail
    const std::string at = "desc->levels[" + std::to_string(k) + "].value";
    if (!finite(v) || v <= 0.0) throw invalid(at + " must be finite and > 0");
    switch (metric) {
      case GZL_LEVEL_SCREEN_HEIGHT_SHARE:
        // One pixel of error when the sphere covers share v of the view's height.
        if (v > 1.0) throw invalid(at + " is a share of the view's height: (0, 1]");
        out[k].detail = diameter_m / (v * h_px);
        break;
      case GZL_LEVEL_PIXELS_AT_FULL_HEIGHT:
        out[k].detail = v * diameter_m / h_px;
        break;
      default:
        out[k].detail = v;
        break;
    }
  }
  return out;
}

plugin::PushedSample to_pushed(const gzl_gaze_sample& s) {
  plugin::PushedSample p;
  p.sample.t_ns = s.time_ns;
  p.sample.direction = {s.direction.x, s.direction.y, s.direction.z};
  p.sample.origin_m = {s.origin_m.x, s.origin_m.y, s.origin_m.z};
  p.sample.valid = (s.flags & GZL_GAZE_SAMPLE_VALID) != 0;
  p.sample.confidence = p.sample.valid ? 1.0f : 0.0f;
  p.in_world = (s.flags & GZL_GAZE_SAMPLE_IN_WORLD) != 0;
  p.has_head_orientation = (s.flags & GZL_GAZE_SAMPLE_HEAD_ORIENTATION) != 0;
  if (p.has_head_orientation) {
    const gzl_quat& q = s.head_orientation;
    p.head_orientation = glm::dquat(q.w, q.x, q.y, q.z);  // checked by the source
  }
  return p;
}

gzl_gaze_sample to_gzl_sample(const plugin::GazeRead& g) {
  gzl_gaze_sample s{};
  s.type = GZL_TYPE_GAZE_SAMPLE;
  s.time_ns = g.sample.t_ns;
  s.direction = to_gzl(g.sample.direction);
  s.origin_m = to_gzl(g.sample.origin_m);
  s.flags =
      (g.sample.valid ? static_cast<std::uint32_t>(GZL_GAZE_SAMPLE_VALID) : 0u) | GZL_GAZE_SAMPLE_HEAD_ORIENTATION;
  s.head_orientation = to_gzl(g.head_orientation);
  return s;
}

plugin::HeadMotion to_head(const gzl_head_pose& h, bool& angular_given, bool& linear_given) {
  plugin::HeadMotion m;
  angular_given = linear_given = false;
  if (!(h.flags & GZL_HEAD_POSE_VALID)) return m;
  m.orientation = to_quat(h.orientation, "input->head.orientation");
  m.position_m = to_vec(h.position_m, "input->head.position_m");
  angular_given = (h.flags & GZL_HEAD_ANGULAR_VELOCITY_VALID) != 0;
  linear_given = (h.flags & GZL_HEAD_LINEAR_VELOCITY_VALID) != 0;
  if (angular_given) m.angular_velocity_rad_s = to_vec(h.angular_velocity_rad_s, "input->head.angular_velocity_rad_s");
  if (linear_given) m.linear_velocity_m_s = to_vec(h.linear_velocity_m_s, "input->head.linear_velocity_m_s");
  m.valid = true;
  return m;
}

gzl_head_pose to_gzl_head(const plugin::HeadMotion& h) {
  gzl_head_pose p{};
  if (!h.valid) return p;
  p.orientation = to_gzl(h.orientation);
  p.position_m = to_gzl(h.position_m);
  p.angular_velocity_rad_s = to_gzl(h.angular_velocity_rad_s);
  p.linear_velocity_m_s = to_gzl(h.linear_velocity_m_s);
  p.flags = GZL_HEAD_POSE_VALID | GZL_HEAD_ANGULAR_VELOCITY_VALID | GZL_HEAD_LINEAR_VELOCITY_VALID;
  return p;
}

}  // namespace gazelod::capi
