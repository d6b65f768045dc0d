// SPDX-License-Identifier: Apache-2.0
// gazelod._gazelod: the perceptual core on numpy arrays. ObjectSet holds the objects in the
// selection's own layout (built once, in C++); select() runs lod::select_lods on them for one
// viewer, so a call costs the selection and two output arrays, nothing per object in Python.
#include "bindings/python/py_arrays.hpp"
#include "bindings/python/py_common.hpp"

#include "lod/display.hpp"
#include "lod/object_set.hpp"
#include "lod/select.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <string>

namespace gazelod::python {
namespace {

glm::dvec3 vec3(const Doubles& a, const char* what) {
  if (a.ndim() != 1 || a.shape(0) != 3) throw py::value_error(std::string(what) + " must have 3 components");
  return {a.at(0), a.at(1), a.at(2)};
}

struct PyObjects {
  lod::ObjectStore store;
  std::size_t size() const { return store.size(); }
};

// levels: (N, L) of removed detail per level (level 0 ignored); NaN pads a shorter chain.
PyObjects make_objects(const Doubles& centers, const Doubles& radii, const Doubles& levels, const std::string& kind,
                       std::optional<Doubles> velocities, const std::optional<py::object>& triangles) {
  if (centers.ndim() != 2 || centers.shape(1) != 3) throw py::value_error("centers must be an (N, 3) array");
  const py::ssize_t n = centers.shape(0);
  if (radii.ndim() != 1 || radii.shape(0) != n) throw py::value_error("radii must be an (N,) array");
  if (levels.ndim() != 2 || levels.shape(0) != n || levels.shape(1) < 1)
    throw py::value_error("levels must be an (N, L) array with L >= 1 (level 0 = full detail)");
  if (velocities && (velocities->ndim() != 2 || velocities->shape(0) != n || velocities->shape(1) != 3))
    throw py::value_error("velocities must be an (N, 3) array");
  lod::DetailKind k;
  if (kind == "geometric_error_m")
    k = lod::DetailKind::geometric_error_m;
  else if (kind == "removed_cycles_per_diameter")
    k = lod::DetailKind::removed_cycles_per_diameter;
  else
    throw py::value_error("kind must be 'geometric_error_m' or 'removed_cycles_per_diameter'");
  PyObjects o;
  const py::ssize_t width = levels.shape(1);
  const std::vector<std::uint32_t> counts =
      triangles ? triangle_table(*triangles, n, width) : std::vector<std::uint32_t>{};
  o.store.reserve(static_cast<std::size_t>(n), static_cast<std::size_t>(n * width));
  auto c = centers.unchecked<2>();
  auto r = radii.unchecked<1>();
  auto l = levels.unchecked<2>();
  std::vector<lod::LodLevel> chain;
  for (py::ssize_t i = 0; i < n; ++i) {
    chain.clear();
    const py::ssize_t length = chain_length(levels, i);
    for (py::ssize_t j = 0; j < length; ++j) {
      lod::LodLevel level;
      level.detail_kind = k;
      level.detail = j == 0 ? 0.0 : l(i, j);
      if (!counts.empty()) level.triangles = counts[i * width + j];
      chain.push_back(level);
    }
    const glm::dvec3 v =
        velocities ? glm::dvec3(velocities->at(i, 0), velocities->at(i, 1), velocities->at(i, 2)) : glm::dvec3(0.0);
    try {
      o.store.add({c(i, 0), c(i, 1), c(i, 2)}, r(i), v, chain);
    } catch (const std::invalid_argument& e) {
      throw py::value_error("object " + std::to_string(i) + ": " + e.what());
    }
  }
  return o;
}

lod::Viewer make_viewer(const py::kwargs& kw) {
  lod::Viewer v;
  // Both set the display's limit: whichever came last won, silently.
  if (kw.contains("hmd") && kw.contains("xi_cpd"))
    throw py::value_error("select(): give xi_cpd or hmd (a preset's xi), not both");
  for (auto item : kw) {
    const std::string key = py::str(item.first);
    const py::handle val = item.second;
    // None is no value: read as False for a flag, it turned a criterion off unseen.
    if (val.is_none()) throw py::type_error("select(): viewer field '" + key + "' is None");
    try {
      if (key == "gaze_direction")
        v.gaze_direction = vec3(doubles(val, "gaze_direction"), "gaze_direction");
      else if (key == "eye_position_m")
        v.eye_position_m = vec3(doubles(val, "eye_position_m"), "eye_position_m");
      else if (key == "eye_velocity_m_s")
        v.eye_velocity_m_s = vec3(doubles(val, "eye_velocity_m_s"), "eye_velocity_m_s");
      else if (key == "head_angular_velocity_rad_s")
        v.head_angular_velocity_rad_s = vec3(doubles(val, key), key.c_str());
      else if (key == "gaze_angular_velocity_in_head_rad_s")
        v.gaze_angular_velocity_in_head_rad_s = vec3(doubles(val, key), key.c_str());
      else if (key == "xi_cpd")
        v.xi_cpd = py::cast<double>(val);
      else if (key == "tracker_error_deg")
        v.tracker_error_deg = py::cast<double>(val);
      else if (key == "scale")
        v.scale = py::cast<double>(val);
      else if (key == "use_size")
        v.use_size = py::cast<bool>(val);
      else if (key == "use_eccentricity")
        v.use_eccentricity = py::cast<bool>(val);
      else if (key == "use_velocity")
        v.use_velocity = py::cast<bool>(val);
      else if (key == "hmd") {
        const std::string name = py::cast<std::string>(val);
        const lod::DisplaySpec* d = lod::find_display_preset(name);
        if (!d) throw py::value_error("unknown HMD preset '" + name + "' (gazelod.hmds() lists them)");
        v.xi_cpd = lod::xi_cpd(*d);
      } else {
        throw py::type_error("select() got an unexpected viewer field '" + key + "'");
      }
    } catch (const py::cast_error&) {
      throw py::type_error("select(): viewer field '" + key + "' has the wrong type (" +
                           std::string(py::str(py::type::of(val).attr("__name__"))) + ")");
    }
  }
  if (const std::string e = lod::validate_viewer(v); !e.empty()) throw py::value_error("viewer: " + e);
  return v;
}

py::dict select(const PyObjects& o, const py::kwargs& kw) {
  const lod::Viewer v = make_viewer(kw);
  const std::size_t n = o.size();
  py::array_t<std::uint8_t> level(static_cast<py::ssize_t>(n)), limited(static_cast<py::ssize_t>(n));
  std::vector<std::uint8_t> a(n), b(n), c(n);
  const lod::Decisions out{{level.mutable_data(), n}, {limited.mutable_data(), n}, a, b, c, {}, {}, {}};
  std::string err;
  {
    py::gil_scoped_release release;
    err = lod::select_lods(v, o.store.view(), out);
  }
  if (!err.empty()) throw py::value_error(err);
  py::dict d;
  d["level"] = level;
  d["limited_by"] = limited;  // 0 none, 1 size, 2 eccentricity, 3 velocity, 4 combined, 5 invalid input
  return d;
}

// The same selection timed in C++ alone (seconds per call, best of `repetitions` batches), for
// the binding's overhead benchmark (bench/python/bench_select.py).
double time_select_cpp(const PyObjects& o, int repetitions, int calls, const py::kwargs& kw) {
  const lod::Viewer v = make_viewer(kw);
  const std::size_t n = o.size();
  std::vector<std::uint8_t> l(n), m(n), a(n), b(n), c(n);
  const lod::Decisions out{l, m, a, b, c, {}, {}, {}};
  double best = 1e30;
  py::gil_scoped_release release;
  for (int r = 0; r < repetitions; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < calls; ++k) (void)lod::select_lods(v, o.store.view(), out);
    const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
    best = std::min(best, dt.count() / calls);
  }
  return best;
}

}  // namespace

void register_select(py::module_& m) {
  py::class_<PyObjects>(m, "ObjectSet")
      .def(py::init(&make_objects), py::arg("centers"), py::arg("radii"), py::arg("levels"),
           py::arg("kind") = "geometric_error_m", py::arg("velocities") = py::none(), py::arg("triangles") = py::none())
      .def("__len__", &PyObjects::size);
  m.def("select", &select, py::arg("objects"));
  m.def("_time_select_cpp", &time_select_cpp, py::arg("objects"), py::arg("repetitions"), py::arg("calls"));
  m.def("xi_cpd", [](const std::string& hmd) {
    const lod::DisplaySpec* d = lod::find_display_preset(hmd);
    if (!d) throw py::value_error("unknown HMD preset '" + hmd + "'");
    return lod::xi_cpd(*d);
  });
}

}  // namespace gazelod::python
