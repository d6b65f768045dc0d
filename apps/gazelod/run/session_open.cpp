// SPDX-License-Identifier: Apache-2.0
// Opening a `gazelod run` session: the objects split between the plugin and the cluster
// meshes, the decisions files, the runtime and the plugin, the objects registered, the plan.
#include "apps/gazelod/run/frame_record.hpp"
#include "apps/gazelod/run/session_steps.hpp"
#include "gaze/hid/hid_gaze_source.hpp"
#include "render/lod_palette.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace gazelod::cli::run_steps {

// The scenario: the runtime serves it; this process also steps it for object motion.
Session::Session(const RunOptions& opt, Io io)
    : opt_(opt),
      io_(io),
      prepared_(prepare_scenario(opt)),
      simulator_(prepared_.scenario),
      scenario_(simulator_.scenario()) {}

// --scene with cluster hierarchies: those objects are cluster meshes (clusters/scene.hpp); the
// plugin's objects are the others.
void Session::split_objects() {
  if (prepared_.baked) clusters_ = make_cluster_scene(*prepared_.baked, prepared_.scene_shift_m, scenario_);
  for (const std::string& note : clusters_.notes) io_.err << "gazelod run: --scene: " << note << "\n";
  for (std::size_t i = 0; i < scenario_.objects.size(); ++i)
    if (i >= clusters_.drawn_as_clusters.size() || !clusters_.drawn_as_clusters[i]) plain_.push_back(i);
  cluster_motion_.emplace(clusters_);
  layout_checked_ = clusters_.empty();
  if (opt_.cluster_select == "gpu") {
    if (!opt_.render) throw UsageError("--cluster-select gpu: needs rendering (not --no-render)");
    if (clusters_.empty())
      throw UsageError(
          "--cluster-select gpu: the scene has no cluster meshes (--scene with a file from gazelod bake --clusters)");
  } else if (opt_.cluster_select != "cpu") {
    throw UsageError("--cluster-select: must be 'cpu' or 'gpu', got '" + opt_.cluster_select + "'");
  }
}

// Before anything is written: a path that names a folder is bad input (exit 2), as for the
// run's input files.
void Session::check_decision_paths() const {
  if (!opt_.cluster_decisions_path.empty() && clusters_.empty())
    throw UsageError(
        "--cluster-decisions: the scene has no cluster meshes (--scene with a file from "
        "gazelod bake --clusters)");
  check_output_file("--decisions", opt_.decisions_path);
  check_output_file("--cluster-decisions", opt_.cluster_decisions_path);
}

// Opened before the session so that a bad path fails at once; committed (renamed into place)
// only after the last frame.
void Session::open_decision_files() {
  if (!opt_.decisions_path.empty()) {
    std::vector<std::string> names;
    for (std::size_t i : plain_) names.push_back(scenario_.objects[i].name);
    decisions_.emplace(opt_.decisions_path, names);
  }
  if (!opt_.cluster_decisions_path.empty()) cluster_decisions_.emplace(opt_.cluster_decisions_path, clusters_);
}

PluginConfig Session::plugin_config() const {
  PluginConfig config;
  // --trace: the trace is the gaze source for the whole run (from the first frame on; the
  // runtime's own gaze is not used), and the source-change lines say when it ends.
  config.use_openxr_eye_gaze =
      opt_.eye_gaze && app_ && app_->eye_gaze_enabled() && opt_.trace_path.empty() && !opt_.hid_gaze;
  config.criteria = opt_.criteria;
  config.compute_breakdown = true;
  config.budget_ms = opt_.budget_ms;
  // One accuracy for every source (the plugin's defaults differ per source), so runs that get the
  // same gaze through different sources can be compared (tests/layer).
  if (opt_.gaze_error_deg > 0.0) config.openxr_gaze_error_deg = config.external_gaze_error_deg = opt_.gaze_error_deg;
  // Plan with a margin: the cost fit is unbiased, so without one about half the frames would
  // land above their prediction.
  config.budget.headroom = 0.15;
  config.hmd_override = opt_.hmd;
  if (opt_.switching) config.switching = *opt_.switching;
  if (opt_.conditioning) config.conditioning = *opt_.conditioning;
  config.external_source = trace_;
  // The shader keeps no history: the plugin's cut is then the one it can be checked against.
  config.cluster_switch_policy = opt_.cluster_select != "gpu";
  return config;
}

int Session::open_runtime_and_plugin() {
  try {
    app_.emplace(opt_.eye_gaze);
  } catch (const xr_host::XrAppError& e) {
    io_.err << "gazelod run: " << e.what() << "\n";
    return 1;
  }
  PluginConfig config = plugin_config();
  if (opt_.hid_gaze) {
    // The first HID eye tracker, its samples mapped onto the runtime's clock. No tracker (or
    // one unplugged later): the source says so and the plugin falls back to head-fixed gaze.
    if (app_->now() == 0) {
      io_.err << "gazelod run: --gaze hid needs XR_KHR_convert_timespec_time (the runtime's clock), which this "
                 "runtime does not offer\n";
      return 2;
    }
    gaze::hid::HidTrackerConfig hid;
    const xr_host::XrApp* host = &*app_;
    hid.host_now_ns = [host] { return static_cast<std::int64_t>(host->now()); };
    hid.log = [log = thread_log_](const std::string& line) {  // the reader thread's: queued
      const std::lock_guard<std::mutex> lock(log->mutex);
      if (log->lines.size() < ThreadLog::kMaxLines)
        log->lines.push_back(line);  // already "gazelod hid: ..."
      else
        ++log->dropped;
    };
    config.external_source = std::make_shared<gaze::hid::HidGazeSource>(std::move(hid));
  }
  // Refused before the session is used, with the field and its value (docs/error-policy.md).
  if (const std::string why = validate_plugin_config(config); !why.empty()) throw UsageError("plugin config: " + why);
  plugin_ = LodPlugin::create(xrGetInstanceProcAddr, app_->instance(), app_->system(), app_->session(),
                              app_->local_space(), config);
  say_source_changes();
  return 0;
}

// The HID reader thread's lines, written by the frame loop's thread (ThreadLog).
void Session::drain_thread_log() {
  std::vector<std::string> lines;
  std::size_t dropped = 0;
  {
    const std::lock_guard<std::mutex> lock(thread_log_->mutex);
    lines.swap(thread_log_->lines);
    std::swap(dropped, thread_log_->dropped);
  }
  if (opt_.quiet) return;
  for (const std::string& line : lines) io_.err << line << "\n";
  if (dropped > 0) io_.err << "gazelod hid: (" << dropped << " more lines not shown)\n";
}

// The first few source changes are said as they happen, the rest (every blink is one) counted
// and summarised at the end; none once the session winds down, when the eye-gaze action goes
// inactive by design (that was a false alarm at the end of every run).
void Session::say_source_changes() {
  constexpr int kSourceLinesShown = 8;
  plugin_->on_source_changed([this](GazeSourceKind now, const std::string& why) {
    if (session_ending_ || opt_.quiet) return;
    if (++source_changes_ > kSourceLinesShown) {
      ++source_changes_unshown_;
      return;
    }
    io_.err << "gazelod run: gaze source " << to_string(now) << ": " << why << "\n";
    if (source_changes_ == kSourceLinesShown)
      io_.err << "gazelod run: (further gaze source changes, blinks among them, are counted: the per-frame source "
                 "is in frames.csv)\n";
  });
}

void Session::register_objects() {
  for (std::size_t i : plain_) {
    const sim::SceneObject& o = scenario_.objects[i];
    ObjectDesc d;
    d.center_m = o.position_m;
    d.radius_m = o.radius_m;
    d.velocity_m_s = o.velocity_m_s;
    d.lods = o.lods;
    d.importance = o.importance;
    plugin_->add_object(d);
    chains_.push_back(o.lods);
    radii_.push_back(o.radius_m);
  }
  register_cluster_meshes(clusters_, *plugin_);
  triangles_full_ = chain_triangles(chains_, std::vector<std::uint8_t>(chains_.size(), 0));
  audit_.emplace(scenario_, opt_.criteria, plain_, chains_, clusters_, opt_.offline_bound || opt_.breakdown);
  // --scene objects are drawn with their levels' own triangles (the scenario's objects are the
  // baked file's, in order); generated objects as stand-in spheres.
  if (prepared_.baked)
    for (std::size_t i : plain_)
      baked_of_plain_.push_back(i < prepared_.baked->objects.size() ? &prepared_.baked->objects[i] : nullptr);
  if (opt_.render)
    renderer_.emplace(*app_, chains_, clusters_.empty() ? nullptr : &clusters_, baked_of_plain_,
                      opt_.cluster_select == "gpu");
  // frame.png's colour key: every level an object has, or every tint when cluster depths are drawn.
  key_levels_ = clusters_.empty() ? 1u : static_cast<std::uint32_t>(render::kLodPaletteSize);
  for (const auto& c : chains_) key_levels_ = std::max(key_levels_, static_cast<std::uint32_t>(c.size()));
  positions_.resize(plain_.size());
  objects_.resize(plain_.size());
}

void Session::plan_frames() {
  rate_hz_ = scenario_.frame_rate_hz > 0 ? scenario_.frame_rate_hz : 90.0;
  planned_ = opt_.frames > 0 ? opt_.frames : static_cast<std::int64_t>(std::llround(scenario_.duration_s * rate_hz_));
  if (opt_.capture_frame && *opt_.capture_frame < 0)  // a caller's options (the command line refuses it)
    throw UsageError("--capture-frame: '" + std::to_string(*opt_.capture_frame) + "' is negative");
  capture_ = opt_.capture_frame.value_or(planned_ / 2);
  // A trace shorter than the run: past its end the gaze falls back to head-fixed (and says so
  // then); say it before, with the way to bound the run.
  const double run_s = static_cast<double>(planned_) / rate_hz_;
  if (trace_ && trace_->duration_s() + 1.0 / rate_hz_ < run_s) {
    const auto covered = static_cast<std::int64_t>(trace_->duration_s() * rate_hz_) + 1;
    char line[256];
    std::snprintf(line, sizeof line,
                  "gazelod run: --trace: the trace lasts %.2f s, the run %.2f s: frames after %lld fall back to "
                  "head-fixed gaze (--frames %lld stops with the trace)\n",
                  trace_->duration_s(), run_s, static_cast<long long>(covered), static_cast<long long>(covered));
    io_.err << line;
  }
  // Every frame keeps a record for the report: say so before a run that will hold gigabytes
  // (a scenario of hours at 1 kHz), and reserve at most 65,536 up front (a reserve of
  // the whole plan failed with std::bad_alloc before the first frame).
  // A plan past half the machine's memory is refused before it starts: it would run for hours
  // and end killed, or swapping, with nothing written.
  const double record_gb = static_cast<double>(planned_) * static_cast<double>(sizeof(FrameRecord) + 32) / 1e9;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGESIZE);
  const double memory_gb =
      pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size) / 1e9 : 0.0;
  if (memory_gb > 0.0 && record_gb > 0.5 * memory_gb) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%lld frames would keep about %.0f GB of per-frame records for the report, more than half of this "
                  "machine's %.0f GB; bound the run with --frames",
                  static_cast<long long>(planned_), record_gb, memory_gb);
    throw UsageError(line);
  }
  if (record_gb > 2.0)
    io_.err << "gazelod run: " << planned_ << " frames will keep about " << static_cast<int>(record_gb + 0.5)
            << " GB of per-frame records for the report; bound the run with --frames\n";
  frames_.reserve(static_cast<std::size_t>(std::min<std::int64_t>(planned_, 1 << 16)));
}

}  // namespace gazelod::cli::run_steps
