// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/scenario.hpp"

#include "auxiliary/json_strict.hpp"

#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"
#include "bake/baked_scene.hpp"
#include "bake/bake_error.hpp"
#include "gaze/replay_source.hpp"
#include "gaze/trace_error.hpp"
#include "gaze/trace_open.hpp"
#include "lod/display.hpp"
#include "sim/effects/effects.hpp"
#include "auxiliary/json_text.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

std::string read_file(const std::string& path) {
  try {
    return sim::read_scenario_text(path);
  } catch (const sim::ScenarioError& e) {
    throw UsageError(std::string("--scenario: ") + e.what());
  }
}

void set_env(const char* name, const std::string& value) {
  if (::setenv(name, value.c_str(), 1) != 0) throw UsageError(std::string("cannot set ") + name);
}

// --scene: the baked glTF's objects and LOD chains replace the scenario's scene objects, in the
// scenario text itself, so the simulated runtime and this process step the same scenario.
// The scenario's text for a patch (--hmd, --scene), parsed as strictly as the scenario loader
// reads it (nesting depth, repeated keys): the patched text is what it reads, and dump()
// recurses as deep as the text nests.
nlohmann::json parse_scenario_text(const std::string& text, const std::string& label) {
  try {
    return aux::parse_json_text(text, label);
  } catch (const aux::JsonTextError& e) {
    throw UsageError(e.what());
  }
}

// Placement "in-front" moves the scene in front of the viewer's start (its bounding sphere's
// centre 2 radii + 1 m down -Z, at eye height); "file" keeps the glTF's coordinates (glTF +Y up
// and OpenXR LOCAL +Y up agree; the glTF origin is LOCAL's). `shift` gets the translation.
// Effects that name objects the baked scene lacks (a pursuit, object motion) are dropped with
// a note.
std::string with_baked_scene(const std::string& text, const std::string& label, const bake::BakedScene& scene_file,
                             const std::string& placement, glm::dvec3& shift_out) {
  const std::vector<bake::BakedObject>& baked = scene_file.objects;
  nlohmann::json j = parse_scenario_text(text, label);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const auto& b : baked) {
    lo = glm::min(lo, b.center_m - glm::dvec3(b.radius_m));
    hi = glm::max(hi, b.center_m + glm::dvec3(b.radius_m));
  }
  const glm::dvec3 mid = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  glm::dvec3 start(0.0);
  if (j.contains("scene") && j["scene"].contains("head_path") && j["scene"]["head_path"].contains("start_m")) {
    const auto& s = j["scene"]["head_path"]["start_m"];
    // A malformed start is the scenario loader's to report (with its JSON path); here it counts as 0.
    if (s.is_array() && s.size() == 3 && s[0].is_number() && s[1].is_number() && s[2].is_number())
      start = {s[0].get<double>(), s[1].get<double>(), s[2].get<double>()};
  }
  const glm::dvec3 shift =
      placement == "file" ? glm::dvec3(0.0) : start + glm::dvec3(0.0, 0.0, -(2.0 * radius + 1.0)) - mid;
  shift_out = shift;
  nlohmann::json objects = nlohmann::json::array();
  std::set<std::string> names;
  for (std::size_t i = 0; i < baked.size(); ++i) {
    const auto& b = baked[i];
    std::string name = b.name;
    if (!names.insert(name).second) names.insert(name += "#" + std::to_string(i));
    nlohmann::json lods = nlohmann::json::array();
    for (const auto& l : b.lods)
      lods.push_back(
          {{"triangles", l.triangles},
           {"vertices", l.vertices},
           {"detail_kind",
            l.detail_kind == lod::DetailKind::geometric_error_m ? "geometric_error_m" : "removed_cycles_per_diameter"},
           {"detail", l.detail}});
    const glm::dvec3 c = b.center_m + shift;
    objects.push_back({{"name", name}, {"position_m", {c.x, c.y, c.z}}, {"radius_m", b.radius_m}, {"lods", lods}});
  }
  nlohmann::json scene = j.value("scene", nlohmann::json::object());
  scene.erase("generators");
  scene["objects"] = objects;
  j["scene"] = scene;
  if (j.contains("effects") && j["effects"].is_array()) {
    nlohmann::json kept = nlohmann::json::array();
    for (const auto& e : j["effects"]) {
      const bool names_object =
          e.is_object() && e.contains("object") && e["object"].is_string() && e["object"].get<std::string>() != "*";
      if (names_object && !names.count(e["object"].get<std::string>())) {
        std::fprintf(stderr, "gazelod run: --scene: effect %s on object '%s' dropped (not in the baked scene)\n",
                     e.value("type", std::string("?")).c_str(), e["object"].get<std::string>().c_str());
        continue;
      }
      kept.push_back(e);
    }
    j["effects"] = kept;
  }
  return aux::json_text(j, 2);
}

// --trace with head poses: the scenario's head effects give way to a head_track of the same
// file, relative to its first pose, its first row at scenario time 0; run_session starts the
// gaze replay there too (TraceFromFirstFrame::start_at), so the two stay together however late
// the first frame comes (a paced runtime). Returns the text unchanged when the trace has no head.
std::string with_trace_head(const std::string& text, const std::string& trace_path, std::vector<std::string>& notes) {
  bool head = false;
  try {
    auto stream = gaze::open_trace(trace_path, gaze::TraceFormat::automatic);
    gaze::TraceRecord r;
    // Read whole: a bad row past the first pose was reported later by the scenario loader, as
    // an effect the user never wrote ("default + --trace head: effects[7].file: ...").
    if (stream->has_head())
      while (stream->next(r)) head = head || (r.has_head && r.head.valid);
  } catch (const gaze::TraceError& e) {
    throw UsageError(std::string("--trace: ") + e.what());
  }
  if (!head) return text;
  nlohmann::json j = aux::parse_json_strict(text);  // loaded once already: valid, strict JSON
  nlohmann::json kept = nlohmann::json::array();
  std::string dropped;
  for (const auto& e : j.value("effects", nlohmann::json::array())) {
    const std::string type = e.is_object() ? e.value("type", std::string()) : std::string();
    if (type == "head_sweep" || type == "head_turn" || type == "head_track") {
      dropped += (dropped.empty() ? "" : ", ") + type;
      continue;
    }
    kept.push_back(e);
  }
  kept.push_back({{"type", "head_track"},
                  {"file", std::filesystem::absolute(trace_path).string()},
                  {"format", "auto"},
                  {"relative", true}});
  j["effects"] = kept;
  notes.push_back("--trace: the head moves as recorded in " + trace_path + ", from its first pose" +
                  (dropped.empty() ? "" : ", in place of " + dropped) +
                  " (--trace-head scenario keeps the scenario's head)");
  return aux::json_text(j, 2);
}

// The effects' relative trace files (head_track, gaze_track) as absolute paths, found where
// the simulator finds them: beside the scenario file first. The runtime reads the copy in
// --out, beside which they are not, and the copy then runs the same from anywhere. Unparsable
// text is returned as it is, for the loader to report.
std::string with_trace_files_resolved(const std::string& text, const std::string& scenario_path) {
  nlohmann::json j;
  try {
    j = aux::parse_json_strict(text);
  } catch (const aux::JsonStrictError&) {
    return text;
  } catch (const nlohmann::json::exception&) {
    return text;
  }
  if (!j.is_object() || !j.contains("effects") || !j["effects"].is_array()) return text;
  bool changed = false;
  for (nlohmann::json& e : j["effects"]) {
    if (!e.is_object()) continue;
    const auto it = e.find("file");
    if (it == e.end() || !it->is_string()) continue;
    const std::string file = it->get<std::string>();
    if (file.empty() || std::filesystem::path(file).is_absolute()) continue;
    std::error_code ec;
    const std::filesystem::path found =
        std::filesystem::absolute(sim::effects::trace_file_path(file, scenario_path), ec);
    if (ec) continue;
    *it = found.string();
    changed = true;
  }
  return changed ? aux::json_text(j, 2) : text;
}

}  // namespace

// No file the run reads or writes elsewhere may be one of the report's files in --out: the run
// would replace its own input (a scenario named scenario.json, a trace named frames.csv), or
// one output another. Checked before anything is written.
void check_run_paths(const RunOptions& opt) {
  const auto same_file = [](const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code e1, e2;
    return std::filesystem::weakly_canonical(a, e1) == std::filesystem::weakly_canonical(b, e2) && !e1 && !e2;
  };
  const std::pair<std::string, const char*> inputs[] = {
      {opt.scenario_path, "--scenario"}, {opt.trace_path, "--trace"}, {opt.scene_path, "--scene"}};
  for (const auto& [path, option] : inputs) {
    if (path.empty()) continue;
    for (const char* report : kRunReportFiles)
      if (same_file(path, opt.out_dir / report))
        throw UsageError(std::string(option) + ": '" + path + "' is where the run writes its " + report +
                         " (in --out); choose another --out, or copy the file elsewhere first");
  }
  for (const auto& [path, option] :
       {std::pair{opt.decisions_path, "--decisions"}, std::pair{opt.cluster_decisions_path, "--cluster-decisions"}}) {
    if (path.empty()) continue;
    for (const char* report : kRunReportFiles)
      if (same_file(path, opt.out_dir / report))
        throw UsageError(std::string(option) + ": '" + path + "' is the run's " + report +
                         " (in --out); write the decisions to another file");
    for (const auto& [in, in_option] : inputs)
      if (!in.empty() && same_file(path, in))
        throw UsageError(std::string(option) + ": '" + path + "' is the run's " + in_option + " input");
  }
  if (!opt.decisions_path.empty() && same_file(opt.decisions_path, opt.cluster_decisions_path))
    throw UsageError("--cluster-decisions: the same file as --decisions");
}

PreparedScenario prepare_scenario(const RunOptions& opt) {
  check_run_paths(opt);
  PreparedScenario p;
  p.label = opt.scenario_path.empty() ? "default" : opt.scenario_path;
  std::string text = opt.scenario_path.empty()
                         ? std::string(sim::default_scenario_json())
                         : with_trace_files_resolved(read_file(opt.scenario_path), opt.scenario_path);
  // --hmd replaces the scenario's display, so the runtime reports the same views the plugin
  // is told about. Patched in the JSON text so the runtime reads exactly this scenario.
  if (!opt.hmd.empty()) {
    if (lod::find_display_preset(opt.hmd) == nullptr)
      throw UsageError("--hmd: unknown HMD '" + opt.hmd + "' (see gazelod hmds)");
    nlohmann::json j = parse_scenario_text(text, p.label);
    if (!j.is_object()) throw UsageError(p.label + ": the scenario must be a JSON object");
    j["display"] = opt.hmd;
    // The headset's own eye tracking: a preset without a tracker offers no eye gaze, whatever
    // the scenario's runtime said of the display it replaces (the default scenario's says yes).
    if (lod::find_display_preset(opt.hmd)->eye_tracking_hz <= 0.0 &&
        (!j.contains("runtime") || j["runtime"].is_object())) {
      j["runtime"]["eye_gaze_supported"] = false;
      p.notes.push_back("--hmd " + opt.hmd +
                        ": no eye tracker, so no eye gaze (the plugin falls back to head-fixed gaze)");
    }
    text = aux::json_text(j, 2);
  }
  if (!opt.scene_path.empty()) {
    if (opt.scene_placement != "in-front" && opt.scene_placement != "file")
      throw UsageError("--scene-placement: '" + opt.scene_placement + "' (use in-front or file)");
    try {
      // Drawn with its levels' own triangles (RunRenderer), which only a rendered run needs.
      p.baked =
          bake::load_baked(opt.scene_path, opt.render ? bake::BakedLoad::with_level_geometry : bake::BakedLoad::chains);
    } catch (const bake::BakeError& e) {
      throw UsageError(std::string("--scene: ") + e.what());
    }
    if (p.baked->objects.empty()) throw UsageError("--scene: '" + opt.scene_path + "' has no meshes");
    text = with_baked_scene(text, p.label, *p.baked, opt.scene_placement, p.scene_shift_m);
    p.label += " + " + opt.scene_path;
  }
  try {
    p.scenario = sim::load_scenario_json(text, p.label);
  } catch (const sim::ScenarioError& e) {
    throw UsageError(e.what());
  }
  if (!opt.trace_path.empty() && opt.trace_head && opt.runtime == "sim") {
    const std::string with_head = with_trace_head(text, opt.trace_path, p.notes);
    if (with_head != text) {
      text = with_head;
      p.trace_head = true;
      try {
        p.scenario = sim::load_scenario_json(text, p.label + " + --trace head");
      } catch (const sim::ScenarioError& e) {
        throw UsageError(e.what());
      }
    }
  }
  if (opt.frames > 0) {
    const double rate = p.scenario.frame_rate_hz > 0 ? p.scenario.frame_rate_hz : 90.0;
    p.scenario.duration_s = static_cast<double>(opt.frames) / rate;
  }
  p.duration_s = p.scenario.duration_s;
  p.file = opt.out_dir / "scenario.json";
  p.text = std::move(text);
  return p;
}

void write_scenario_file(const PreparedScenario& p) {
  try {
    write_run_file(p.file.string(), p.text + "\n");
  } catch (const aux::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what(), 1);  // a failure to write, not bad usage
  }
}

// The simulated runtime's manifest: beside an installed program (cmake --install puts it in
// <prefix>/share/openxr/1/), else the one of the build tree the program was built in.
std::string simulator_manifest() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed =
        exe.parent_path().parent_path() / "share" / "openxr" / "1" / "gazelod_xr_runtime.json";
    if (std::filesystem::is_regular_file(installed, ec)) return installed.string();
  }
#ifdef GAZELOD_XR_RUNTIME_JSON
  return GAZELOD_XR_RUNTIME_JSON;
#else
  throw UsageError("--runtime sim: this build has no simulated runtime; set XR_RUNTIME_JSON");
#endif
}

void point_loader_at_simulator(const PreparedScenario& prepared, const RunOptions& opt) {
  if (const char* given = std::getenv("XR_RUNTIME_JSON"); given == nullptr || *given == '\0')
    set_env("XR_RUNTIME_JSON", simulator_manifest());
  set_env("GAZELOD_SIM_SCENARIO", std::filesystem::absolute(prepared.file).string());
  // A second of slack: the run asks the session to end after its frames, the runtime must
  // not end it first.
  std::ostringstream d;
  d.precision(17);
  d << prepared.duration_s + sim::kRunSlackS;
  set_env("GAZELOD_SIM_DURATION_S", d.str());
  set_env("GAZELOD_SIM_PACED", opt.paced ? "1" : "0");
}

TraceFromFirstFrame::TraceFromFirstFrame(std::vector<gaze::TraceRecord> records)
    : start_ns_(records.empty() ? 0 : records.front().gaze.t_ns),
      duration_ns_(records.empty() ? 0 : records.back().gaze.t_ns - records.front().gaze.t_ns),
      replay_(std::move(records)) {}

void TraceFromFirstFrame::start_at(std::int64_t t_ns) {
  offset_ns_ = t_ns - start_ns_;
  started_ = true;
}

std::optional<gaze::GazeSample> TraceFromFirstFrame::sample_at(std::int64_t t_ns) {
  if (!started_) start_at(t_ns);
  auto s = replay_.sample_at(t_ns - offset_ns_);
  if (s) s->t_ns += offset_ns_;
  return s;
}

std::shared_ptr<TraceFromFirstFrame> make_external_source(const RunOptions& opt) {
  if (opt.trace_path.empty()) return nullptr;
  try {
    auto stream = gaze::open_trace(opt.trace_path, gaze::TraceFormat::automatic);
    auto records = gaze::ReplaySource::load(*stream);
    if (records.empty()) throw UsageError("--trace: '" + opt.trace_path + "' has no samples");
    // A recording without two valid samples has no gaze to replay: the run went on with the
    // gaze "valid in 0.0% of frames" and no word (eval family --recording refuses it too).
    const auto valid =
        std::count_if(records.begin(), records.end(), [](const gaze::TraceRecord& r) { return r.gaze.valid; });
    if (valid < 2)
      throw UsageError("--trace: '" + opt.trace_path + "' has " + std::to_string(valid) + " valid gaze sample" +
                       (valid == 1 ? "" : "s") + " of " + std::to_string(records.size()) +
                       "; a replay needs at least two");
    return std::make_shared<TraceFromFirstFrame>(std::move(records));
  } catch (const gaze::TraceError& e) {
    throw UsageError(std::string("--trace: ") + e.what());
  }
}

}  // namespace gazelod::cli
