// SPDX-License-Identifier: Apache-2.0
// Loading a scenario (format: version 1; see sim/scenarios/*.json and the README section
// "Scenario files"). Every error names the source and the JSON path.
#include "auxiliary/angles.hpp"
#include "auxiliary/json_path.hpp"
#include "auxiliary/json_strict.hpp"
#include "auxiliary/time.hpp"
#include "sim/effect.hpp"
#include "sim/effects/effects.hpp"
#include "sim/json_fields.hpp"
#include "sim/scene_json.hpp"
#include "sim/simulator.hpp"

#include "lod/display.hpp"
#include "auxiliary/json_text.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::sim {
namespace {

std::string preset_names() {
  std::string s;
  for (const lod::DisplaySpec& d : lod::display_presets()) s += (s.empty() ? "" : ", ") + d.name;
  return s;
}

// gazelod's plugin (and so `gazelod run`) uses the stereo view configuration only; the simulated
// runtime offers a one-view display as PRIMARY_MONO, which the plugin cannot use.
const char* const kTwoViews =
    "gazelod's plugin uses the stereo view configuration; the simulated runtime offers a one-view display as "
    "PRIMARY_MONO only";

const lod::DisplaySpec& preset_or_fail(const std::string& name, JsonFields& f, const std::string& key) {
  const lod::DisplaySpec* d = lod::find_display_preset(name);
  if (!d) f.fail(key, "unknown display preset \"" + name + "\" (known: " + preset_names() + ")");
  return *d;
}

// A preset used as it is must have two views.
const lod::DisplaySpec& stereo_preset_or_fail(const std::string& name, JsonFields& f, const std::string& key) {
  const lod::DisplaySpec& d = preset_or_fail(name, f, key);
  if (d.view_count != 2)
    f.fail(key, "the preset \"" + name + "\" has " + std::to_string(d.view_count) +
                    " view; a scenario's display must have 2 (" + kTwoViews + ")");
  return d;
}

lod::FovRad read_fov(JsonFields& f, const std::string& key, double scale) {
  JsonFields a(*f.child(key), f.key_path(key), f.source());
  const double lim = 90.0 / (scale == 1.0 ? aux::kDegPerRad : 1.0);  // 90 deg in the key's unit
  lod::FovRad fov;
  fov.angle_left_rad = a.required_number("left", -lim, lim) * scale;
  fov.angle_right_rad = a.required_number("right", -lim, lim) * scale;
  fov.angle_up_rad = a.required_number("up", -lim, lim) * scale;
  fov.angle_down_rad = a.required_number("down", -lim, lim) * scale;
  a.finish();
  return fov;
}

lod::DisplaySpec read_display(const nlohmann::json& j, JsonFields& top) {
  if (j.is_string()) return stereo_preset_or_fail(j.get<std::string>(), top, "display");
  JsonFields f(j, top.key_path("display"), top.source());
  lod::DisplaySpec d;
  const bool preset = f.has("preset");
  if (preset)
    d = preset_or_fail(f.string("preset", ""), f, "preset");
  else
    d.name = "custom", d.label = "custom display", d.source = "scenario";
  d.name = f.string("name", d.name);
  d.label = f.string("label", d.label);
  d.view_count = static_cast<int>(f.integer("views", d.view_count, 1, 2));
  if (d.view_count != 2)
    f.fail(f.has("views") ? "views" : "preset",
           "must be 2 (" + std::string(kTwoViews) + "), got " + std::to_string(d.view_count));
  lod::ViewSpec v = d.views[0];
  if (!preset && !f.has("width_px")) f.fail("width_px", "missing (or give a \"preset\")");
  if (!preset && !f.has("height_px")) f.fail("height_px", "missing (or give a \"preset\")");
  v.width_px = static_cast<int>(f.integer("width_px", v.width_px, 1, 65536));
  v.height_px = static_cast<int>(f.integer("height_px", v.height_px, 1, 65536));
  const int fov_keys = f.has("fov_deg") + f.has("fov_rad") + (f.has("fov_h_deg") || f.has("fov_v_deg"));
  const std::string fov_key = f.has("fov_deg")     ? "fov_deg"
                              : f.has("fov_rad")   ? "fov_rad"
                              : f.has("fov_h_deg") ? "fov_h_deg"
                              : f.has("fov_v_deg") ? "fov_v_deg"
                                                   : "";
  if (fov_keys > 1) f.fail("", "give one of fov_deg, fov_rad or fov_h_deg + fov_v_deg");
  if (f.has("fov_deg"))
    v.fov = read_fov(f, "fov_deg", aux::kRadPerDeg);
  else if (f.has("fov_rad"))
    v.fov = read_fov(f, "fov_rad", 1.0);
  else if (f.has("fov_h_deg") || f.has("fov_v_deg"))
    v.fov = lod::symmetric_fov(f.required_number("fov_h_deg", lod::kMinFovDeg, lod::kMaxFovDeg),
                               f.required_number("fov_v_deg", lod::kMinFovDeg, lod::kMaxFovDeg));
  else if (!preset)
    f.fail("fov_deg", "missing (fov_deg {left, right, up, down}, fov_rad, or fov_h_deg + fov_v_deg)");
  d.views[0] = d.views[1] = v;
  d.refresh_hz = f.number("refresh_hz", d.refresh_hz, 1.0, 1000.0);
  d.eye_tracking_hz = f.number("eye_tracking_hz", d.eye_tracking_hz, 0.0, 10000.0);
  d.eye_tracking_accuracy_deg = f.number("eye_tracking_accuracy_deg", d.eye_tracking_accuracy_deg, 0.0, 89.0);
  d.center_ppd = f.number("center_ppd", d.center_ppd, 0.0, 1000.0);
  d.source = f.string("source", d.source);
  f.finish();
  const std::string problem = lod::validate_display(d);
  if (!problem.empty()) f.fail("", problem);
  // The limits every described field of view has (also `gazelod thresholds --fov`).
  if (std::string e = lod::validate_described_view(d.views[0]); !e.empty()) f.fail(fov_key, e);
  return d;
}

RuntimeOptions read_runtime(const nlohmann::json& j, JsonFields& top, RuntimeOptions r) {
  JsonFields f(j, top.key_path("runtime"), top.source());
  r.eye_gaze_supported = f.boolean("eye_gaze_supported", r.eye_gaze_supported);
  const std::string g = f.string("gaze_delivery", "normal");
  if (g == "normal")
    r.gaze_delivery = GazeDelivery::normal;
  else if (g == "never_delivers")
    r.gaze_delivery = GazeDelivery::never_delivers;
  else if (g == "sample_time_zero")
    r.gaze_delivery = GazeDelivery::sample_time_zero;
  else if (g == "sample_time_is_request_time")
    r.gaze_delivery = GazeDelivery::sample_time_is_request_time;
  else
    f.fail("gaze_delivery",
           "unknown \"" + g + "\" (known: normal, never_delivers, sample_time_zero, sample_time_is_request_time)");
  r.paced = f.boolean("paced", r.paced);
  f.finish();
  return r;
}

// Estimated memory of a replay effect (head_track, gaze_track): 4 bytes per byte of its trace,
// whatever its format (a row of a few dozen characters becomes a 64-byte pose or sample), for
// the file the effect will open (effects::trace_file_path); 0 when that is not a readable
// regular file (the effect reports that itself).
std::size_t track_bytes(const nlohmann::json& e, const std::string& source) {
  const auto file = e.find("file");
  if (file == e.end() || !file->is_string()) return 0;
  const std::string path = effects::trace_file_path(file->get<std::string>(), source);
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return 0;
  const auto size = static_cast<std::size_t>(st.st_size);
  return size > kMaxScenarioMemoryBytes ? kMaxScenarioMemoryBytes + 1 : 4 * size;
}

}  // namespace

Scenario load_scenario_json(std::string_view json_text, std::string_view source_name) {
  const std::string source(source_name);
  if (json_text.size() > kMaxScenarioBytes)
    throw_at(source, "",
             "must be at most " + bytes_text(kMaxScenarioBytes) + " of JSON, got " + bytes_text(json_text.size()));
  // Nesting is limited while parsing (a deeply nested value would cost stack in every later
  // pass over it without ever being a valid scenario), and a key given twice is refused.
  nlohmann::json j;
  try {
    j = aux::parse_json_text(json_text, source, kMaxJsonDepth);
  } catch (const aux::JsonTextError& e) {
    throw ScenarioError(e.what());
  }
  JsonFields f(j, "", source);
  Scenario sc;
  if (!f.has("version")) f.fail("version", "missing (this reader reads version 1)");
  sc.version = static_cast<int>(f.integer("version", 1, 0, 1'000'000));
  if (sc.version != 1)
    f.fail("version", "unsupported version " + std::to_string(sc.version) + " (this reader reads 1)");
  sc.name = f.string("name", source);
  const nlohmann::json* display = f.child("display");
  if (!display) f.fail("display", "missing (a preset name such as \"questpro\", or an object)");
  sc.display = read_display(*display, f);
  sc.duration_s = f.number("duration_s", sc.duration_s, 1e-3, kMaxScenarioDurationS);
  // The frame rate is the display's refresh rate (the runtime paces at display.refresh_hz).
  sc.frame_rate_hz = f.number("frame_rate_hz", sc.display.refresh_hz, 1.0, 1000.0);
  sc.display.refresh_hz = sc.frame_rate_hz;
  // `gazelod run` plays round(duration x rate) frames: less than one frame would be none.
  if (sc.duration_s * sc.frame_rate_hz < 1.0)
    f.fail("duration_s", "must be at least one frame (1 / " + format_number(sc.frame_rate_hz) + " Hz = " +
                             format_number(1.0 / sc.frame_rate_hz) + " s), got " + format_number(sc.duration_s));
  sc.seed = f.unsigned_integer("seed", sc.seed);
  ScenarioTally tally;
  if (const nlohmann::json* scene = f.child("scene")) read_scene(*scene, f.key_path("scene"), source, sc, tally);
  // A preset without an eye tracker (Quest 3, Index) offers no eye gaze unless the scenario
  // says otherwise: the simulated runtime gave every display a perfect tracker, and `compare`
  // reported gaze-contingent savings for headsets that cannot track the eye.
  const bool from_preset = display->is_string() || (display->is_object() && display->contains("preset"));
  sc.runtime.eye_gaze_supported = !from_preset || sc.display.eye_tracking_hz > 0.0;
  if (const nlohmann::json* rt = f.child("runtime")) sc.runtime = read_runtime(*rt, f, sc.runtime);
  if (const nlohmann::json* effects = f.child("effects")) {
    if (!effects->is_array()) f.fail("effects", "expected an array, got " + aux::json_type_name(*effects));
    if (effects->size() > kMaxEffects)
      f.fail("effects",
             "must have at most " + std::to_string(kMaxEffects) + " effects, got " + std::to_string(effects->size()));
    for (std::size_t i = 0; i < effects->size(); ++i) {
      const nlohmann::json& e = (*effects)[i];
      EffectSpec spec;
      spec.json_path = aux::json_element_path("effects", i);
      JsonFields ef(e, spec.json_path, source);
      spec.type = ef.required_string("type");
      if (spec.type == "head_track" || spec.type == "gaze_track") {  // loaded whole: counted before
        const std::size_t bytes = track_bytes(e, source);
        if (bytes > kMaxScenarioMemoryBytes - tally.memory_bytes)
          ef.fail("file", "must take at most " + bytes_text(kMaxScenarioMemoryBytes - tally.memory_bytes) +
                              " (a scenario's estimated memory is at most " + bytes_text(kMaxScenarioMemoryBytes) +
                              ", " + bytes_text(tally.memory_bytes) + " before; a trace takes 4 bytes per byte), got " +
                              bytes_text(bytes));
        tally.memory_bytes += bytes;
      }
      spec.params_json = aux::json_text(e);
      sc.effects.push_back(std::move(spec));
    }
  }
  f.finish();
  // The gaze effects compose in list order (sim/scenarios/README.md): `vor` turns the saccades
  // before it into those of an eye holding the world, and a `smooth_pursuit` after it wins
  // while active. The other order ran without a word: saccades after the reflex overwrote it,
  // a reflex after the pursuit held the pursuing eye against the head's rotation.
  std::size_t vor_at = sc.effects.size(), pursuit_at = sc.effects.size();
  for (std::size_t i = 0; i < sc.effects.size(); ++i) {
    const std::string& type = sc.effects[i].type;
    if (type == "saccades" && vor_at < i)
      throw_at(source, sc.effects[i].json_path,
               "saccades must come before vor (" + sc.effects[vor_at].json_path +
                   "), which turns them into saccades of an eye holding the world; list vor after it");
    if (type == "vor" && pursuit_at < i)
      throw_at(source, sc.effects[i].json_path,
               "vor must come before smooth_pursuit (" + sc.effects[pursuit_at].json_path +
                   "), which wins while it is active; list smooth_pursuit after it");
    if (type == "vor" && vor_at == sc.effects.size()) vor_at = i;
    if (type == "smooth_pursuit" && pursuit_at == sc.effects.size()) pursuit_at = i;
  }
  // Build every effect once so that bad parameters are reported now, with their path; and
  // add up what effects combine: the tracker latency (each <= 1000 ms, and so all together).
  TrackerTiming timing;
  for (std::size_t i = 0; i < sc.effects.size(); ++i) {
    const std::unique_ptr<Effect> effect = make_effect(sc.effects[i], sc, i, source);
    if (!(effect->stages() & kStageTrackerTiming)) continue;
    effect->apply_timing(timing);
    if (timing.latency_ns > aux::ns_from_ms(kMaxTrackerLatencyMs))
      throw_at(source, sc.effects[i].json_path,
               "the tracker latency of all effects together must be <= " + format_number(kMaxTrackerLatencyMs) +
                   " ms, got " + format_number(aux::ms_from_ns(timing.latency_ns)) + " ms with this one");
  }
  return sc;
}

std::string read_scenario_text(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw ScenarioError(path + ": cannot open the scenario file: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw ScenarioError(path + ": is a directory, not a scenario file");
  if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
    throw ScenarioError(path + ": is not a regular file (a device or socket), not a scenario file");
  if (S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) > kMaxScenarioBytes)
    throw_at(path, "",
             "must be at most " + bytes_text(kMaxScenarioBytes) + " of JSON, got " +
                 bytes_text(static_cast<std::size_t>(st.st_size)));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the scenario file: " + std::strerror(errno));
  // Bounded also for a pipe (or a file that grows): at most one chunk past the limit is read.
  std::string text;
  if (S_ISREG(st.st_mode)) text.reserve(static_cast<std::size_t>(st.st_size));
  char chunk[1 << 16];
  while (in && text.size() <= kMaxScenarioBytes) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw ScenarioError(path + ": cannot read the scenario file: " + std::strerror(errno));
  if (text.size() > kMaxScenarioBytes)
    throw_at(path, "", "must be at most " + bytes_text(kMaxScenarioBytes) + " of JSON, got more");
  return text;
}

Scenario load_scenario_file(const std::string& path) {
  Scenario sc = load_scenario_json(read_scenario_text(path), path);
  sc.file = path;
  return sc;
}

}  // namespace gazelod::sim
