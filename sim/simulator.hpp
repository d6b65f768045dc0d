// SPDX-License-Identifier: Apache-2.0
// The scripted simulator: a scenario (display, scene, head and eye effects) stepped into
// head poses, eye-tracker samples and object positions at any time. The simulated OpenXR
// runtime (sim/runtime/) and `gazelod run` read it; only the effects a scenario lists run.
#pragma once

#include "gaze/gaze_sample.hpp"
#include "lod/display.hpp"
#include "lod/lod_chain.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <climits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gazelod::sim {

// A scenario that cannot be loaded: the message names the JSON path ("effects[2].amplitude_deg")
// and the source (file name).
struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// How the simulated runtime delivers eye gaze; real runtimes differ (docs/runtime.md, Gaze quirks).
enum class GazeDelivery : std::uint8_t {
  normal,                       // pose at the requested time, true sample time
  never_delivers,               // advertises the extension, pose never valid
  sample_time_zero,             // XrEyeGazeSampleTimeEXT.time = 0
  sample_time_is_request_time,  // XrEyeGazeSampleTimeEXT.time = the time asked for
};

struct RuntimeOptions {
  bool eye_gaze_supported = true;  // XrSystemEyeGazeInteractionPropertiesEXT
  GazeDelivery gaze_delivery = GazeDelivery::normal;
  bool paced = true;  // xrWaitFrame sleeps to the display rate
};

struct SceneObject {
  std::string name;
  glm::dvec3 position_m{0.0};       // world (OpenXR LOCAL space) at t = 0
  glm::dvec3 velocity_m_s{0.0};     // constant, unless an effect moves it
  double radius_m = 0.5;            // bounding sphere
  std::vector<lod::LodLevel> lods;  // level 0 = full detail
  double importance = 1.0;
};

// One effect as written in the scenario; parsed and validated by its own file in sim/.
struct EffectSpec {
  std::string type;         // "head_sweep", "saccades", "tracker_noise", ...
  std::string params_json;  // the effect's JSON object, verbatim
  std::string json_path;    // "effects[2]", for error messages
};

// The observer's path before head effects: position_m(t) = start_m + velocity_m_s * t
// (Reddy 1998's forward walk through a random field of objects).
struct HeadPath {
  glm::dvec3 start_m{0.0};
  glm::dvec3 velocity_m_s{0.0};
};

// The longest scenario (seconds, `duration_s`), and the slack `gazelod run` gives the simulated
// runtime beyond its frames (the run, not the runtime, ends the session): the runtime accepts a
// duration up to their sum, so every scenario that validates also runs.
inline constexpr double kMaxScenarioDurationS = 1e6;
inline constexpr double kRunSlackS = 1.0;

struct Scenario {
  int version = 1;
  std::string name;
  // The file it was read from (load_scenario_file; "" for text): the effects' relative trace
  // files are found beside it. Not written back (scenario_to_json).
  std::string file;
  lod::DisplaySpec display;
  double duration_s = 10.0;
  double frame_rate_hz = 90.0;
  std::uint64_t seed = 1;
  std::vector<SceneObject> objects;
  std::vector<EffectSpec> effects;
  RuntimeOptions runtime;
  HeadPath head_path;  // scene.head_path, or the generator's forward_speed_m_s
};

Scenario load_scenario_json(std::string_view json_text, std::string_view source_name);
Scenario load_scenario_file(const std::string& path);
// The file's text, refusing what is not a scenario file (a directory, a device) and anything
// past the size limit (sim/scene_json.hpp) before reading it all; throws ScenarioError.
std::string read_scenario_text(const std::string& path);
// The embedded default: a Reddy-1998-style field of objects with four LODs, an eye-tracked HMD
// preset, head sweeps, saccades and a pursuit.
std::string_view default_scenario_json();
// The scenario as JSON that load_scenario_json reads back to an equal scenario (generated
// objects are written out explicitly), e.g. to hand an adjusted scenario to the runtime.
std::string scenario_to_json(const Scenario& scenario);

// Head pose in the world (LOCAL) frame, with velocities, at a time.
struct HeadState {
  std::int64_t t_ns = 0;
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 position_m{0.0};
  glm::dvec3 angular_velocity_rad_s{0.0};  // world frame
  glm::dvec3 linear_velocity_m_s{0.0};
};

struct ObjectState {
  glm::dvec3 position_m{0.0};
  glm::dvec3 velocity_m_s{0.0};
};

// The true state of the eye at a time (ground truth for audits; no tracker ever reports it).
// Gaze effects that own the eye direction at t set it (later effects in the list win, as for
// the direction): saccades (in a saccade), smooth_pursuit (the pursued object; its catch-up
// saccades, instantaneous in the simulator, and the jumps onto and off the target count as
// saccades ending then); blinks (the lid closed).
struct EyeTruth {
  bool in_saccade = false;
  bool in_blink = false;
  int pursuit_object = -1;  // index into Scenario::objects; -1: no pursuit
  // When the latest saccade at or before t ended (INT64_MIN: none yet).
  std::int64_t last_saccade_end_ns = INT64_MIN;
};

// Not thread-safe: one caller at a time (the simulated runtime holds its lock).
class Simulator {
 public:
  explicit Simulator(Scenario scenario);
  ~Simulator();
  Simulator(Simulator&&) noexcept;
  Simulator& operator=(Simulator&&) noexcept;

  const Scenario& scenario() const;

  // Times are nanoseconds from the scenario's start (0). Queries may come in any order;
  // the same scenario and seed give the same values bit for bit.
  HeadState head_at(std::int64_t t_ns);
  // What the eye tracker reports at t: the newest sample available by t after the tracker
  // effects (rate, latency, noise, dropouts, offset). sample.t_ns is when it was taken.
  gaze::GazeSample tracker_at(std::int64_t t_ns);
  // The true gaze (head space) at t, before any tracker effect.
  gaze::GazeSample true_gaze_at(std::int64_t t_ns);
  // Object positions at t, one per scenario().objects entry.
  std::span<const ObjectState> objects_at(std::int64_t t_ns);
  // The true eye state at t (saccade, blink, pursuit); no allocation beyond the effects' own
  // lazily drawn schedules.
  EyeTruth eye_truth_at(std::int64_t t_ns);

  std::int64_t duration_ns() const;
  // When the tracker delivers its first sample (taken at 0): its latency. Before that,
  // tracker_at returns an invalid sample with t_ns 0.
  std::int64_t first_tracker_sample_ns() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gazelod::sim
