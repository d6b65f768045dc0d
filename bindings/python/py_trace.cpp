// SPDX-License-Identifier: Apache-2.0
// gazelod._gazelod: traces as numpy arrays (read_trace) and their classification (classify),
// through the same readers and classifier as `gazelod trace stats`.
#include "bindings/python/py_common.hpp"

#include "gaze/trace_error.hpp"
#include "gaze/trace_open.hpp"
#include "gaze/trace_stats.hpp"

#include <pybind11/numpy.h>

#include <vector>

namespace gazelod::python {
namespace {

gaze::TraceFormat format_of(const std::string& name) {
  const auto f = gaze::parse_trace_format(name);
  if (!f)
    throw py::value_error("format '" + name +
                          "' is not one of auto, gazelod, gazebasevr, pupil, pupil_cloud, sranipal");
  return *f;
}

template <typename T>
py::array_t<T> to_array(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::array_t<double> to_array_n3(const std::vector<double>& v, py::ssize_t width) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()) / width, width});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict read_trace(const std::string& path, const std::string& format, bool lenient) {
  std::vector<std::int64_t> t;
  std::vector<std::uint8_t> valid, has_head;
  std::vector<float> confidence;
  std::vector<double> dir, origin, head_q, head_p;
  std::string detected;
  bool with_head = false;
  {
    py::gil_scoped_release release;
    gaze::ReadOptions options;
    options.lenient = lenient;
    auto stream = gaze::open_trace(path, format_of(format), options);
    detected =
        std::string(gaze::trace_format_name(gaze::opened_trace_format(*stream).value_or(gaze::TraceFormat::gazelod)));
    with_head = stream->has_head();
    gaze::TraceRecord r;
    while (stream->next(r)) {
      t.push_back(r.gaze.t_ns);
      valid.push_back(r.gaze.valid);
      confidence.push_back(r.gaze.confidence);
      dir.insert(dir.end(), {r.gaze.direction.x, r.gaze.direction.y, r.gaze.direction.z});
      origin.insert(origin.end(), {r.gaze.origin_m.x, r.gaze.origin_m.y, r.gaze.origin_m.z});
      if (with_head) {
        has_head.push_back(r.has_head && r.head.valid);
        const glm::dquat& q = r.head.orientation;
        head_q.insert(head_q.end(), {q.x, q.y, q.z, q.w});
        head_p.insert(head_p.end(), {r.head.position_m.x, r.head.position_m.y, r.head.position_m.z});
      }
    }
  }
  py::dict d;
  d["t_ns"] = to_array(t);
  d["valid"] = to_array(valid).attr("astype")("bool");
  d["direction"] = to_array_n3(dir, 3);
  d["origin_m"] = to_array_n3(origin, 3);
  d["confidence"] = to_array(confidence);
  if (with_head) {
    d["head_valid"] = to_array(has_head).attr("astype")("bool");
    d["head_orientation_xyzw"] = to_array_n3(head_q, 4);
    d["head_position_m"] = to_array_n3(head_p, 3);
  }
  d["format"] = detected;
  return d;
}

py::dict classify(const std::string& path, const std::string& format) {
  gaze::TraceStats st;
  gaze::TraceClassification c;
  {
    py::gil_scoped_release release;
    auto stream = gaze::open_trace(path, format_of(format));
    st = gaze::compute_trace_stats(*stream, {}, {}, {}, &c);
  }
  std::vector<std::uint8_t> label(c.label.size());
  std::transform(c.label.begin(), c.label.end(), label.begin(),
                 [](gaze::GazeLabel l) { return static_cast<std::uint8_t>(l); });
  std::vector<std::int64_t> s_start, s_end, f_start, f_end;
  std::vector<double> s_amp, s_peak;
  for (const auto& s : c.saccades) {
    s_start.push_back(s.start_ns), s_end.push_back(s.end_ns);
    s_amp.push_back(s.amplitude_deg), s_peak.push_back(s.peak_velocity_deg_s);
  }
  for (const auto& f : c.fixations) f_start.push_back(f.start_ns), f_end.push_back(f.end_ns);
  py::dict d;
  d["label"] = to_array(label);  // 0 fixation, 1 saccade, 2 invalid, 3 unknown
  d["velocity_deg_s"] = to_array(c.velocity_deg_s);
  py::dict sac;
  sac["start_ns"] = to_array(s_start), sac["end_ns"] = to_array(s_end);
  sac["amplitude_deg"] = to_array(s_amp), sac["peak_velocity_deg_s"] = to_array(s_peak);
  d["saccades"] = sac;
  py::dict fix;
  fix["start_ns"] = to_array(f_start), fix["end_ns"] = to_array(f_end);
  d["fixations"] = fix;
  py::dict stats;
  stats["samples"] = st.samples, stats["invalid"] = st.invalid, stats["with_head"] = st.with_head;
  stats["duration_s"] = st.duration_s, stats["rate_hz"] = st.rate_hz;
  stats["saccades"] = st.saccades, stats["fixations"] = st.fixations;
  stats["mean_saccade_amplitude_deg"] = st.mean_saccade_amplitude_deg;
  stats["max_saccade_peak_velocity_deg_s"] = st.max_saccade_peak_velocity_deg_s;
  stats["classified_in"] = st.classified_in_world ? (st.classified_in_head > 0 ? "head_then_world" : "world") : "head";
  d["stats"] = stats;
  return d;
}

}  // namespace

void register_trace(py::module_& m) {
  // A trace's errors name the file, line and column (TraceError): ValueError in Python.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const gaze::TraceError& e) {
      PyErr_SetString(PyExc_ValueError, utf8_of(e.what()).c_str());
    }
  });
  m.def("read_trace", &read_trace, py::arg("path"), py::arg("format") = "auto", py::arg("lenient") = false);
  m.def("classify", &classify, py::arg("path"), py::arg("format") = "auto");
}

}  // namespace gazelod::python
