// SPDX-License-Identifier: Apache-2.0
#include "gaze/trace_reader.hpp"

#include "auxiliary/yaw_pitch.hpp"
#include "gaze/trace_format.hpp"

#include <glm/geometric.hpp>

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gazelod::gaze {
namespace {

namespace tf = trace_format;

// Physical ranges, as the SRanipal importer has them: an eye within 1 m of the head's origin, a
// head within 1000 km of the world's. A head at 1e308 m passed, and the run drew nothing in view.
constexpr double kMaxEyeOffsetM = 1.0;
constexpr double kMaxHeadPositionM = 1e6;

int parse_version(const CsvCursor& c) {
  for (const std::string& comment : c.leading_comments()) {
    std::string_view s(comment);
    if (s.substr(0, tf::kMagic.size()) != tf::kMagic) continue;
    s.remove_prefix(tf::kMagic.size());
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    int v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || v < 1) throw TraceError({c.file(), 0, 0, "bad format version line '" + comment + "'"});
    if (v > tf::kVersion)
      throw TraceError({c.file(), 0, 0,
                        "format version " + std::to_string(v) + " is newer than this reader (" +
                            std::to_string(tf::kVersion) + ")"});
    return v;
  }
  return 0;
}

}  // namespace

glm::dvec3 direction_from_yaw_pitch_deg(double yaw_right_deg, double pitch_up_deg) {
  return aux::direction_from(aux::yaw_pitch_from_yaw_right_deg(yaw_right_deg, pitch_up_deg));
}

TraceReader::TraceReader(std::istream& in, std::string file, ReadOptions options)
    : CsvRecordStream(in, std::move(file), options) {
  if (!cursor_.next_row()) cursor_.fail_no_header();
  version_ = parse_version(cursor_);
  const CsvHeader h(cursor_);
  header_fields_ = h.size();
  std::vector<std::string> missing;
  auto need = [&](std::string_view n) {
    auto i = h.find(n);
    if (!i) missing.emplace_back(n);
    return i.value_or(0);
  };
  // A group is optional, but once one of its columns is present all of them are required.
  auto group_present = [&](std::initializer_list<std::string_view> names) {
    for (auto n : names)
      if (h.find(n)) return true;
    return false;
  };

  if (auto t = h.find(tf::kTimeNs)) {
    time_field_ = *t;
  } else if (auto ts = h.find(tf::kTimeS)) {
    time_field_ = *ts;
    time_ns_ = false;
  } else {
    missing.emplace_back("t_ns or t_s");
  }
  if (group_present({tf::kGazeX, tf::kGazeY, tf::kGazeZ})) {
    gaze_vec_ = Cols3{need(tf::kGazeX), need(tf::kGazeY), need(tf::kGazeZ)};
  } else if (group_present({tf::kYawDeg, tf::kPitchDeg})) {
    yaw_pitch_ = std::pair{need(tf::kYawDeg), need(tf::kPitchDeg)};
  } else {
    missing.emplace_back("gaze_x,gaze_y,gaze_z or gaze_yaw_deg,gaze_pitch_deg");
  }
  if (group_present({tf::kEyeX, tf::kEyeY, tf::kEyeZ})) eye_ = Cols3{need(tf::kEyeX), need(tf::kEyeY), need(tf::kEyeZ)};
  if (group_present({tf::kHeadQw, tf::kHeadQx, tf::kHeadQy, tf::kHeadQz}))
    head_q_ = Cols4{need(tf::kHeadQw), need(tf::kHeadQx), need(tf::kHeadQy), need(tf::kHeadQz)};
  if (group_present({tf::kHeadPx, tf::kHeadPy, tf::kHeadPz})) {
    head_p_ = Cols3{need(tf::kHeadPx), need(tf::kHeadPy), need(tf::kHeadPz)};
    if (!head_q_) missing.emplace_back("head_qw,head_qx,head_qy,head_qz (head_p* given)");
  }
  valid_ = h.find(tf::kValid);
  confidence_ = h.find(tf::kConfidence);
  head_valid_ = h.find(tf::kHeadValid);
  if (!missing.empty()) {
    std::string msg = "missing required column(s): ";
    for (std::size_t i = 0; i < missing.size(); ++i) msg += (i ? "; " : "") + missing[i];
    cursor_.fail(0, msg);
  }
}

void TraceReader::parse_row(TraceRecord& out) {
  const CsvCursor& c = cursor_;
  if (c.fields().size() != header_fields_)
    c.fail(0, "row has " + std::to_string(c.fields().size()) + " fields, header has " + std::to_string(header_fields_));
  GazeSample& g = out.gaze;
  if (time_ns_) {
    g.t_ns = c.integer(time_field_, tf::kTimeNs);
  } else {
    const auto ns = seconds_to_ns(c.number(time_field_, tf::kTimeS));
    if (!ns) c.fail(c.fields()[time_field_].column, "t_s: out of range");
    g.t_ns = *ns;
  }
  g.valid = true;
  if (valid_) {
    const auto& f = c.field(*valid_, tf::kValid);
    if (f.text != "0" && f.text != "1") c.fail(f.column, "valid: expected 0 or 1");
    g.valid = f.text == "1";
  }
  g.confidence = g.valid ? 1.0f : 0.0f;
  if (confidence_) {
    const double conf = c.number(*confidence_, tf::kConfidence);
    if (conf < 0.0 || conf > 1.0) c.fail(c.fields()[*confidence_].column, "confidence: must be in [0, 1]");
    g.confidence = static_cast<float>(conf);
  }
  std::size_t gaze_col = 0;
  if (gaze_vec_) {
    gaze_col = c.fields()[gaze_vec_->x].column;
    g.direction = {c.number(gaze_vec_->x, tf::kGazeX), c.number(gaze_vec_->y, tf::kGazeY),
                   c.number(gaze_vec_->z, tf::kGazeZ)};
  } else {
    gaze_col = c.fields()[yaw_pitch_->first].column;
    const double yaw = c.number(yaw_pitch_->first, tf::kYawDeg);
    const double pitch = c.number(yaw_pitch_->second, tf::kPitchDeg);
    if (yaw < -180.0 || yaw > 180.0) c.fail(gaze_col, "gaze_yaw_deg: must be in [-180, 180]");
    if (pitch < -90.0 || pitch > 90.0)
      c.fail(c.fields()[yaw_pitch_->second].column, "gaze_pitch_deg: must be in [-90, 90]");
    g.direction = direction_from_yaw_pitch_deg(yaw, pitch);
  }
  // An invalid sample's direction is never used (trackers write 0,0,0 during blinks).
  if (g.valid) {
    const double n = glm::length(g.direction);
    if (n == 0.0) c.fail(gaze_col, "zero gaze vector");
    if (std::fabs(n - 1.0) > kUnitTolerance)
      c.fail(gaze_col, "gaze vector is not unit length (|g| = " + std::to_string(n) + ")");
  }
  if (eye_) {
    g.origin_m = {c.number(eye_->x, tf::kEyeX), c.number(eye_->y, tf::kEyeY), c.number(eye_->z, tf::kEyeZ)};
    const std::size_t cols[3] = {eye_->x, eye_->y, eye_->z};
    const std::string_view names[3] = {tf::kEyeX, tf::kEyeY, tf::kEyeZ};
    for (int k = 0; k < 3; ++k)
      if (std::fabs(g.origin_m[k]) > kMaxEyeOffsetM)
        c.fail(c.fields()[cols[k]].column, std::string(names[k]) + ": beyond 1 m of the head's origin");
  }

  out.has_head = false;
  if (head_q_) {
    // A row whose head cells are all empty has no head pose (the writer does this).
    bool all_empty =
        c.is_empty(head_q_->w) && c.is_empty(head_q_->x) && c.is_empty(head_q_->y) && c.is_empty(head_q_->z);
    if (head_p_) all_empty = all_empty && c.is_empty(head_p_->x) && c.is_empty(head_p_->y) && c.is_empty(head_p_->z);
    if (head_valid_) all_empty = all_empty && c.is_empty(*head_valid_);
    if (!all_empty) {
      HeadSample& h = out.head;
      out.has_head = true;
      h.t_ns = g.t_ns;
      h.orientation = glm::dquat(c.number(head_q_->w, tf::kHeadQw), c.number(head_q_->x, tf::kHeadQx),
                                 c.number(head_q_->y, tf::kHeadQy), c.number(head_q_->z, tf::kHeadQz));
      const double qn = std::sqrt(glm::dot(h.orientation, h.orientation));
      if (std::fabs(qn - 1.0) > kUnitTolerance)
        c.fail(c.fields()[head_q_->w].column, "head quaternion is not unit length (|q| = " + std::to_string(qn) + ")");
      if (head_p_) {
        h.position_m = {c.number(head_p_->x, tf::kHeadPx), c.number(head_p_->y, tf::kHeadPy),
                        c.number(head_p_->z, tf::kHeadPz)};
        const std::size_t cols[3] = {head_p_->x, head_p_->y, head_p_->z};
        const std::string_view names[3] = {tf::kHeadPx, tf::kHeadPy, tf::kHeadPz};
        for (int k = 0; k < 3; ++k)
          if (std::fabs(h.position_m[k]) > kMaxHeadPositionM)
            c.fail(c.fields()[cols[k]].column, std::string(names[k]) + ": beyond 1000 km of the origin");
      }
      h.valid = true;
      if (head_valid_) {
        const auto& f = c.field(*head_valid_, tf::kHeadValid);
        if (f.text != "0" && f.text != "1") c.fail(f.column, "head_valid: expected 0 or 1");
        h.valid = f.text == "1";
      }
    }
  }
}

}  // namespace gazelod::gaze
