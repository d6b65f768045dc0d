// SPDX-License-Identifier: Apache-2.0
// `gazelod run`: one session through the OpenXR loader (the simulated runtime by default),
// the plugin choosing LODs each frame, every eye rendered with Vulkan, and a report.
#pragma once

#include "apps/gazelod/commands/command.hpp"
#include "plugin/lod_plugin.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::cli {

struct RunSummary;   // run/report.hpp
struct FrameRecord;  // run/report.hpp

struct RunOptions {
  std::int64_t frames = 0;    // 0: the scenario's whole duration
  std::string scenario_path;  // "" = the embedded default scenario
  std::string scene_path;     // a glb from `gazelod bake`: its objects replace the scenario's
  std::string scene_placement =
      "in-front";   // "in-front": moved before the viewer's start; "file": the glTF's own placement
  std::string hmd;  // preset overriding the scenario's display
  EnabledCriteria criteria;
  std::filesystem::path out_dir = "gazelod-out";
  std::string runtime = "sim";  // "sim" or "system"
  double budget_ms = 0.0;       // 0: no frame budget
  double gaze_error_deg = 0.0;  // > 0: the gaze error assumed for every source; 0: the plugin's per-source defaults
  bool paced = false;           // sleep to the display rate (default: as fast as possible)
  bool render = true;           // false: select only, no Vulkan drawing
  // "cpu": the plugin's cut drawn cluster by cluster; "gpu": selected by the compute shader and
  // drawn with one indirect-count draw per eye (run/gpu_clusters.hpp; needs rendering, a scene
  // with cluster meshes that stay put, and turns the plugin's cluster switch policy off).
  std::string cluster_select = "cpu";
  bool eye_gaze = true;    // false: ignore the runtime's eye gaze (fallback test)
  std::string trace_path;  // an external gaze source: a gazelod trace to replay
  // With a trace that has head poses (and the simulated runtime): the head moves as recorded
  // (relative to its first pose) in place of the scenario's head effects, so the replayed
  // eye-in-head gaze and the head it was recorded with stay together. false: the scenario's head.
  bool trace_head = true;
  bool hid_gaze = false;                      // the first HID eye tracker (usage page 0x12) as the gaze source
  std::optional<std::int64_t> capture_frame;  // frame saved as PNG in out_dir (none: the middle one); >= 0
  bool quiet = false;                         // no progress lines
  bool audit = true;                          // the visibility audit against the simulator's truth (run/audit.hpp)
  bool breakdown = false;                     // print the audit's breakdown (run/audit_breakdown.hpp)
  // The offline optimum at the policy's switches (run/offline_bound.hpp; on with breakdown):
  // keeps 3 bytes per object-frame, up to kMaxOfflineObjectFrames.
  bool offline_bound = false;
  // Evaluate the LOD-map thesis's policy (eval/lod_map.hpp) beside the plugin each frame, for
  // the reports' comparison (eval, compare); nothing it picks is drawn.
  bool lod_map = false;
  std::string decisions_path;          // "" = none; else the drawn levels per frame (DecisionsFile, run/report.hpp)
  std::string cluster_decisions_path;  // "" = none; else the drawn cut per frame (clusters/decisions.hpp)
  // Callers that run sessions as a function (gazelod eval family): the switch policy and the
  // gaze conditioning in place of the plugin's defaults; write_reports = false writes only the
  // scenario the runtime reads (no summary.json, frames.csv or plots), and `result` (when set)
  // receives the summary.
  std::optional<lod::SwitchPolicyConfig> switching;
  std::optional<gaze::ConditionerConfig> conditioning;
  bool write_reports = true;
  RunSummary* result = nullptr;
  std::vector<FrameRecord>* frames_result = nullptr;  // when set: receives the per-frame records
  // Tests only (no option): called with each counted frame's decisions and diagnostics, after
  // the frame is drawn; the spans are valid during the call.
  std::function<void(const FrameDecisions&, const FrameDiagnostics&)> frame_observer;
};

// --criteria: "all", "none" or a comma list of size, eccentricity, velocity. Throws UsageError.
EnabledCriteria parse_criteria(const std::string& text);

// Returns the process exit status; throws UsageError for bad options or input.
int run_session(const RunOptions& options, Io io);

// A session run as a function, for eval and compare: quiet, its summary returned (and its
// report files written when options.write_reports). Throws UsageError "<what> failed (exit N):
// <the run's own message>" when it does not end with status 0.
RunSummary run_for_summary(RunOptions options, const std::string& what);

}  // namespace gazelod::cli
