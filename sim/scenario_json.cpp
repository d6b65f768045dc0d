// Loading a scenario (format: version 1; see sim/scenarios/*.json and the README section
// "Scenario files"). Every error names the source and the JSON path.
#include "sim/angles.hpp"
#include "sim/effect.hpp"
#include "sim/json_fields.hpp"
#include "sim/scene_json.hpp"
#include "sim/simulator.hpp"

#include <fstream>
#include <sstream>

namespace gazelod::sim {
namespace {

std::string preset_names() {
  std::string s;
  for (const lod::DisplaySpec& d : lod::display_presets()) s += (s.empty() ? "" : ", ") + d.name;
  return s;
}

const lod::DisplaySpec& preset_or_fail(const std::string& name, JsonFields& f, const std::string& key) {
  const lod::DisplaySpec* d = lod::find_display_preset(name);
  if (!d) f.fail(key, "unknown display preset \"" + name + "\" (known: " + preset_names() + ")");
  return *d;
}

lod::FovRad read_fov(JsonFields& f, const std::string& key, double scale) {
  JsonFields a(*f.child(key), f.key_path(key), f.source());
  const double lim = 90.0 / (scale == 1.0 ? kDegPerRad : 1.0);  // 90 deg in the key's unit
  lod::FovRad fov;
  fov.angle_left_rad = a.required_number("left", -lim, lim) * scale;
  fov.angle_right_rad = a.required_number("right", -lim, lim) * scale;
  fov.angle_up_rad = a.required_number("up", -lim, lim) * scale;
  fov.angle_down_rad = a.required_number("down", -lim, lim) * scale;
  a.finish();
  return fov;
}

lod::DisplaySpec read_display(const nlohmann::json& j, JsonFields& top) {
  if (j.is_string()) return preset_or_fail(j.get<std::string>(), top, "display");
  JsonFields f(j, top.key_path("display"), top.source());
  lod::DisplaySpec d;
  const bool preset = f.has("preset");
  if (preset) d = preset_or_fail(f.string("preset", ""), f, "preset");
  else d.name = "custom", d.label = "custom display", d.source = "scenario";
  d.name = f.string("name", d.name);
  d.label = f.string("label", d.label);
  d.view_count = static_cast<int>(f.integer("views", d.view_count, 1, 2));
  lod::ViewSpec v = d.views[0];
  if (!preset && !f.has("width_px")) f.fail("width_px", "missing (or give a \"preset\")");
  if (!preset && !f.has("height_px")) f.fail("height_px", "missing (or give a \"preset\")");
  v.width_px = static_cast<int>(f.integer("width_px", v.width_px, 1, 65536));
  v.height_px = static_cast<int>(f.integer("height_px", v.height_px, 1, 65536));
  const int fov_keys = f.has("fov_deg") + f.has("fov_rad") + (f.has("fov_h_deg") || f.has("fov_v_deg"));
  if (fov_keys > 1) f.fail("", "give one of fov_deg, fov_rad or fov_h_deg + fov_v_deg");
  if (f.has("fov_deg")) v.fov = read_fov(f, "fov_deg", kRadPerDeg);
  else if (f.has("fov_rad")) v.fov = read_fov(f, "fov_rad", 1.0);
  else if (f.has("fov_h_deg") || f.has("fov_v_deg"))
    v.fov = lod::symmetric_fov(f.required_number("fov_h_deg", 1e-3, 179.0), f.required_number("fov_v_deg", 1e-3, 179.0));
  else if (!preset) f.fail("fov_deg", "missing (fov_deg {left, right, up, down}, fov_rad, or fov_h_deg + fov_v_deg)");
  d.views[0] = d.views[1] = v;
  d.refresh_hz = f.number("refresh_hz", d.refresh_hz, 1.0, 1000.0);
  d.eye_tracking_hz = f.number("eye_tracking_hz", d.eye_tracking_hz, 0.0, 10000.0);
  d.eye_tracking_accuracy_deg = f.number("eye_tracking_accuracy_deg", d.eye_tracking_accuracy_deg, 0.0, 89.0);
  d.center_ppd = f.number("center_ppd", d.center_ppd, 0.0, 1000.0);
  d.source = f.string("source", d.source);
  f.finish();
  const std::string problem = lod::validate_display(d);
  if (!problem.empty()) f.fail("", problem);
  return d;
}

RuntimeOptions read_runtime(const nlohmann::json& j, JsonFields& top) {
  JsonFields f(j, top.key_path("runtime"), top.source());
  RuntimeOptions r;
  r.eye_gaze_supported = f.boolean("eye_gaze_supported", r.eye_gaze_supported);
  const std::string g = f.string("gaze_delivery", "normal");
  if (g == "normal") r.gaze_delivery = GazeDelivery::normal;
  else if (g == "never_delivers") r.gaze_delivery = GazeDelivery::never_delivers;
  else if (g == "sample_time_zero") r.gaze_delivery = GazeDelivery::sample_time_zero;
  else if (g == "sample_time_is_request_time") r.gaze_delivery = GazeDelivery::sample_time_is_request_time;
  else
    f.fail("gaze_delivery", "unknown \"" + g +
                                "\" (known: normal, never_delivers, sample_time_zero, sample_time_is_request_time)");
  r.paced = f.boolean("paced", r.paced);
  f.finish();
  return r;
}

// "file:line:column" of a byte offset, for JSON syntax errors.
std::string line_column(std::string_view text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, col = 1;
    else ++col;
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

}  // namespace

Scenario load_scenario_json(std::string_view json_text, std::string_view source_name) {
  const std::string source(source_name);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::parse_error& e) {
    throw ScenarioError(source + ":" + line_column(json_text, e.byte > 0 ? e.byte - 1 : 0) +
                        ": JSON syntax error: " + e.what());
  } catch (const nlohmann::json::exception& e) {  // e.g. out_of_range: a number too large
    throw ScenarioError(source + ": JSON error: " + e.what());
  }
  JsonFields f(j, "", source);
  Scenario sc;
  if (!f.has("version")) f.fail("version", "missing (this reader reads version 1)");
  sc.version = static_cast<int>(f.integer("version", 1, 0, 1'000'000));
  if (sc.version != 1) f.fail("version", "unsupported version " + std::to_string(sc.version) + " (this reader reads 1)");
  sc.name = f.string("name", source);
  const nlohmann::json* display = f.child("display");
  if (!display) f.fail("display", "missing (a preset name such as \"questpro\", or an object)");
  sc.display = read_display(*display, f);
  sc.duration_s = f.number("duration_s", sc.duration_s, 1e-3, 1e6);
  // The frame rate is the display's refresh rate (the runtime paces at display.refresh_hz).
  sc.frame_rate_hz = f.number("frame_rate_hz", sc.display.refresh_hz, 1.0, 1000.0);
  sc.display.refresh_hz = sc.frame_rate_hz;
  sc.seed = f.unsigned_integer("seed", sc.seed);
  if (const nlohmann::json* scene = f.child("scene")) read_scene(*scene, f.key_path("scene"), source, sc);
  if (const nlohmann::json* rt = f.child("runtime")) sc.runtime = read_runtime(*rt, f);
  if (const nlohmann::json* effects = f.child("effects")) {
    if (!effects->is_array()) f.fail("effects", "expected an array, got " + json_type_name(*effects));
    for (std::size_t i = 0; i < effects->size(); ++i) {
      const nlohmann::json& e = (*effects)[i];
      EffectSpec spec;
      spec.json_path = "effects[" + std::to_string(i) + "]";
      JsonFields ef(e, spec.json_path, source);
      spec.type = ef.required_string("type");
      spec.params_json = e.dump();
      sc.effects.push_back(std::move(spec));
    }
  }
  f.finish();
  // Build every effect once so that bad parameters are reported now, with their path.
  for (std::size_t i = 0; i < sc.effects.size(); ++i) (void)make_effect(sc.effects[i], sc, i, source);
  return sc;
}

Scenario load_scenario_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot open the scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ScenarioError(path + ": cannot read the scenario file");
  return load_scenario_json(text.str(), path);
}

}  // namespace gazelod::sim
