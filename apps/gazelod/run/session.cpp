// SPDX-License-Identifier: Apache-2.0
// One `gazelod run` session as a frame loop anyone can follow (after hello_xr): open the
// scenario, the runtime and the plugin (run/session_open.cpp); each frame select, draw, submit
// and count; then report. Each step is one member function of run_steps::Session
// (run/session_steps.hpp), in the order the session takes them.
#include "apps/gazelod/run/frame_record.hpp"
#include "apps/gazelod/run/session_steps.hpp"
#include "apps/gazelod/commands/out_folder.hpp"

#include <algorithm>
#include <sstream>

namespace gazelod::cli {
namespace run_steps {
namespace {

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string criteria_text(const EnabledCriteria& c) {
  std::string s;
  auto add = [&](bool on, const char* name) {
    if (!on) return;
    if (!s.empty()) s += ",";
    s += name;
  };
  add(c.size, "size");
  add(c.eccentricity, "eccentricity");
  add(c.velocity, "velocity");
  return s.empty() ? "none" : s;
}

}  // namespace

int Session::run() {
  // Routine notes (what the preparation did) only without --quiet; warnings always.
  if (!opt_.quiet)
    for (const std::string& note : prepared_.notes) io_.err << "gazelod run: " << note << "\n";
  // Every refusal decided up front comes before the first write to --out (a run refused for
  // memory left scenario.json): the options, the objects' split, the trace, the plugin's
  // configuration, the plan, the decisions files' paths. Then the decisions files are opened
  // (so that a bad path fails before the session), in --out too: a folder created for them is
  // removed again when they cannot be.
  if (opt_.runtime != "sim" && opt_.runtime != "system")
    throw UsageError("--runtime: must be 'sim' or 'system', got '" + opt_.runtime + "'");
  split_objects();
  trace_ = make_external_source(opt_);
  if (const std::string why = validate_plugin_config(plugin_config()); !why.empty())
    throw UsageError("plugin config: " + why);
  plan_frames();
  check_decision_paths();
  // From the first write on, Ctrl-C / SIGTERM stop cleanly: the loop acts on a request made
  // while the runtime was opening, and a second one removes the temporaries being written.
  stop_.emplace();
  // Held before anything is written there (commands/out_folder.hpp).
  OutFolder out = hold_out_folder(opt_.out_dir, "run", io_.err);
  out_lock_ = std::move(out.lock);
  try {
    open_decision_files();
  } catch (...) {
    std::error_code ec;
    if (out.created) std::filesystem::remove(opt_.out_dir, ec);  // only when still empty
    throw;
  }
  write_scenario_file(prepared_);
  if (opt_.runtime == "sim") point_loader_at_simulator(prepared_, opt_);
  if (const int rc = open_runtime_and_plugin(); rc != 0) return rc;
  register_objects();
  last_progress_ = started_ = Clock::now();
  while (handle_events_and_signals())
    if (const int rc = frame(); rc != 0) return rc;
  return finish();
}

// The runtime's events, a stop signal, and the end of the planned frames.
bool Session::handle_events_and_signals() {
  drain_thread_log();
  for (;;) {
    const bool keep_going = app_->poll_events([&](XrSessionState s, XrTime t) {
      if (s == XR_SESSION_STATE_STOPPING || s == XR_SESSION_STATE_EXITING || s == XR_SESSION_STATE_LOSS_PENDING)
        session_ending_ = true;
      plugin_->on_session_state(s, t);
      if (s == XR_SESSION_STATE_LOSS_PENDING)  // never end silently: say why the run stops
        io_.err << "gazelod run: the runtime is losing the session (XR_SESSION_STATE_LOSS_PENDING); ending after "
                << frames_.size() << " frames\n";
    });
    if (!keep_going) return false;
    if (interrupted_by_ == 0 && stop_->requested() != 0) {
      interrupted_by_ = stop_->requested();
      stop_->acted_on();
      io_.err << "gazelod run: " << StopOnSignal::name(interrupted_by_) << " after " << frames_.size()
              << " frames: ending the session and writing the report of those (again to quit at once)\n";
      if (!exit_requested_ && app_->session_running()) xrRequestExitSession(app_->session());
      exit_requested_ = true;
      session_ending_ = true;
      if (!app_->session_running()) return false;
    }
    if (!app_->session_running()) continue;
    if (static_cast<std::int64_t>(frames_.size()) >= planned_ && !exit_requested_) {
      xrRequestExitSession(app_->session());
      exit_requested_ = true;
      session_ending_ = true;
    }
    return true;
  }
}

int Session::frame() {
  const XrFrameState fs = app_->wait_frame();
  const auto t0 = Clock::now();
  app_->begin_frame();
  if (time_base_ == 0) {
    time_base_ = app_->scenario_time_base();
    // A replayed trace is not the simulator's eye: no ground truth to hold it against.
    audit_->start(opt_.runtime == "sim" && time_base_ != 0 && opt_.trace_path.empty() && !opt_.hid_gaze, opt_.audit);
    if (time_base_ == 0) time_base_ = fs.predictedDisplayTime - fs.predictedDisplayPeriod;
    if (trace_ && prepared_.trace_head) trace_->start_at(time_base_);  // where the replayed head starts
  }
  const auto all_objects = simulator_.objects_at(fs.predictedDisplayTime - time_base_);
  for (std::size_t k = 0; k < plain_.size() && plain_[k] < all_objects.size(); ++k) {
    objects_[k] = all_objects[plain_[k]];
    plugin_->set_object_motion(static_cast<std::uint32_t>(k), objects_[k].position_m, objects_[k].velocity_m_s);
    positions_[k] = objects_[k].position_m;
  }
  for (std::size_t k : cluster_motion_->update(scenario_, all_objects)) {
    if (opt_.cluster_select == "gpu")
      throw UsageError("--cluster-select gpu: the scenario moves cluster mesh '" + clusters_.meshes[k].label +
                       "'; the GPU path draws cluster meshes where they were registered (use --cluster-select cpu)");
    plugin_->set_cluster_mesh_motion(static_cast<std::uint32_t>(k), cluster_motion_->pose(k),
                                     cluster_motion_->velocity_m_s(k));
    audit_->set_cluster_pose(k, cluster_motion_->pose(k), cluster_motion_->velocity_m_s(k));
  }
  const FrameDecisions& d = plugin_->begin_frame(fs.predictedDisplayTime);
  const FrameDiagnostics& diag = plugin_->diagnostics();
  const double select_ms = ms_since(t0);
  if (!layout_checked_ && !same_cluster_layout(clusters_, d.cluster_first)) {
    io_.err << "gazelod run: the plugin laid out the cluster meshes otherwise than they were registered\n";
    return 1;
  }
  layout_checked_ = true;
  const bool counting = !exit_requested_ && static_cast<std::int64_t>(frames_.size()) < planned_;
  draw(fs, d, diag, counting);
  const double frame_ms = ms_since(t0);
  plugin_->end_frame(frame_ms);
  if (counting) count(fs, frame_ms, select_ms, d, diag);
  return 0;
}

// Both eyes drawn and submitted (an empty layer list when not rendering); frame.png saved at
// the capture frame.
void Session::draw(const XrFrameState& fs, const FrameDecisions& d, const FrameDiagnostics& diag, bool counting) {
  std::vector<XrView>* submitted = nullptr;
  if (fs.shouldRender && app_->locate_views(fs.predictedDisplayTime, views_) && renderer_) {
    const bool save = counting && static_cast<std::int64_t>(frames_.size()) == capture_;
    for (std::size_t eye = 0; eye < views_.size(); ++eye) {
      const std::uint32_t index = app_->acquire(eye);
      renderer_->render_eye(eye, index, views_[eye], positions_, radii_, d, diag, cluster_motion_->shift_m());
      if (save && eye == 0) {
        renderer_->save_png(eye, index, opt_.out_dir / "frame.png", key_levels_);
        png_saved_ = true;
      }
      app_->release(eye);
    }
    submitted = &views_;
  }
  app_->end_frame(fs.predictedDisplayTime, submitted ? *submitted : std::vector<XrView>{});
}

void Session::count(const XrFrameState& fs, double frame_ms, double select_ms, const FrameDecisions& d,
                    const FrameDiagnostics& diag) {
  const std::int64_t t_ns = fs.predictedDisplayTime - time_base_;
  const double t_s = static_cast<double>(t_ns) * 1e-9;
  FrameRecordInput in;
  in.chains = &chains_;
  in.objects = objects_;
  in.radii = radii_;
  in.decisions = &d;
  in.diagnostics = &diag;
  in.head = simulator_.head_at(t_ns);
  in.fov = scenario_.display.views[0].fov;
  in.triangles_full = triangles_full_;
  in.lod_map = opt_.lod_map;
  FrameRecord r = record_frame(in);
  r.index = static_cast<std::int64_t>(frames_.size());
  r.t_s = t_s;
  r.frame_ms = frame_ms;
  r.select_ms = select_ms;
  r.cluster_triangles_drawn = clusters_.triangles_of(d.cluster_drawn);
  r.cluster_triangles_perceptual = clusters_.triangles_of(diag.cluster_drawn_perceptual);
  r.cluster_triangles_full = clusters_.full_triangles;
  // Eye-in-head movement: head turns are not saccades.
  r.saccade = saccades_.update(d.gaze_valid, diag.gaze_direction_head, t_s);
  audit_->frame(simulator_, t_ns, t_s, d, diag, in.head, r);
  if (decisions_) decisions_->write(r.index, t_ns, d.lod);
  if (cluster_decisions_) cluster_decisions_->write(r.index, t_ns, d);
  if (opt_.frame_observer) opt_.frame_observer(d, diag);
  const std::uint64_t cluster_triangles = r.cluster_triangles_drawn;
  frames_.push_back(std::move(r));
  progress_line(cluster_triangles);
}

void Session::progress_line(std::uint64_t cluster_triangles) {
  if (opt_.quiet || (ms_since(last_progress_) <= 1000.0 && static_cast<std::int64_t>(frames_.size()) != planned_))
    return;
  last_progress_ = Clock::now();
  io_.err << "gazelod run: frame " << frames_.size() << "/" << planned_ << " ("
          << (100 * static_cast<std::int64_t>(frames_.size())) / std::max<std::int64_t>(planned_, 1) << "%), "
          << static_cast<int>(ms_since(started_) / 1000.0) << " s elapsed";
  if (!clusters_.empty())
    io_.err << ", cluster triangles " << cluster_triangles << " of " << clusters_.full_triangles << " ("
            << (100 * cluster_triangles) / std::max<std::uint64_t>(clusters_.full_triangles, 1) << "%)";
  io_.err << "\n";
}

// The summary printed and returned, the report files and the decisions files committed.
int Session::finish() {
  drain_thread_log();
  RunInfo info;
  info.scenario = prepared_.label;
  info.hmd = opt_.hmd.empty() ? scenario_.display.name : opt_.hmd;
  info.runtime = app_->runtime_name();
  info.device = opt_.render ? app_->vk_device_name() : "none (--no-render)";
  info.criteria = criteria_text(opt_.criteria);
  info.budget_ms = opt_.budget_ms;
  RunSummary summary = summarize(frames_, opt_.budget_ms);
  summary.lod_map_evaluated = opt_.lod_map;
  if (interrupted_by_ != 0) summary.interrupted = StopOnSignal::name(interrupted_by_);
  summary.gaze_bad_samples = plugin_->diagnostics().gaze_bad_samples;
  summary.clusters.meshes = clusters_.meshes.size();
  summary.clusters.clusters = clusters_.cluster_count();
  for (const ClusterMesh& m : clusters_.meshes)
    for (std::uint8_t depth : m.primitive->hierarchy.depth) summary.clusters.leaves += depth == 0 ? 1 : 0;
  if (renderer_) summary.clusters.gpu = renderer_->gpu_summary();
  // The offline optimum takes about a second per million object-frames kept: say so first.
  if (!opt_.quiet && audit_->kept_object_frames() >= (std::size_t{1} << 20))
    io_.err << "gazelod run: the offline optimum over " << audit_->kept_object_frames() << " object-frames\n"
            << std::flush;
  audit_->finish(summary, !opt_.trace_path.empty()  ? "no ground truth: the gaze is a replayed trace"
                          : opt_.hid_gaze           ? "no ground truth: the gaze is a HID eye tracker"
                          : !audit_->ground_truth() ? "no ground truth: not the simulated runtime"
                                                    : "switched off with --no-audit");
  if (source_changes_unshown_ > 0)
    io_.err << "gazelod run: the gaze source changed " << source_changes_unshown_ << " more time"
            << (source_changes_unshown_ == 1 ? "" : "s") << " (frames.csv has each frame's source)\n";
  print_summary(info, summary, io_.out, opt_.breakdown);
  if (opt_.result != nullptr) *opt_.result = summary;
  if (opt_.frames_result != nullptr) *opt_.frames_result = frames_;
  if (opt_.write_reports) {
    write_report_files(opt_.out_dir, info, summary, frames_);
    // An earlier run's picture must not pass for this run's (a --no-render run, a capture frame
    // past the end). Removed only now, with this run's report complete: a run that fails keeps
    // the earlier report whole. A link goes, not what it points to.
    if (!png_saved_) {
      std::error_code ec;
      const std::filesystem::path png = opt_.out_dir / "frame.png";
      const auto st = std::filesystem::symlink_status(png, ec);
      if (!ec && (std::filesystem::is_regular_file(st) || std::filesystem::is_symlink(st)))
        std::filesystem::remove(png, ec);
    }
    io_.out << "files: " << (opt_.out_dir / "summary.json").string() << ", frames.csv, frames.svg"
            << (summary.audit.available ? ", audit.svg" : "") << (png_saved_ ? ", frame.png" : "");
  }
  if (frames_.empty()) {
    io_.out << "\n";
    io_.err << "gazelod run: the session ended before any frame was rendered\n";
    return 1;
  }
  if (decisions_) {
    decisions_->commit();
    io_.out << ", " << decisions_->path().string();
  }
  if (cluster_decisions_) {
    cluster_decisions_->commit();
    io_.out << ", " << cluster_decisions_->path();
  }
  io_.out << "\n";
  if (opt_.render && !png_saved_)
    io_.err << "gazelod run: no frame.png: --capture-frame " << capture_ << " is past the run's last frame ("
            << frames_.size() << " frames)\n";
  // The shell's convention for a run a signal ended: 128 + its number.
  return interrupted_by_ != 0 ? 128 + interrupted_by_ : 0;
}

}  // namespace run_steps

EnabledCriteria parse_criteria(const std::string& text) {
  EnabledCriteria c{false, false, false};
  if (text.empty())
    throw UsageError("--criteria: empty (use all, none or a comma list of size, eccentricity, velocity)");
  if (text == "none") return c;
  if (text == "all") return EnabledCriteria{};
  // getline drops a trailing empty item ("size,"): split by hand so it is seen.
  std::vector<std::string> items(1);
  for (char ch : text) {
    if (ch == ',')
      items.emplace_back();
    else
      items.back().push_back(ch);
  }
  for (const std::string& item : items) {
    bool* flag = item == "size"           ? &c.size
                 : item == "eccentricity" ? &c.eccentricity
                 : item == "velocity"     ? &c.velocity
                                          : nullptr;
    if (flag && *flag) throw UsageError("--criteria: '" + item + "' twice in '" + text + "'");
    if (flag)
      *flag = true;
    else if (item.empty())
      throw UsageError("--criteria: an empty item in '" + text + "'");
    else
      throw UsageError("--criteria: unknown criterion '" + item +
                       "' (use all, none or a comma list of size, eccentricity, velocity)");
  }
  return c;
}

int run_session(const RunOptions& opt, Io io) {
  run_steps::Session session(opt, io);
  return session.run();
}

RunSummary run_for_summary(RunOptions options, const std::string& what) {
  RunSummary summary;
  options.result = &summary;
  options.quiet = true;
  std::ostringstream out, err;
  const int rc = run_session(options, Io{out, err});
  if (rc != 0) {
    std::string msg = err.str();
    while (!msg.empty() && msg.back() == '\n') msg.pop_back();
    throw UsageError(what + " failed (exit " + std::to_string(rc) + "): " + msg, rc);
  }
  return summary;
}

}  // namespace gazelod::cli
