// SPDX-License-Identifier: Apache-2.0
#include "gaze/import_pupil_cloud.hpp"

#include "gaze/trace_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string_view>

namespace gazelod::gaze {
namespace {

constexpr const char* kTimestamp = "timestamp [ns]";
constexpr const char* kAzimuth = "azimuth [deg]";
constexpr const char* kElevation = "elevation [deg]";
constexpr const char* kWorn = "worn";
constexpr const char* kFixationId = "fixation id";
constexpr const char* kBlinkId = "blink id";
constexpr const char* kRecordingId = "recording id";
constexpr const char* kBlinkStart = "start timestamp [ns]";
constexpr const char* kBlinkEnd = "end timestamp [ns]";

void check_field_count(const CsvCursor& c, std::size_t header_fields) {
  if (c.fields().size() != header_fields)
    c.fail(0, "row has " + std::to_string(c.fields().size()) + " fields, header has " + std::to_string(header_fields));
}

// Unix nanoseconds: non-negative, so differences between two of them cannot overflow.
std::int64_t unix_ns(const CsvCursor& c, std::size_t index, const char* name) {
  const std::int64_t t = c.integer(index, name);
  if (t < 0) c.fail(c.fields()[index].column, std::string(name) + ": negative Unix time");
  return t;
}

std::string missing_columns(const CsvHeader& h, std::initializer_list<const char*> names) {
  std::string missing;
  for (const char* n : names)
    if (!h.find(n)) missing += std::string(missing.empty() ? "" : ", ") + "'" + n + "'";
  return missing;
}

}  // namespace

PupilCloudBlinks read_pupil_cloud_blinks(std::istream& in, const std::string& file) {
  CsvCursor c(in, file);
  if (!c.next_row()) c.fail_no_header();
  const CsvHeader h(c);
  if (const std::string missing = missing_columns(h, {kBlinkStart, kBlinkEnd}); !missing.empty())
    c.fail(0, "missing required Pupil Cloud blinks.csv column(s): " + missing);
  const std::size_t start = *h.find(kBlinkStart), end = *h.find(kBlinkEnd);
  PupilCloudBlinks out{file, {}};
  while (c.next_row()) {
    check_field_count(c, h.size());
    PupilCloudBlink b{unix_ns(c, start, kBlinkStart), unix_ns(c, end, kBlinkEnd)};
    if (b.end_ns < b.start_ns) c.fail(c.fields()[end].column, std::string(kBlinkEnd) + ": before " + kBlinkStart);
    out.intervals.push_back(b);
  }
  std::stable_sort(out.intervals.begin(), out.intervals.end(),
                   [](const PupilCloudBlink& a, const PupilCloudBlink& b) { return a.start_ns < b.start_ns; });
  return out;
}

std::optional<std::string> pupil_cloud_blinks_path(const std::string& gaze_path) {
  namespace fs = std::filesystem;
  const fs::path p(gaze_path);
  const std::string name = p.filename().string();
  constexpr std::string_view kSuffix = "_gaze.csv";
  if (name == "gaze.csv") return (p.parent_path() / "blinks.csv").string();
  if (name.size() > kSuffix.size() && name.compare(name.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0)
    return (p.parent_path() / (name.substr(0, name.size() - kSuffix.size()) + "_blinks.csv")).string();
  return std::nullopt;
}

PupilCloudReader::PupilCloudReader(std::istream& in, std::string file, ReadOptions options, PupilCloudBlinks blinks)
    : CsvRecordStream(in, std::move(file), options), blinks_(std::move(blinks)) {
  if (!cursor_.next_row()) cursor_.fail_no_header();
  const CsvHeader h(cursor_);
  fields_ = h.size();
  if (const std::string missing = missing_columns(h, {kTimestamp, kAzimuth, kElevation}); !missing.empty()) {
    std::string msg = "missing required Pupil Cloud gaze.csv column(s): " + missing;
    if (h.find("gaze x [px]"))
      msg += " (gaze x/y [px] alone are scene-image pixels: a direction needs the camera's intrinsics)";
    cursor_.fail(0, msg);
  }
  t_ = *h.find(kTimestamp);
  azimuth_ = *h.find(kAzimuth);
  elevation_ = *h.find(kElevation);
  worn_ = h.find(kWorn);
  fixation_id_ = h.find(kFixationId);
  blink_id_ = h.find(kBlinkId);
  recording_id_ = h.find(kRecordingId);
  time_field_ = t_;
}

std::uint32_t PupilCloudReader::event_id(const std::optional<std::size_t>& col, const char* name) const {
  if (!col || cursor_.is_empty(*col)) return 0;
  const std::int64_t id = cursor_.integer(*col, name);
  if (id < 1 || id > std::numeric_limits<std::uint32_t>::max())
    cursor_.fail(cursor_.fields()[*col].column, std::string(name) + ": must be empty or an integer in [1, 4294967295]");
  return static_cast<std::uint32_t>(id);
}

bool PupilCloudReader::in_blink(std::int64_t t_unix_ns) {
  // Intervals sorted by start, samples in increasing time: one pass over both.
  const auto& v = blinks_.intervals;
  while (next_blink_ < v.size() && v[next_blink_].start_ns <= t_unix_ns) {
    blink_end_max_ns_ = any_blink_started_ ? std::max(blink_end_max_ns_, v[next_blink_].end_ns) : v[next_blink_].end_ns;
    any_blink_started_ = true;
    ++next_blink_;
  }
  return any_blink_started_ && t_unix_ns < blink_end_max_ns_;
}

void PupilCloudReader::parse_row(TraceRecord& out) {
  const CsvCursor& c = cursor_;
  check_field_count(c, fields_);
  const std::int64_t t = unix_ns(c, t_, kTimestamp);
  if (have_first_ && t <= last_unix_ns_)
    c.fail(c.fields()[t_].column,
           std::string(kTimestamp) + ": " + std::to_string(t) +
               (t == last_unix_ns_ ? " repeats the previous sample's time"
                                   : " is before the previous sample's " + std::to_string(last_unix_ns_)) +
               " (timestamps must increase)");
  if (recording_id_) {
    const std::string_view id = c.field(*recording_id_, kRecordingId).text;
    if (have_first_ && id != recording_id_value_)
      c.fail(c.fields()[*recording_id_].column, std::string(kRecordingId) + ": changes from '" + recording_id_value_ +
                                                    "' to '" + std::string(id) + "': export one recording per file");
  }
  bool worn = true;
  if (worn_) {
    const double w = c.number(*worn_, kWorn);
    if (w != 0.0 && w != 1.0) c.fail(c.fields()[*worn_].column, std::string(kWorn) + ": expected 0 or 1");
    worn = w == 1.0;
  }
  const auto az = c.number_or_missing(azimuth_, kAzimuth);
  const auto el = c.number_or_missing(elevation_, kElevation);
  if (az && std::abs(*az) > 180.0)
    c.fail(c.fields()[azimuth_].column, std::string(kAzimuth) + ": must be in [-180, 180]");
  if (el && std::abs(*el) > 90.0)
    c.fail(c.fields()[elevation_].column, std::string(kElevation) + ": must be in [-90, 90]");
  const PupilCloudEventIds ids{event_id(fixation_id_, kFixationId), event_id(blink_id_, kBlinkId)};

  // Nothing below throws: the reader's state advances only for an accepted row.
  // Without a blinks file (a pipe, a renamed export) the gaze's own `blink id` marks the same
  // samples: the blinks were dropped without a word, 2 376 of the sample export's 8 567 samples
  // read valid.
  const bool blink = blinks_.file.empty() ? ids.blink_id != 0 : in_blink(t);
  samples_in_blinks_ += blink;
  if (!have_first_) {
    first_unix_ns_ = t;
    if (recording_id_) recording_id_value_ = std::string(c.fields()[*recording_id_].text);
  }
  have_first_ = true;
  last_unix_ns_ = t;
  last_ids_ = ids;
  out.has_head = false;
  out.gaze.t_ns = t - first_unix_ns_;  // both >= 0: exact
  out.gaze.valid = worn && !blink && az && el;
  out.gaze.confidence = out.gaze.valid ? 1.0f : 0.0f;
  if (az && el) out.gaze.direction = direction_from_yaw_pitch_deg(*az, *el);
}

}  // namespace gazelod::gaze
