// SPDX-License-Identifier: Apache-2.0
#include "layer/layer_config.hpp"

#include "auxiliary/json_path.hpp"
#include "auxiliary/json_strict.hpp"
#include "auxiliary/time.hpp"
#include "auxiliary/yaw_pitch.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace gazelod::layer {
namespace {

using nlohmann::json;

// A config error: "<file>: <json path>: <what>".
struct Bad {
  std::string line;
};

[[noreturn]] void bad(const std::string& file, const std::string& path, const std::string& what) {
  throw Bad{aux::json_error_line(file, path, what)};
}

std::string shown(const json& v) {
  std::string s = aux::json_text(v);
  return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

double number_in(const std::string& file, const std::string& path, const json& v, double lo, double hi, bool lo_open) {
  if (!v.is_number()) bad(file, path, "must be a number, got " + shown(v));
  const double x = v.get<double>();
  const bool above = lo_open ? x > lo : x >= lo;
  if (!std::isfinite(x) || !above || x > hi) {
    std::ostringstream m;
    m << "must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << "], got " << shown(v);
    bad(file, path, m.str());
  }
  return x;
}

std::vector<double> numbers(const std::string& file, const std::string& path, const json& v, std::size_t n, double lo,
                            double hi, bool lo_open) {
  if (!v.is_array() || v.size() != n)
    bad(file, path, "must be an array of " + std::to_string(n) + " numbers, got " + shown(v));
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(number_in(file, aux::json_element_path(path, i), v[i], lo, hi, lo_open));
  return out;
}

void only_keys(const std::string& file, const std::string& path, const json& obj,
               std::initializer_list<std::string_view> known) {
  if (const std::string* key = aux::first_unknown_key(obj, known))
    bad(file, aux::json_member_path(path, *key), "unknown key (known: " + aux::joined_keys(known) + ")");
}

// The file's rotation_deg: yaw positive to the right, pitch positive up (as gaze_yaw_deg /
// gaze_pitch_deg in traces, converted by the one function for that), roll positive clockwise
// as the wearer sees it; applied in that order.
glm::dquat orientation_from_deg(double yaw_right_deg, double pitch_up_deg, double roll_cw_deg) {
  const glm::dquat yaw_pitch = aux::rotation_from(aux::yaw_pitch_from_yaw_right_deg(yaw_right_deg, pitch_up_deg));
  const glm::dquat roll = glm::angleAxis(-roll_cw_deg * aux::kRadPerDeg, glm::dvec3(0.0, 0.0, -1.0));
  return glm::normalize(yaw_pitch * roll);
}

void apply(const json& j, const std::string& file, LayerConfig& c) {
  if (!j.is_object()) bad(file, std::string(aux::kJsonTopLevel), "must be a JSON object, got " + shown(j));
  only_keys(file, "", j, {"override", "freshness_ms", "trace_format", "head_offset", "hid"});
  if (j.contains("override")) {
    if (!j["override"].is_boolean()) bad(file, "override", "must be true or false, got " + shown(j["override"]));
    c.override_runtime = j["override"].get<bool>();
  }
  if (j.contains("freshness_ms"))
    c.freshness_ns = aux::ns_from_ms(number_in(file, "freshness_ms", j["freshness_ms"], 0.0, 10000.0, true));
  if (j.contains("trace_format")) {
    const json& f = j["trace_format"];
    const auto parsed = f.is_string() ? gaze::parse_trace_format(f.get<std::string>()) : std::nullopt;
    if (!parsed)
      bad(file, "trace_format",
          "must be \"auto\", \"gazelod\", \"gazebasevr\", \"pupil\", \"pupil_cloud\" or \"sranipal\", got " + shown(f));
    c.trace_format = *parsed;
  }
  if (j.contains("head_offset")) {
    const json& h = j["head_offset"];
    if (!h.is_object()) bad(file, "head_offset", "must be an object, got " + shown(h));
    only_keys(file, "head_offset", h, {"position_m", "rotation_deg"});
    if (h.contains("position_m")) {
      const auto p = numbers(file, "head_offset.position_m", h["position_m"], 3, -1.0, 1.0, false);
      c.tracker_position_m = {p[0], p[1], p[2]};
    }
    if (h.contains("rotation_deg")) {
      const auto r = numbers(file, "head_offset.rotation_deg", h["rotation_deg"], 3, -180.0, 180.0, false);
      c.tracker_orientation = orientation_from_deg(r[0], r[1], r[2]);
    }
  }
  if (j.contains("hid")) {
    const json& h = j["hid"];
    if (!h.is_object()) bad(file, "hid", "must be an object, got " + shown(h));
    only_keys(file, "hid", h, {"path", "layout", "screen_mm"});
    if (h.contains("path")) {
      if (!h["path"].is_string()) bad(file, "hid.path", "must be a string, got " + shown(h["path"]));
      c.hid_path = h["path"].get<std::string>();
    }
    if (h.contains("layout")) {
      const json& l = h["layout"];
      if (!l.is_string() || (l.get<std::string>() != "packed" && l.get<std::string>() != "dmf"))
        bad(file, "hid.layout", "must be \"packed\" or \"dmf\", got " + shown(l));
      c.hid_layout = l.get<std::string>();
    }
    if (h.contains("screen_mm")) {
      const auto s = numbers(file, "hid.screen_mm", h["screen_mm"], 2, 0.0, 10000.0, true);
      c.hid_screen_width_m = s[0] * 1e-3;
      c.hid_screen_height_m = s[1] * 1e-3;
    }
  }
}

// The file's text, bounded; throws Bad with the system's reason.
std::string read_config_file(const std::string& path) {
  const std::string where = std::string(kConfigEnv) + "=" + path;
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(st))
    throw Bad{where + ": cannot open: " + (ec ? ec.message() : std::string(std::strerror(ENOENT)))};
  if (!std::filesystem::is_regular_file(st)) throw Bad{where + ": not a regular file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Bad{where + ": cannot open: " + std::strerror(errno)};
  std::string text;
  char buf[4096];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxConfigBytes) throw Bad{where + ": larger than " + std::to_string(kMaxConfigBytes) + " bytes"};
  }
  if (in.bad()) throw Bad{where + ": read failed: " + std::strerror(errno)};
  return text;
}

}  // namespace

ConfigResult parse_config_json(const std::string& text, const std::string& file, LayerConfig base) {
  ConfigResult r{std::move(base), ""};
  try {
    json j;
    try {
      j = aux::parse_json_text(text, file);
    } catch (const aux::JsonTextError& e) {
      throw Bad{e.what()};
    }
    apply(j, file, r.config);
  } catch (const Bad& b) {
    r.error = b.line;
  } catch (const json::exception& e) {
    r.error = file + ": " + e.what();
  }
  return r;
}

ConfigResult load_config(const char* trace_env, const char* config_env) {
  LayerConfig c;
  if (trace_env != nullptr) c.trace_path = trace_env;
  if (config_env == nullptr || *config_env == '\0') return {c, ""};
  c.config_path = config_env;
  std::string text;
  try {
    text = read_config_file(c.config_path);
  } catch (const Bad& b) {
    return {c, b.line};
  }
  return parse_config_json(text, c.config_path, c);
}

ConfigResult load_config_from_env() {
  return load_config(std::getenv(kTraceEnv), std::getenv(kConfigEnv));
}

}  // namespace gazelod::layer
