// SPDX-License-Identifier: Apache-2.0
#include "gaze/import_pupil.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace gazelod::gaze {
namespace {

const char* const kGaze[3] = {"gaze_point_3d_x", "gaze_point_3d_y", "gaze_point_3d_z"};
const char* const kEye0[3] = {"eye_center0_3d_x", "eye_center0_3d_y", "eye_center0_3d_z"};
const char* const kEye1[3] = {"eye_center1_3d_x", "eye_center1_3d_y", "eye_center1_3d_z"};

// An eye centre is centimetres from the scene camera; a metre bounds any headset's geometry and
// keeps target - origin far from overflow.
constexpr double kMaxEyeCentreMm = 1000.0;

// |d| without overflow: a gaze point near the double range (finite, so accepted as a number)
// would square to infinity and normalise to NaN.
double scaled_length(const glm::dvec3& d) {
  const double m = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  if (!(m > 0.0) || !std::isfinite(m)) return m;
  return m * glm::length(d / m);
}

}  // namespace

glm::dvec3 pupil_camera_to_openxr_m(const glm::dvec3& p_mm) {
  return glm::dvec3(p_mm.x, -p_mm.y, -p_mm.z) * 1e-3;
}

PupilReader::PupilReader(std::istream& in, std::string file, ReadOptions options, PupilImportOptions pupil)
    : CsvRecordStream(in, std::move(file), options), pupil_(pupil) {
  if (!cursor_.next_row()) cursor_.fail_no_header();
  const CsvHeader h(cursor_);
  fields_ = h.size();
  std::string missing;
  auto need = [&](const char* name) {
    auto i = h.find(name);
    if (!i) missing += std::string(missing.empty() ? "" : ",") + name;
    return i.value_or(0);
  };
  t_ = need("gaze_timestamp");
  conf_ = need("confidence");
  gaze_ = {need(kGaze[0]), need(kGaze[1]), need(kGaze[2])};
  if (!missing.empty()) {
    std::string msg = "missing required Pupil gaze_positions.csv column(s): " + missing;
    if (h.find("norm_pos_x")) msg += " (a 2D-only export: norm_pos needs camera intrinsics, use a 3D gaze mapper)";
    cursor_.fail(0, msg);
  }
  auto group = [&](const char* const names[3]) -> std::optional<Cols3> {
    auto a = h.find(names[0]), b = h.find(names[1]), c = h.find(names[2]);
    if (a && b && c) return Cols3{*a, *b, *c};
    return std::nullopt;
  };
  eye0_ = group(kEye0);
  eye1_ = group(kEye1);
  time_field_ = t_;
}

std::optional<glm::dvec3> PupilReader::point_mm(const Cols3& cols, const char* const names[3]) const {
  glm::dvec3 p;
  for (int k = 0; k < 3; ++k) {
    auto v = cursor_.number_or_missing(cols[static_cast<std::size_t>(k)], names[k]);
    if (!v) return std::nullopt;
    p[k] = *v;
  }
  return p;
}

void PupilReader::parse_row(TraceRecord& out) {
  const CsvCursor& c = cursor_;
  if (c.fields().size() != fields_)
    c.fail(0, "row has " + std::to_string(c.fields().size()) + " fields, header has " + std::to_string(fields_));
  const auto t_ns = seconds_to_ns(c.number(t_, "gaze_timestamp"));
  if (!t_ns) c.fail(c.fields()[t_].column, "gaze_timestamp: out of range");
  out.gaze.t_ns = *t_ns;
  const double conf = c.number(conf_, "confidence");
  if (conf < 0.0 || conf > 1.0) c.fail(c.fields()[conf_].column, "confidence: must be in [0, 1]");
  out.gaze.confidence = static_cast<float>(conf);
  out.has_head = false;

  glm::dvec3 origin_mm(0.0);
  int eyes = 0;
  for (const auto& [cols, names] : {std::pair{eye0_, kEye0}, std::pair{eye1_, kEye1}}) {
    if (!cols) continue;
    if (auto e = point_mm(*cols, names)) {
      for (int k = 0; k < 3; ++k)
        if (!(std::abs((*e)[k]) <= kMaxEyeCentreMm))
          c.fail(c.fields()[(*cols)[static_cast<std::size_t>(k)]].column,
                 std::string(names[k]) + ": outside +-1000 mm of the scene camera (not an eye centre)");
      origin_mm += *e;
      ++eyes;
    }
  }
  if (eyes > 0) origin_mm /= static_cast<double>(eyes);
  const auto target = point_mm(gaze_, kGaze);
  out.gaze.valid = false;
  out.gaze.origin_m = pupil_camera_to_openxr_m(origin_mm);
  if (!target) return;  // missing 3D gaze point: invalid sample
  const glm::dvec3 d = pupil_camera_to_openxr_m(*target - origin_mm);
  const double len = scaled_length(d);
  if (!(len > 1e-9)) {
    if (conf >= pupil_.min_confidence) c.fail(c.fields()[gaze_[0]].column, "gaze point coincides with the eye centre");
    return;
  }
  out.gaze.direction = d / len;
  out.gaze.valid = conf >= pupil_.min_confidence;
}

}  // namespace gazelod::gaze
