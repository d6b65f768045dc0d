// SPDX-License-Identifier: Apache-2.0
#include "gaze/import_sranipal.hpp"

#include "auxiliary/angles.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace gazelod::gaze {
namespace {

constexpr std::int64_t kUnixEpochTicks = 621'355'968'000'000'000;  // 1970-01-01 in .NET ticks
constexpr std::int64_t kOriginValid = 1 << 0, kDirectionValid = 1 << 1;
constexpr double kMaxOriginMm = 1000.0;
constexpr double kMaxHeadPositionM = 1e6;
// Unity writes Euler angles in [0, 360); past two turns a value is no angle it wrote (1e308 deg
// turned the head at random and raised the peak saccade speed from 451 to 2941 deg/s).
constexpr double kMaxHeadAngleDeg = 720.0;

const char* const kValid[2] = {"eye_valid_L", "eye_valid_R"};
const char* const kDirection[2][3] = {{"gaze_direct_L.x", "gaze_direct_L.y", "gaze_direct_L.z"},
                                      {"gaze_direct_R.x", "gaze_direct_R.y", "gaze_direct_R.z"}};
const char* const kOrigin[2][3] = {{"gaze_origin_L.x(mm)", "gaze_origin_L.y(mm)", "gaze_origin_L.z(mm)"},
                                   {"gaze_origin_R.x(mm)", "gaze_origin_R.y(mm)", "gaze_origin_R.z(mm)"}};
const char* const kHeadPosition[3] = {"helmet_pos_x", "helmet_pos_y", "helmet_pos_z"};
const char* const kHeadRotation[3] = {"helmet_rot_x", "helmet_rot_y", "helmet_rot_z"};

}  // namespace

std::optional<std::int64_t> dotnet_ticks_to_unix_ns(std::int64_t ticks) {
  // ticks - epoch cannot overflow for ticks >= 0; a negative tick count is no DateTime.
  if (ticks < 0) return std::nullopt;
  const std::int64_t since_epoch = ticks - kUnixEpochTicks;
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max() / 100;
  if (since_epoch > kMax || since_epoch < -kMax) return std::nullopt;
  return since_epoch * 100;
}

glm::dquat unity_euler_deg_to_openxr(const glm::dvec3& euler_deg) {
  const auto about = [](double deg, const glm::dvec3& axis) { return glm::angleAxis(deg * aux::kRadPerDeg, axis); };
  // Unity applies z first, then x, then y (each about the world's axes).
  const glm::dquat unity =
      about(euler_deg.y, {0, 1, 0}) * about(euler_deg.x, {1, 0, 0}) * about(euler_deg.z, {0, 0, 1});
  return glm::normalize(glm::dquat(unity.w, -unity.x, -unity.y, unity.z));
}

SranipalReader::SranipalReader(std::istream& in, std::string file, ReadOptions options)
    : CsvRecordStream(in, std::move(file), options, ';') {
  if (!cursor_.next_row()) cursor_.fail_no_header();
  const CsvHeader h(cursor_);
  fields_ = h.size();
  std::string missing;
  const auto need = [&](const char* name) {
    const auto i = h.find(name);
    if (!i) missing += std::string(missing.empty() ? "" : ",") + name;
    return i.value_or(0);
  };
  t_ = need("time(100ns)");
  for (std::size_t e = 0; e < 2; ++e) {
    valid_[e] = need(kValid[e]);
    for (std::size_t k = 0; k < 3; ++k) direction_[e][k] = need(kDirection[e][k]);
  }
  if (!missing.empty()) {
    // One column holding the names: the header is not split on the logger's semicolons.
    if (h.size() == 1 && cursor_.fields()[0].text.find("time(100ns),") != std::string_view::npos)
      cursor_.fail(0,
                   "an SRanipal (HTC Vive Pro Eye) header separated by commas: this layout is read with the "
                   "Unity logger's semicolons");
    cursor_.fail(0, "missing required SRanipal (HTC Vive Pro Eye) column(s): " + missing);
  }
  // Optional groups: used only when every column of the group is there.
  const auto group = [&](const char* const names[3]) -> std::optional<Cols3> {
    const auto a = h.find(names[0]), b = h.find(names[1]), c = h.find(names[2]);
    if (a && b && c) return Cols3{*a, *b, *c};
    return std::nullopt;
  };
  if (const auto l = group(kOrigin[0]), r = group(kOrigin[1]); l && r) origin_ = std::array<Cols3, 2>{*l, *r};
  if (const auto p = group(kHeadPosition), q = group(kHeadRotation); p && q) head_ = HeadCols{*p, *q};
  time_field_ = t_;
}

// The field as a number; a decimal comma (a logger run under a locale that writes them) is named.
double SranipalReader::number(std::size_t index, const char* name) const {
  const CsvField& f = cursor_.field(index, name);
  if (f.text.find(',') != std::string_view::npos)
    cursor_.fail(f.column, std::string(name) + ": '" + std::string(f.text) +
                               "' has a decimal comma (the logger wrote its locale's numbers); write them with '.'");
  return cursor_.number(index, name);
}

void SranipalReader::parse_row(TraceRecord& out) {
  const CsvCursor& c = cursor_;
  if (c.fields().size() != fields_)
    c.fail(0, "row has " + std::to_string(c.fields().size()) + " fields, header has " + std::to_string(fields_));
  const auto t_ns = dotnet_ticks_to_unix_ns(c.integer(t_, "time(100ns)"));
  if (!t_ns) c.fail(c.fields()[t_].column, "time(100ns): not a .NET tick count within +-292 years of 1970");
  out.gaze.t_ns = *t_ns;
  const auto vec = [&](const Cols3& cols, const char* const names[3]) {
    glm::dvec3 v;  // in column order, so the first bad field is the one named
    for (glm::length_t k = 0; k < 3; ++k) v[k] = number(cols[static_cast<std::size_t>(k)], names[k]);
    return v;
  };
  // The eyes whose direction is valid (bit 1; an eye's columns are read only then: SRanipal
  // writes zeros, or nothing, for an eye it lost), and the origins of those same eyes, so the
  // origin and the direction describe one cyclopean eye.
  glm::dvec3 direction_sum(0.0), origin_sum_mm(0.0);
  int eyes = 0, origins = 0;
  for (std::size_t e = 0; e < 2; ++e) {
    const std::int64_t bits = c.integer(valid_[e], kValid[e]);
    if (bits < 0 || bits > 31)
      c.fail(c.fields()[valid_[e]].column, std::string(kValid[e]) + ": must be in [0, 31] (validity bits)");
    if (!(bits & kDirectionValid)) continue;
    const glm::dvec3 d = vec(direction_[e], kDirection[e]);
    const double length = glm::length(d);
    if (length == 0.0) continue;  // flagged, but no vector: the eye is lost all the same
    if (std::fabs(length - 1.0) > 0.05)
      c.fail(c.fields()[direction_[e][0]].column, std::string(kDirection[e][0]).substr(0, 13) +
                                                      ": not a unit vector (length " + std::to_string(length) + ")");
    direction_sum += sranipal_to_openxr(d / length);
    ++eyes;
    if (origin_ && (bits & kOriginValid)) {
      const glm::dvec3 o = vec((*origin_)[e], kOrigin[e]);
      // An eye sits a few centimetres from the tracker; a metre away is no eye position.
      for (std::size_t k = 0; k < 3; ++k)
        if (std::fabs(o[static_cast<glm::length_t>(k)]) > kMaxOriginMm)
          c.fail(c.fields()[(*origin_)[e][k]].column,
                 std::string(kOrigin[e][k]) + ": beyond 1000 mm of the eye tracker");
      origin_sum_mm += sranipal_to_openxr(o);
      ++origins;
    }
  }
  out.gaze.valid = false;
  out.gaze.confidence = 0.0f;
  if (origins > 0) out.gaze.origin_m = origin_sum_mm / static_cast<double>(origins) * 1e-3;
  const double sum_length = glm::length(direction_sum);
  if (eyes > 0 && sum_length > 1e-9) {  // two valid eyes pointing exactly apart give no gaze
    out.gaze.direction = direction_sum / sum_length;
    out.gaze.valid = true;
    out.gaze.confidence = 0.5f * static_cast<float>(eyes);
  }
  out.has_head = head_.has_value();
  if (head_) {
    const glm::dvec3 p = vec(head_->position, kHeadPosition);
    for (std::size_t k = 0; k < 3; ++k)
      if (std::fabs(p[static_cast<glm::length_t>(k)]) > kMaxHeadPositionM)
        c.fail(c.fields()[head_->position[k]].column, std::string(kHeadPosition[k]) + ": beyond 1000 km of the origin");
    out.head.t_ns = out.gaze.t_ns;
    out.head.position_m = {p.x, p.y, -p.z};
    const glm::dvec3 euler_deg = vec(head_->rotation, kHeadRotation);
    for (std::size_t k = 0; k < 3; ++k)
      if (std::fabs(euler_deg[static_cast<glm::length_t>(k)]) > kMaxHeadAngleDeg)
        c.fail(c.fields()[head_->rotation[k]].column, std::string(kHeadRotation[k]) + ": beyond +-720 deg");
    out.head.orientation = unity_euler_deg_to_openxr(euler_deg);
    out.head.valid = true;
  }
}

}  // namespace gazelod::gaze
