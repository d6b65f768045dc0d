// SPDX-License-Identifier: Apache-2.0
// gazelod._gazelod.Plugin: the C ABI's data mode (include/gazelod/gazelod.h) driven from Python,
// frame by frame, with numpy arrays in and out. Every call goes through libgazelod's gzl_*
// functions, as any other language binding's would.
#include "bindings/python/py_arrays.hpp"
#include "bindings/python/py_common.hpp"

#include "gazelod/gazelod.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::python {
namespace {

std::string last_error(gzl_plugin p) {
  std::size_t n = 0;
  gzl_get_last_error(p, nullptr, 0, &n);
  std::string s(n + 1, '\0');
  gzl_get_last_error(p, s.data(), s.size(), nullptr);
  s.resize(n);
  return s;
}

void check(gzl_plugin p, gzl_result r) {
  if (r == GZL_SUCCESS) return;
  const std::string m = last_error(p) + " [" + gzl_result_to_string(r) + "]";
  if (r == GZL_ERROR_INTERNAL || r == GZL_ERROR_OUT_OF_MEMORY) throw std::runtime_error(m);
  throw py::value_error(m);
}

gzl_vec3 vec(const py::object& o, const char* what) {
  const Doubles a = doubles(o, what);
  if (a.ndim() != 1 || a.shape(0) != 3) throw py::value_error(std::string(what) + " must have 3 components");
  return {a.at(0), a.at(1), a.at(2)};
}

gzl_quat quat(const py::object& o, const char* what) {
  const Doubles a = doubles(o, what);
  if (a.ndim() != 1 || a.shape(0) != 4) throw py::value_error(std::string(what) + " must be (x, y, z, w)");
  return {a.at(0), a.at(1), a.at(2), a.at(3)};
}

gzl_level_metric metric_of(const std::string& m) {
  if (m == "geometric_error_m") return GZL_LEVEL_GEOMETRIC_ERROR_M;
  if (m == "removed_cycles_per_diameter") return GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER;
  if (m == "screen_height_share") return GZL_LEVEL_SCREEN_HEIGHT_SHARE;
  if (m == "pixels_at_full_height") return GZL_LEVEL_PIXELS_AT_FULL_HEIGHT;
  throw py::value_error(
      "metric must be geometric_error_m, removed_cycles_per_diameter, screen_height_share or "
      "pixels_at_full_height");
}

py::dict vec_dict(const gzl_vec3& v) {
  py::array_t<double> a(3);
  a.mutable_at(0) = v.x, a.mutable_at(1) = v.y, a.mutable_at(2) = v.z;
  return py::dict(py::arg("v") = a);
}

class Plugin {
 public:
  // views: a list of dicts {fov: (left, right, up, down) rad, width_px, height_px,
  // [position_in_head_m], [orientation_in_head_xyzw]}.
  Plugin(const py::list& views, bool disable_switch_policy, double gaze_accuracy_deg, double max_gaze_sample_age_s,
         const std::string& hmd_preset, double frame_budget_ms, const std::vector<std::string>& disabled_criteria) {
    std::vector<gzl_view> v;
    for (const py::handle h : views) {
      const std::string at = "views[" + std::to_string(v.size()) + "]";
      if (!py::isinstance<py::dict>(h)) throw py::value_error(at + " must be a dict {fov, width_px, height_px, ...}");
      const auto d = py::reinterpret_borrow<py::dict>(h);
      for (const char* key : {"fov", "width_px", "height_px"})
        if (!d.contains(key)) throw py::value_error(at + " has no " + key);
      gzl_view g{};
      const Doubles fov = doubles(d["fov"], at + ".fov");
      if (fov.ndim() != 1 || fov.shape(0) != 4)
        throw py::value_error(at + ".fov is (left, right, up, down) in radians");
      g.fov = {fov.at(0), fov.at(1), fov.at(2), fov.at(3)};
      g.width_px = pixel_count(d["width_px"], at + ".width_px");
      g.height_px = pixel_count(d["height_px"], at + ".height_px");
      if (d.contains("position_in_head_m"))
        g.position_in_head_m = vec(d["position_in_head_m"], (at + ".position_in_head_m").c_str());
      if (d.contains("orientation_in_head_xyzw"))
        g.orientation_in_head = quat(d["orientation_in_head_xyzw"], (at + ".orientation_in_head_xyzw").c_str());
      v.push_back(g);
    }
    gzl_config c{};
    c.type = GZL_TYPE_CONFIG;
    c.disable_switch_policy = disable_switch_policy;
    for (const std::string& name : disabled_criteria) {
      if (name == "size")
        c.disabled_criteria |= GZL_CRITERION_SIZE;
      else if (name == "eccentricity")
        c.disabled_criteria |= GZL_CRITERION_ECCENTRICITY;
      else if (name == "velocity")
        c.disabled_criteria |= GZL_CRITERION_VELOCITY;
      else
        throw py::value_error("disabled_criteria: '" + name + "' is not size, eccentricity or velocity");
    }
    c.gaze_accuracy_deg = gaze_accuracy_deg;
    c.max_gaze_sample_age_s = max_gaze_sample_age_s;
    c.frame_budget_ms = frame_budget_ms;
    c.hmd_preset = hmd_preset.c_str();
    gzl_data_create_info info{};
    info.type = GZL_TYPE_DATA_CREATE_INFO;
    info.view_count = static_cast<std::uint32_t>(v.size());
    info.views = v.data();
    info.config = &c;
    check(nullptr, gzl_create_data(&info, &p_));
  }
  ~Plugin() { gzl_destroy(p_); }
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  py::array_t<std::uint64_t> add_objects(const Doubles& centers, const Doubles& radii, const Doubles& levels,
                                         const std::string& metric, std::optional<Doubles> velocities,
                                         const std::optional<py::object>& triangles) {
    if (centers.ndim() != 2 || centers.shape(1) != 3) throw py::value_error("centers must be an (N, 3) array");
    const py::ssize_t n = centers.shape(0);
    if (radii.ndim() != 1 || radii.shape(0) != n) throw py::value_error("radii must be an (N,) array");
    if (levels.ndim() != 2 || levels.shape(0) != n) throw py::value_error("levels must be an (N, L) array");
    if (velocities && (velocities->ndim() != 2 || velocities->shape(0) != n || velocities->shape(1) != 3))
      throw py::value_error("velocities must be an (N, 3) array");
    const py::ssize_t width = levels.shape(1);
    const std::vector<std::uint32_t> counts =
        triangles ? triangle_table(*triangles, n, width) : std::vector<std::uint32_t>{};
    py::array_t<std::uint64_t> handles(n);
    std::vector<gzl_level> chain;
    for (py::ssize_t i = 0; i < n; ++i) {
      chain.clear();
      const py::ssize_t length = chain_length(levels, i);
      for (py::ssize_t j = 0; j < length; ++j)
        chain.push_back({j == 0 ? 0.0 : levels.at(i, j), counts.empty() ? 0u : counts[i * width + j]});
      gzl_object_desc d{};
      d.type = GZL_TYPE_OBJECT_DESC;
      d.center_m = {centers.at(i, 0), centers.at(i, 1), centers.at(i, 2)};
      d.radius_m = radii.at(i);
      if (velocities) d.velocity_m_s = {velocities->at(i, 0), velocities->at(i, 1), velocities->at(i, 2)};
      d.metric = metric_of(metric);
      d.level_count = static_cast<std::uint32_t>(chain.size());
      d.levels = chain.data();
      gzl_object o = GZL_NULL_OBJECT;
      const gzl_result r = gzl_add_object(p_, &d, &o);
      if (r != GZL_SUCCESS) {
        // All or nothing: the objects of this call registered so far are removed again.
        std::string why = last_error(p_);  // "gazelod: desc->...": the object's index after the prefix
        why.insert(why.rfind("gazelod: ", 0) == 0 ? 9 : 0, "objects[" + std::to_string(i) + "]: ");
        for (py::ssize_t k = 0; k < i; ++k) gzl_remove_object(p_, handles.at(k));
        throw py::value_error(why + " [" + gzl_result_to_string(r) + "]");
      }
      handles.mutable_at(i) = o;
    }
    return handles;
  }

  // Any shape, as levels() takes them (at(i) refused a 2-D array with "index dimension mismatch").
  using Handles = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>;
  void remove(const Handles& handles) {
    for (py::ssize_t i = 0; i < handles.size(); ++i) check(p_, gzl_remove_object(p_, handles.data()[i]));
  }
  void set_enabled(const Handles& handles, bool enabled) {
    for (py::ssize_t i = 0; i < handles.size(); ++i) check(p_, gzl_set_object_enabled(p_, handles.data()[i], enabled));
  }
  void session_state(int state, std::int64_t t_ns) { check(p_, gzl_on_session_state(p_, state, t_ns)); }

  // One sample, or arrays of them (t_ns (N,), direction (N, 3), valid (N,)).
  // Times are integer nanoseconds: a float array (1000.9, NaN) is refused, not truncated.
  void push_gaze(const py::object& t_ns, const Doubles& direction, const std::optional<py::object>& valid,
                 bool in_world) {
    const bool one = direction.ndim() == 1;
    const char* shapes = "direction is (3,) with one time, or (N, 3) with N times";
    if ((direction.ndim() != 1 && direction.ndim() != 2) || direction.shape(one ? 0 : 1) != 3)
      throw py::value_error(shapes);
    const py::ssize_t n = one ? 1 : direction.shape(0);
    py::array t_shape;
    const std::vector<std::int64_t> times = int64s(t_ns, "t_ns", &t_shape);
    if (t_shape.ndim() > 1 || static_cast<py::ssize_t>(times.size()) != n) throw py::value_error(shapes);
    using Flags = py::array_t<bool, py::array::c_style | py::array::forcecast>;
    Flags flags;
    if (valid) {
      flags = py::cast<Flags>(*valid);
      if (flags.ndim() > 1 || (flags.size() != 1 && flags.size() != n))
        throw py::value_error("valid is one flag or (N,) flags, one per sample; got " + std::to_string(flags.size()) +
                              " for " + std::to_string(n) + " samples");
    }
    for (py::ssize_t i = 0; i < n; ++i) {
      gzl_gaze_sample s{};
      s.type = GZL_TYPE_GAZE_SAMPLE;
      s.time_ns = times[static_cast<std::size_t>(i)];
      const double* d = direction.data() + 3 * i;
      s.direction = {d[0], d[1], d[2]};
      const bool ok = valid ? flags.data()[flags.size() == 1 ? 0 : i] : true;
      s.flags = (ok ? static_cast<std::uint32_t>(GZL_GAZE_SAMPLE_VALID) : 0u) |
                (in_world ? static_cast<std::uint32_t>(GZL_GAZE_SAMPLE_IN_WORLD) : 0u);
      check(p_, gzl_push_gaze_sample(p_, &s));
    }
  }

  void begin_frame(std::int64_t t_ns, const py::object& orientation_xyzw, const py::object& position_m,
                   const py::object& angular_velocity_rad_s, const py::object& linear_velocity_m_s) {
    gzl_frame_input in{};
    in.type = GZL_TYPE_FRAME_INPUT;
    in.display_time_ns = t_ns;
    in.head.orientation = quat(orientation_xyzw, "orientation_xyzw");
    in.head.position_m = vec(position_m, "position_m");
    in.head.flags = GZL_HEAD_POSE_VALID;
    if (!angular_velocity_rad_s.is_none()) {
      in.head.angular_velocity_rad_s = vec(angular_velocity_rad_s, "angular_velocity_rad_s");
      in.head.flags |= GZL_HEAD_ANGULAR_VELOCITY_VALID;
    }
    if (!linear_velocity_m_s.is_none()) {
      in.head.linear_velocity_m_s = vec(linear_velocity_m_s, "linear_velocity_m_s");
      in.head.flags |= GZL_HEAD_LINEAR_VELOCITY_VALID;
    }
    check(p_, gzl_begin_frame_data(p_, &in));
  }

  py::array_t<std::uint8_t> levels(
      const py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>& handles) {
    py::array_t<std::uint8_t> out(handles.size());
    check(p_, gzl_get_levels(p_, static_cast<std::uint32_t>(handles.size()), handles.data(), out.mutable_data()));
    return out;
  }

  py::dict frame_info() {
    gzl_frame_info i{};
    i.type = GZL_TYPE_FRAME_INFO;
    check(p_, gzl_get_frame_info(p_, &i));
    static const char* sources[] = {"head_fixed", "openxr", "pushed"};
    static const char* motions[] = {"fixation", "saccade", "pursuit", "loss"};
    py::dict d;
    d["frame_index"] = i.frame_index, d["display_time_ns"] = i.display_time_ns, d["object_count"] = i.object_count;
    d["gaze_source"] = sources[std::min<int>(i.gaze_source, 2)];
    d["eye_motion"] = motions[std::min<int>(i.eye_motion, 3)];
    d["gaze_suppressed"] = i.gaze_suppressed != 0, d["head_valid"] = i.head_valid != 0;
    d["gaze_direction_base"] = vec_dict(i.gaze_direction_base)["v"];
    d["eye_position_base_m"] = vec_dict(i.eye_position_base_m)["v"];
    d["head_angular_velocity_rad_s"] = vec_dict(i.head_angular_velocity_rad_s)["v"];
    d["head_linear_velocity_m_s"] = vec_dict(i.head_linear_velocity_m_s)["v"];
    d["gaze_angular_velocity_in_head_rad_s"] = vec_dict(i.gaze_angular_velocity_in_head_rad_s)["v"];
    d["gaze_uncertainty_deg"] = i.gaze_uncertainty_deg, d["xi_cpd"] = i.xi_cpd;
    d["triangles_drawn"] = i.triangles_drawn, d["triangles_full"] = i.triangles_full;
    return d;
  }

  py::dict foveal_cone(std::uint32_t view) {
    gzl_foveal_cone c{};
    c.type = GZL_TYPE_FOVEAL_CONE;
    check(p_, gzl_get_foveal_cone(p_, view, &c));
    py::dict d;
    d["direction_in_view"] = vec_dict(c.direction_in_view)["v"];
    d["fovea_deg"] = c.fovea_deg, d["uncertainty_deg"] = c.uncertainty_deg, d["half_angle_deg"] = c.half_angle_deg;
    d["center_uv"] = py::make_tuple(c.center_u, c.center_v);
    d["radius_uv"] = py::make_tuple(c.radius_u, c.radius_v);
    d["in_view"] = c.in_view != 0;
    return d;
  }

  std::string gaze_status() {
    std::size_t n = 0;
    check(p_, gzl_get_gaze_status(p_, nullptr, 0, &n));
    std::string s(n + 1, '\0');
    check(p_, gzl_get_gaze_status(p_, s.data(), s.size(), nullptr));
    s.resize(n);
    return s;
  }

 private:
  gzl_plugin p_ = nullptr;
};

}  // namespace

void register_plugin(py::module_& m) {
  m.def("abi_version", [] {
    const std::uint32_t v = gzl_version();
    return py::make_tuple(GZL_VERSION_MAJOR(v), GZL_VERSION_MINOR(v), GZL_VERSION_PATCH(v));
  });
  py::class_<Plugin>(m, "Plugin")
      .def(py::init<const py::list&, bool, double, double, const std::string&, double,
                    const std::vector<std::string>&>(),
           py::arg("views"), py::arg("disable_switch_policy") = false, py::arg("gaze_accuracy_deg") = 0.0,
           py::arg("max_gaze_sample_age_s") = 0.0, py::arg("hmd_preset") = "", py::arg("frame_budget_ms") = 0.0,
           py::arg("disabled_criteria") = std::vector<std::string>{})
      .def("add_objects", &Plugin::add_objects, py::arg("centers"), py::arg("radii"), py::arg("levels"),
           py::arg("metric") = "geometric_error_m", py::arg("velocities") = py::none(),
           py::arg("triangles") = py::none())
      .def("remove", &Plugin::remove, py::arg("handles"))
      .def("set_enabled", &Plugin::set_enabled, py::arg("handles"), py::arg("enabled"))
      .def("session_state", &Plugin::session_state, py::arg("state"), py::arg("t_ns"))
      .def("push_gaze", &Plugin::push_gaze, py::arg("t_ns"), py::arg("direction"), py::arg("valid") = py::none(),
           py::arg("in_world") = false)
      .def("begin_frame", &Plugin::begin_frame, py::arg("t_ns"),
           py::arg("orientation_xyzw") = py::make_tuple(0, 0, 0, 1), py::arg("position_m") = py::make_tuple(0, 0, 0),
           py::arg("angular_velocity_rad_s") = py::none(), py::arg("linear_velocity_m_s") = py::none())
      .def("levels", &Plugin::levels, py::arg("handles"))
      .def("frame_info", &Plugin::frame_info)
      .def("foveal_cone", &Plugin::foveal_cone, py::arg("view") = 0)
      .def("gaze_status", &Plugin::gaze_status);
}

}  // namespace gazelod::python
