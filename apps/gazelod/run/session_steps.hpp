// SPDX-License-Identifier: Apache-2.0
// The steps of one `gazelod run` session (run/session.hpp), for run/session.cpp (the frame
// loop and the report) and run/session_open.cpp (opening the scenario, runtime and plugin).
// Internal to the run room.
#pragma once

#include "apps/gazelod/clusters/decisions.hpp"
#include "apps/gazelod/clusters/scene.hpp"
#include "apps/gazelod/run/render.hpp"
#include "apps/gazelod/run/decisions_file.hpp"
#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/run/scenario.hpp"
#include "apps/gazelod/run/session.hpp"
#include "apps/gazelod/run/session_audit.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "apps/xr_host/xr_app.hpp"
#include "auxiliary/angles.hpp"
#include "auxiliary/folder_lock.hpp"
#include "sim/simulator.hpp"

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::cli::run_steps {

using Clock = std::chrono::steady_clock;

// Saccade onsets for the plot: the gaze turning faster than 100 deg/s between two frames
// after a frame that did not (a frame-rate I-VT; the trace tools classify properly).
class SaccadeMarker {
 public:
  bool update(bool valid, const glm::dvec3& dir_head, double t_s) {
    bool onset = false;
    if (valid && have_ && t_s > t_s_) {
      const double angle = aux::angle_between_rad(prev_, dir_head);
      const bool fast = angle * aux::kDegPerRad / (t_s - t_s_) > 100.0;
      onset = fast && !in_saccade_;
      in_saccade_ = fast;
    }
    have_ = valid;
    prev_ = dir_head;
    t_s_ = t_s;
    return onset;
  }

 private:
  bool have_ = false, in_saccade_ = false;
  glm::dvec3 prev_{0.0, 0.0, -1.0};
  double t_s_ = 0.0;
};

class Session {
 public:
  Session(const RunOptions& opt, Io io);
  // The exit status: 0, 1 (no frame, the runtime failed), 2, or 128 + the signal that stopped it.
  int run();

 private:
  void split_objects();
  void check_decision_paths() const;  // throws UsageError
  void open_decision_files();
  int open_runtime_and_plugin();  // 0 or the exit status
  PluginConfig plugin_config() const;
  void say_source_changes();
  void register_objects();
  void plan_frames();
  bool handle_events_and_signals();  // false: the session is over
  int frame();                       // 0 or the exit status
  void draw(const XrFrameState& fs, const FrameDecisions& d, const FrameDiagnostics& diag, bool counting);
  void count(const XrFrameState& fs, double frame_ms, double select_ms, const FrameDecisions& d,
             const FrameDiagnostics& diag);
  void progress_line(std::uint64_t cluster_triangles);
  int finish();

  const RunOptions& opt_;
  Io io_;
  // --out held against another gazelod writing there, until the last report file is written.
  std::unique_ptr<aux::FolderLock> out_lock_;
  // Ctrl-C / SIGTERM: stop at a frame boundary with a report. Before the files: it goes after
  // them, so their destructors remove their temporaries before it re-raises a pending signal.
  std::optional<StopOnSignal> stop_;
  const PreparedScenario prepared_;
  sim::Simulator simulator_;
  const sim::Scenario& scenario_;
  ClusterScene clusters_;
  std::vector<std::size_t> plain_;  // plain_[k]: the scenario index of plugin object k
  std::optional<DecisionsFile> decisions_;
  std::optional<ClusterDecisionsFile> cluster_decisions_;
  std::optional<xr_host::XrApp> app_;
  std::shared_ptr<TraceFromFirstFrame> trace_;
  // Lines the HID reader thread logs wait here for the frame loop (drain_thread_log): io_.err
  // is not that thread's to write. In-process (Python, eval, the tests) it is an ostringstream,
  // and the thread's line written beside the frame loop's corrupted its buffer ("malloc():
  // smallbin double linked list corrupted", once in a loaded CI run). Shared with the thread's
  // callback, so a line logged while the plugin shuts down has somewhere to go.
  struct ThreadLog {
    std::mutex mutex;
    std::vector<std::string> lines;
    std::size_t dropped = 0;  // past kMaxLines between two drains
    static constexpr std::size_t kMaxLines = 1000;
  };
  std::shared_ptr<ThreadLog> thread_log_ = std::make_shared<ThreadLog>();
  void drain_thread_log();
  std::unique_ptr<LodPlugin> plugin_;
  // Source changes: the first few said as they happen, the rest (every blink is one) counted.
  int source_changes_ = 0, source_changes_unshown_ = 0;
  bool session_ending_ = false;
  std::vector<std::vector<lod::LodLevel>> chains_;  // plugin object k's levels
  std::vector<double> radii_;
  std::uint64_t triangles_full_ = 0;
  std::optional<RunRenderer> renderer_;
  std::vector<const bake::BakedObject*> baked_of_plain_;
  std::uint32_t key_levels_ = 1;  // frame.png's colour key
  double rate_hz_ = 90.0;
  std::int64_t planned_ = 0, capture_ = 0;
  std::vector<FrameRecord> frames_;
  std::vector<glm::dvec3> positions_;
  std::vector<sim::ObjectState> objects_;  // the plugin's objects, from the simulator
  std::vector<XrView> views_;
  SaccadeMarker saccades_;
  XrTime time_base_ = 0;
  std::optional<SessionAudit> audit_;
  std::optional<ClusterMotion> cluster_motion_;
  bool layout_checked_ = false, exit_requested_ = false;
  bool png_saved_ = false;  // --capture-frame past the last frame saves none
  int interrupted_by_ = 0;
  Clock::time_point last_progress_, started_;
};

}  // namespace gazelod::cli::run_steps
