// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/family_recording.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/time.hpp"
#include "gaze/trace_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

namespace gazelod::cli {
namespace {

// What the recording replaces: the scripted head, eyes and blinks (the recording has its own).
// The tracker's effects (rate, latency, noise, dropouts, calibration offset) and the objects'
// stay.
const std::set<std::string> kReplaced = {"head_sweep", "head_turn",      "head_track", "saccades",
                                         "vor",        "smooth_pursuit", "blinks"};

}  // namespace

FamilyRecording read_family_recording(const std::string& path, gaze::TraceFormat format) {
  FamilyRecording r;
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(path, ec);
  r.path = ec ? path : abs.lexically_normal().string();
  r.format = format;
  std::int64_t first = 0, last = 0;
  int valid = 0;
  try {
    std::unique_ptr<gaze::RecordStream> stream = gaze::open_trace(r.path, format);
    r.has_head = stream->has_head();
    gaze::TraceRecord rec;
    bool any = false;
    while (stream->next(rec)) {
      if (!any) first = rec.gaze.t_ns, any = true;
      last = std::max(last, rec.gaze.t_ns);
      valid += rec.gaze.valid ? 1 : 0;
    }
  } catch (const gaze::TraceError& e) {
    throw UsageError(std::string("--recording: ") + e.what(), 1);
  }
  if (valid < 2) throw UsageError("--recording: " + path + ": fewer than two valid gaze samples", 1);
  r.span_s = aux::seconds_from_ns(last - first);
  if (!(r.span_s >= 1.0)) throw UsageError("--recording: " + path + ": shorter than 1 s", 1);
  return r;
}

double recording_duration_s(double duration_s, const FamilyRecording& recording) {
  return std::min(duration_s, std::floor(recording.span_s * 10.0) / 10.0);
}

std::string with_recording(const std::string& scenario_json, const FamilyRecording& recording) {
  nlohmann::json j = nlohmann::json::parse(scenario_json);
  const std::string format(gaze::trace_format_name(recording.format));
  nlohmann::json effects = nlohmann::json::array();
  if (recording.has_head)
    effects.push_back({{"type", "head_track"}, {"file", recording.path}, {"format", format}, {"relative", true}});
  effects.push_back({{"type", "gaze_track"}, {"file", recording.path}, {"format", format}});
  for (const nlohmann::json& e : j.at("effects"))
    if (!kReplaced.count(e.at("type").get<std::string>())) effects.push_back(e);
  j["effects"] = effects;
  j["duration_s"] = recording_duration_s(j.at("duration_s").get<double>(), recording);
  return j.dump(2);
}

std::string recording_summary(const std::string& summary, const FamilyRecording& recording) {
  // family_scenario's summary: head, eyes[, pursuit N deg/s], display, tracker, field.
  std::vector<std::string> parts;
  std::size_t at = 0;
  while (true) {
    const std::size_t comma = summary.find(", ", at);
    parts.push_back(summary.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 2;
  }
  std::ostringstream out;
  out << (recording.has_head ? "recorded eyes and head" : "recorded eyes, still head");
  std::size_t k = std::min<std::size_t>(2, parts.size());
  if (k < parts.size() && parts[k].rfind("pursuit", 0) == 0) ++k;
  for (; k < parts.size(); ++k) out << ", " << parts[k];
  return out.str();
}

}  // namespace gazelod::cli
