// SPDX-License-Identifier: Apache-2.0
// The scenario of a `gazelod run`: loaded (file or embedded default), adjusted by the
// command line (--hmd, --frames, --paced), written to the output folder for the simulated
// runtime, and the environment that points the OpenXR loader at that runtime.
#pragma once

#include "gaze/gaze_source.hpp"
#include "gaze/replay_source.hpp"
#include "apps/gazelod/run/session.hpp"
#include "auxiliary/time.hpp"
#include "bake/baked_scene.hpp"
#include "sim/simulator.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::cli {

struct PreparedScenario {
  sim::Scenario scenario;
  std::string label;           // "default" or the file name
  std::filesystem::path file;  // the effective scenario as the runtime reads it (--out/scenario.json)
  std::string text;            // its JSON, written by write_scenario_file
  double duration_s = 0.0;
  // --scene: the baked file, whose objects are the scenario's objects in the same order, and the
  // translation --scene-placement applied to them (0 for `file`).
  std::optional<bake::BakedScene> baked;
  glm::dvec3 scene_shift_m{0.0};
  std::vector<std::string> notes;  // what the preparation changed, for the run to print
  // --trace with head poses: the head replays the trace from scenario time 0, and the gaze
  // replay must start there too (TraceFromFirstFrame::start_at).
  bool trace_head = false;
};

// The files a run writes in --out (the report, and the scenario as run).
inline constexpr const char* kRunReportFiles[] = {"summary.json", "frames.csv", "frames.svg",
                                                  "audit.svg",    "frame.png",  "scenario.json"};

// Loads and adjusts the scenario; writes nothing. Throws UsageError naming the scenario file /
// JSON path, the scene file, or an input that is one of the report's files in --out.
PreparedScenario prepare_scenario(const RunOptions& options);

// Writes scenario.json in --out (created). An earlier run's other report files stay until
// this run's report replaces them (the run removes a frame.png it did not write then, and the
// report an audit.svg). Throws UsageError.
void write_scenario_file(const PreparedScenario& prepared);

// Sets XR_RUNTIME_JSON (the simulated runtime built with this program, unless the caller
// set it), GAZELOD_SIM_SCENARIO, GAZELOD_SIM_DURATION_S and GAZELOD_SIM_PACED.
void point_loader_at_simulator(const PreparedScenario& prepared, const RunOptions& options);

// A trace replayed as the external gaze source: trace time 0 (its first row) plays at the first
// time the plugin asks for, so any recording lines up with any session, or at start_at's time
// when called before that (the scenario's time 0, where a replayed head starts).
class TraceFromFirstFrame final : public gaze::GazeSource {
 public:
  explicit TraceFromFirstFrame(std::vector<gaze::TraceRecord> records);
  void start_at(std::int64_t t_ns);
  std::string name() const override { return "trace"; }
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override;
  std::string status() const override { return replay_.status(); }
  // From the first sample to the last (seconds): how long the trace can stand in for gaze.
  double duration_s() const { return aux::seconds_from_ns(duration_ns_); }

 private:
  std::int64_t start_ns_ = 0, offset_ns_ = 0, duration_ns_ = 0;
  bool started_ = false;
  gaze::ReplaySource replay_;
};

// The external gaze source from the options (a trace replay), or null.
std::shared_ptr<TraceFromFirstFrame> make_external_source(const RunOptions& options);

}  // namespace gazelod::cli
