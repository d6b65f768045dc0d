// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/family_recording.hpp"

#include "apps/gazelod/eval/family.hpp"
#include "apps/gazelod/run/session.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/time.hpp"
#include "gaze/trace_error.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
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
  // The span between the first and the last VALID samples: rows after the last valid one would
  // replay as one long blink, every frame suppressed and nothing audited.
  std::int64_t first_valid_ns = 0, last_valid_ns = 0;
  int valid = 0, poses = 0;
  try {
    std::unique_ptr<gaze::RecordStream> stream = gaze::open_trace(r.path, format);
    gaze::TraceRecord rec;
    while (stream->next(rec)) {
      poses += rec.has_head && rec.head.valid ? 1 : 0;
      if (!rec.gaze.valid) continue;
      if (valid++ == 0) first_valid_ns = rec.gaze.t_ns;
      last_valid_ns = rec.gaze.t_ns;
    }
  } catch (const gaze::TraceError& e) {
    throw UsageError(std::string("--recording: ") + e.what());  // bad input (exit 2), as run --trace
  }
  if (valid < 2) throw UsageError("--recording: " + r.path + ": fewer than two valid gaze samples");
  // head_track needs two poses; with fewer the head stands still and gaze_track labels in it.
  r.has_head = poses >= 2;
  r.span_s = aux::seconds_from_ns(last_valid_ns - first_valid_ns);
  if (!(r.span_s >= 1.0)) throw UsageError("--recording: " + r.path + ": its valid samples span less than 1 s");
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
  // A walking seed's walk is the field coming toward the viewer (and the pursuit target with
  // it), not an effect: the recorded head moves as it moved, so the field stands still.
  nlohmann::json& scene = j.at("scene");
  double walk_m_s = 0.0;
  for (nlohmann::json& g : scene["generators"])
    if (g.contains("forward_speed_m_s")) walk_m_s = g["forward_speed_m_s"].get<double>(), g["forward_speed_m_s"] = 0.0;
  if (walk_m_s != 0.0)
    for (nlohmann::json& o : scene["objects"])
      if (o.contains("velocity_m_s")) o["velocity_m_s"][2] = o["velocity_m_s"][2].get<double>() + walk_m_s;
  j["duration_s"] = recording_duration_s(j.at("duration_s").get<double>(), recording);
  return aux::json_text(j, 2);
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

void apply_recording_flags(const std::string* recording, const std::string& format, const std::string& criteria,
                           FamilySettings& settings) {
  const std::optional<gaze::TraceFormat> parsed = gaze::parse_trace_format(format);
  if (!parsed) throw UsageError("--recording-format: unknown trace format '" + format + "'");
  if (recording && recording->empty()) throw UsageError("--recording: expected a file, got ''");
  const std::string chosen = !criteria.empty() ? criteria : recording ? "size,eccentricity" : "all";
  settings.criteria = parse_criteria(chosen);
  if (chosen != "all") settings.changed.push_back("criteria=" + chosen);
  if (!recording) return;
  settings.recording = read_family_recording(*recording, *parsed);
  settings.changed.push_back("recording=" + settings.recording->path);
}

}  // namespace gazelod::cli
