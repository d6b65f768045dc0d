// SPDX-License-Identifier: Apache-2.0
// What configures the eye-gaze layer (docs/layer.md): GAZELOD_LAYER_TRACE=FILE replays a trace,
// otherwise the first HID eye tracker is the source; GAZELOD_LAYER_CONFIG=FILE is an optional
// JSON object for the rest. A bad value is one line saying what and where (file, JSON path or
// byte offset); the caller logs it and the layer then serves no gaze.
#pragma once

#include "gaze/trace_open.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>

namespace gazelod::layer {

inline constexpr const char* kTraceEnv = "GAZELOD_LAYER_TRACE";
inline constexpr const char* kConfigEnv = "GAZELOD_LAYER_CONFIG";

// Defaults for how long the newest sample stays usable: a trace holds its last valid sample as
// gazelod's replay does (gaze/replay_source.hpp: 150 ms, a blink); a HID tracker as
// gaze/hid/hid_gaze_source.hpp does (100 ms).
inline constexpr std::int64_t kTraceFreshnessNs = 150'000'000;
inline constexpr std::int64_t kHidFreshnessNs = 100'000'000;
inline constexpr std::size_t kMaxConfigBytes = 1 << 20;

struct LayerConfig {
  std::string trace_path;                                         // GAZELOD_LAYER_TRACE; empty: the HID eye tracker
  gaze::TraceFormat trace_format = gaze::TraceFormat::automatic;  // "trace_format"
  std::string config_path;                                        // GAZELOD_LAYER_CONFIG, for messages ("" = none)
  bool override_runtime = false;  // "override": emulate even when the runtime has eye gaze
  // "head_offset": the tracker's frame in the head (VIEW) space; identity by default.
  glm::dvec3 tracker_position_m{0.0};
  glm::dquat tracker_orientation{1.0, 0.0, 0.0, 0.0};
  std::int64_t freshness_ns = 0;                               // "freshness_ms"; 0: the source's default (above)
  std::string hid_path;                                        // "hid.path": a hidapi path; empty: the first tracker
  std::string hid_layout = "packed";                           // "hid.layout": packed | dmf (gaze/hid/README.md)
  double hid_screen_width_m = 0.0, hid_screen_height_m = 0.0;  // "hid.screen_mm"; 0: the device's

  std::int64_t effective_freshness_ns() const {
    if (freshness_ns > 0) return freshness_ns;
    return trace_path.empty() ? kHidFreshnessNs : kTraceFreshnessNs;
  }
};

struct ConfigResult {
  LayerConfig config;
  std::string error;  // "" = fine; else one line, e.g. "/x.json: head_offset.position_m: ..."
};

// From the two variables' values (null or "" = unset); reads the JSON file when given.
ConfigResult load_config(const char* trace_env, const char* config_env);
// Reads the process environment.
ConfigResult load_config_from_env();
// The JSON object `text` (from `file`, for messages) applied over `base`.
ConfigResult parse_config_json(const std::string& text, const std::string& file, LayerConfig base);

}  // namespace gazelod::layer
