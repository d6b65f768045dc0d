// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/session.hpp"

#include "apps/gazelod/run/signals.hpp"

#include "gaze/hid/hid_gaze_source.hpp"
#include "lod/angles.hpp"

#include "apps/gazelod/eval/lod_map_frame.hpp"
#include "apps/gazelod/run/audit.hpp"
#include "apps/gazelod/clusters/audit.hpp"
#include "apps/gazelod/clusters/decisions.hpp"
#include "apps/gazelod/clusters/scene.hpp"
#include "apps/gazelod/run/render.hpp"
#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/run/scenario.hpp"
#include "apps/xr_host/xr_app.hpp"
#include "render/lod_palette.hpp"
#include "sim/simulator.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace gazelod::cli {
namespace {

using Clock = std::chrono::steady_clock;

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

std::uint64_t triangles(const std::vector<std::vector<lod::LodLevel>>& chains, std::span<const std::uint8_t> lods) {
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < chains.size() && i < lods.size(); ++i)
    n += chains[i][std::min<std::size_t>(lods[i], chains[i].size() - 1)].triangles;
  return n;
}

// Saccade onsets for the plot: the gaze turning faster than 100 deg/s between two frames
// after a frame that did not (a frame-rate I-VT; the trace tools classify properly).
class SaccadeMarker {
 public:
  bool update(bool valid, const glm::dvec3& dir_head, double t_s) {
    bool onset = false;
    if (valid && have_ && t_s > t_s_) {
      const double angle = std::atan2(glm::length(glm::cross(prev_, dir_head)), glm::dot(prev_, dir_head));
      const bool fast = angle * lod::kDegPerRad / (t_s - t_s_) > 100.0;
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

}  // namespace

int run_session(const RunOptions& opt, Io io) {
  // The scenario: the runtime serves it; this process also steps it for object motion.
  const PreparedScenario prepared = prepare_scenario(opt);
  // Routine notes (what the preparation did) only without --quiet; warnings always.
  if (!opt.quiet)
    for (const std::string& note : prepared.notes) io.err << "gazelod run: " << note << "\n";
  sim::Simulator simulator(prepared.scenario);
  const sim::Scenario& scenario = simulator.scenario();
  if (opt.runtime == "sim")
    point_loader_at_simulator(prepared, opt);
  else if (opt.runtime != "system")
    throw UsageError("--runtime: must be 'sim' or 'system', got '" + opt.runtime + "'");
  // --scene with cluster hierarchies: those objects are cluster meshes (clusters/scene.hpp);
  // the plugin's objects are the others, plain[k] being plugin object k's scenario index.
  const ClusterScene clusters =
      prepared.baked ? make_cluster_scene(*prepared.baked, prepared.scene_shift_m, scenario) : ClusterScene{};
  for (const std::string& note : clusters.notes) io.err << "gazelod run: --scene: " << note << "\n";
  std::vector<std::size_t> plain;
  std::vector<int> plugin_id(scenario.objects.size(), -1);
  for (std::size_t i = 0; i < scenario.objects.size(); ++i) {
    if (i < clusters.drawn_as_clusters.size() && clusters.drawn_as_clusters[i]) continue;
    plugin_id[i] = static_cast<int>(plain.size());
    plain.push_back(i);
  }
  // Opened before the session so that a bad path fails at once; committed (renamed into place)
  // only after the last frame.
  // A decisions file must not replace one of the report's files (or the other decisions file).
  const auto same_file = [](const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code e1, e2;
    return std::filesystem::weakly_canonical(a, e1) == std::filesystem::weakly_canonical(b, e2) && !e1 && !e2;
  };
  for (const auto& [path, option] :
       {std::pair{opt.decisions_path, "--decisions"}, std::pair{opt.cluster_decisions_path, "--cluster-decisions"}}) {
    if (path.empty()) continue;
    for (const char* report : {"summary.json", "frames.csv", "frames.svg", "audit.svg", "frame.png", "scenario.json"})
      if (same_file(path, opt.out_dir / report))
        throw UsageError(std::string(option) + ": '" + path + "' is the run's " + report +
                         " (in --out); write the decisions to another file");
  }
  if (!opt.decisions_path.empty() && same_file(opt.decisions_path, opt.cluster_decisions_path))
    throw UsageError("--cluster-decisions: the same file as --decisions");
  std::optional<DecisionsFile> decisions;
  if (!opt.decisions_path.empty()) {
    std::vector<std::string> names;
    for (std::size_t i : plain) names.push_back(scenario.objects[i].name);
    decisions.emplace(opt.decisions_path, names);
  }
  std::optional<ClusterDecisionsFile> cluster_decisions;
  if (!opt.cluster_decisions_path.empty()) {
    if (clusters.empty())
      throw UsageError(
          "--cluster-decisions: the scene has no cluster meshes (--scene with a file from "
          "gazelod bake --clusters)");
    cluster_decisions.emplace(opt.cluster_decisions_path, clusters);
  }

  std::optional<xr_host::XrApp> app;
  try {
    app.emplace(opt.eye_gaze);
  } catch (const xr_host::XrAppError& e) {
    io.err << "gazelod run: " << e.what() << "\n";
    return 1;
  }

  PluginConfig config;
  // --trace: the trace is the gaze source for the whole run (from the first frame on; the
  // runtime's own gaze is not used), and the source-change lines say when it ends.
  config.use_openxr_eye_gaze = opt.eye_gaze && app->eye_gaze_enabled() && opt.trace_path.empty() && !opt.hid_gaze;
  config.criteria = opt.criteria;
  config.compute_breakdown = true;
  config.budget_ms = opt.budget_ms;
  // One accuracy for every source (the plugin's defaults differ per source), so runs that get the
  // same gaze through different sources can be compared (tests/layer).
  if (opt.gaze_error_deg > 0.0) config.openxr_gaze_error_deg = config.external_gaze_error_deg = opt.gaze_error_deg;
  // Plan with a margin: the cost fit is unbiased, so without one about half the frames would
  // land above their prediction.
  config.budget.headroom = 0.15;
  config.hmd_override = opt.hmd;
  if (opt.switching) config.switching = *opt.switching;
  if (opt.conditioning) config.conditioning = *opt.conditioning;
  const std::shared_ptr<TraceFromFirstFrame> trace = make_external_source(opt);
  config.external_source = trace;
  if (opt.hid_gaze) {
    // The first HID eye tracker, its samples mapped onto the runtime's clock. No tracker (or
    // one unplugged later): the source says so and the plugin falls back to head-fixed gaze.
    if (app->now() == 0) {
      io.err << "gazelod run: --gaze hid needs XR_KHR_convert_timespec_time (the runtime's clock), which this runtime "
                "does not offer\n";
      return 2;
    }
    gaze::hid::HidTrackerConfig hid;
    const xr_host::XrApp* host = &*app;
    hid.host_now_ns = [host] { return static_cast<std::int64_t>(host->now()); };
    hid.log = [&io, &opt](const std::string& line) {
      if (!opt.quiet) io.err << line << "\n";  // already "gazelod hid: ..."
    };
    config.external_source = std::make_shared<gaze::hid::HidGazeSource>(std::move(hid));
  }
  auto plugin = LodPlugin::create(xrGetInstanceProcAddr, app->instance(), app->system(), app->session(),
                                  app->local_space(), config);
  // Source changes: the first few said as they happen, the rest (every blink is one) counted
  // and summarised at the end; none once the session winds down, when the eye-gaze action goes
  // inactive by design (that was a false alarm at the end of every run).
  constexpr int kSourceLinesShown = 8;
  int source_changes = 0, source_changes_unshown = 0;
  bool session_ending = false;
  plugin->on_source_changed([&](GazeSourceKind now, const std::string& why) {
    if (session_ending || opt.quiet) return;
    if (++source_changes > kSourceLinesShown) {
      ++source_changes_unshown;
      return;
    }
    io.err << "gazelod run: gaze source " << to_string(now) << ": " << why << "\n";
    if (source_changes == kSourceLinesShown)
      io.err << "gazelod run: (further gaze source changes, blinks among them, are counted: the per-frame source "
                "is in frames.csv)\n";
  });
  std::vector<std::vector<lod::LodLevel>> chains;
  std::vector<double> radii;
  for (std::size_t i : plain) {
    const sim::SceneObject& o = scenario.objects[i];
    ObjectDesc d;
    d.center_m = o.position_m;
    d.radius_m = o.radius_m;
    d.velocity_m_s = o.velocity_m_s;
    d.lods = o.lods;
    d.importance = o.importance;
    plugin->add_object(d);
    chains.push_back(o.lods);
    radii.push_back(o.radius_m);
  }
  register_cluster_meshes(clusters, *plugin);

  const std::vector<std::uint8_t> full_detail(chains.size(), 0);
  const std::uint64_t triangles_full = triangles(chains, full_detail);
  std::optional<RunRenderer> renderer;
  // --scene objects are drawn with their levels' own triangles (the scenario's objects are the
  // baked file's, in order); generated objects as stand-in spheres.
  std::vector<const bake::BakedObject*> baked_of_plain;
  if (prepared.baked)
    for (std::size_t i : plain)
      baked_of_plain.push_back(i < prepared.baked->objects.size() ? &prepared.baked->objects[i] : nullptr);
  if (opt.render) renderer.emplace(*app, chains, clusters.empty() ? nullptr : &clusters, baked_of_plain);
  // frame.png's colour key: every level an object has, or every tint when cluster depths are drawn.
  std::uint32_t key_levels = clusters.empty() ? 1u : static_cast<std::uint32_t>(render::kLodPaletteSize);
  for (const auto& c : chains) key_levels = std::max(key_levels, static_cast<std::uint32_t>(c.size()));

  const double rate = scenario.frame_rate_hz > 0 ? scenario.frame_rate_hz : 90.0;
  const std::int64_t planned =
      opt.frames > 0 ? opt.frames : static_cast<std::int64_t>(std::llround(scenario.duration_s * rate));
  const std::int64_t capture = opt.capture_frame >= 0 ? opt.capture_frame : planned / 2;
  // A trace shorter than the run: past its end the gaze falls back to head-fixed (and says so
  // then); say it before, with the way to bound the run.
  if (trace && trace->duration_s() + 1.0 / rate < static_cast<double>(planned) / rate) {
    const auto covered = static_cast<std::int64_t>(trace->duration_s() * rate) + 1;
    char line[256];
    std::snprintf(line, sizeof line,
                  "gazelod run: --trace: the trace lasts %.2f s, the run %.2f s: frames after %lld fall back to "
                  "head-fixed gaze (--frames %lld stops with the trace)\n",
                  trace->duration_s(), static_cast<double>(planned) / rate, static_cast<long long>(covered),
                  static_cast<long long>(covered));
    io.err << line;
  }
  std::vector<FrameRecord> frames;
  // Every frame keeps a record for the report: say so before a run that will hold gigabytes
  // (a scenario of hours at 1 kHz), and reserve at most 65,536 up front (a reserve of
  // the whole plan failed with std::bad_alloc before the first frame).
  const double record_gb = static_cast<double>(planned) * static_cast<double>(sizeof(FrameRecord) + 32) / 1e9;
  if (record_gb > 2.0)
    io.err << "gazelod run: " << planned << " frames will keep about " << static_cast<int>(record_gb + 0.5)
           << " GB of per-frame records for the report; bound the run with --frames\n";
  frames.reserve(static_cast<std::size_t>(std::min<std::int64_t>(planned, 1 << 16)));
  std::vector<glm::dvec3> positions(plain.size());
  std::vector<sim::ObjectState> objects(plain.size());  // the plugin's objects, from the simulator
  std::vector<XrView> views;
  SaccadeMarker saccades;
  XrTime time_base = 0;
  // The audit needs the simulator's truth on the runtime's clock: gazelod's simulated runtime.
  bool ground_truth = false;
  std::optional<AuditOracle> oracle;
  std::optional<ClusterAuditOracle> cluster_oracle;
  ClusterMotion cluster_motion(clusters);
  bool layout_checked = clusters.empty();
  std::vector<std::uint8_t> previous_lod(chains.size(), 0), previous_oracle(chains.size(), 0);
  AuditBreakdown breakdown;  // summed frame by frame (not kept per frame)
  double previous_t_s = 0.0;
  bool exit_requested = false;
  bool png_saved = false;  // --capture-frame past the last frame saves none
  StopOnSignal stop;       // Ctrl-C / SIGTERM: stop at a frame boundary with a report
  int interrupted_by = 0;
  auto last_progress = Clock::now();
  const auto started = Clock::now();

  for (;;) {
    const bool keep_going = app->poll_events([&](XrSessionState s, XrTime t) {
      if (s == XR_SESSION_STATE_STOPPING || s == XR_SESSION_STATE_EXITING || s == XR_SESSION_STATE_LOSS_PENDING)
        session_ending = true;
      plugin->on_session_state(s, t);
      if (s == XR_SESSION_STATE_LOSS_PENDING)  // never end silently: say why the run stops
        io.err << "gazelod run: the runtime is losing the session (XR_SESSION_STATE_LOSS_PENDING); ending after "
               << frames.size() << " frames\n";
    });
    if (!keep_going) break;
    if (interrupted_by == 0 && stop.requested() != 0) {
      interrupted_by = stop.requested();
      stop.acted_on();
      io.err << "gazelod run: " << StopOnSignal::name(interrupted_by) << " after " << frames.size()
             << " frames: ending the session and writing the report of those (again to quit at once)\n";
      if (!exit_requested && app->session_running()) xrRequestExitSession(app->session());
      exit_requested = true;
      session_ending = true;
      if (!app->session_running()) break;
    }
    if (!app->session_running()) continue;
    if (static_cast<std::int64_t>(frames.size()) >= planned && !exit_requested) {
      xrRequestExitSession(app->session());
      exit_requested = true;
      session_ending = true;
    }

    const XrFrameState fs = app->wait_frame();
    const auto t0 = Clock::now();
    app->begin_frame();
    if (time_base == 0) {
      time_base = app->scenario_time_base();
      // A replayed trace is not the simulator's eye: no ground truth to hold it against.
      ground_truth = opt.runtime == "sim" && time_base != 0 && opt.trace_path.empty() && !opt.hid_gaze;
      if (ground_truth && opt.audit) oracle.emplace(scenario, opt.criteria, plain);
      try {
        if (oracle && !clusters.empty()) cluster_oracle.emplace(clusters);
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--scene: ") + e.what());
      }
      if (time_base == 0) time_base = fs.predictedDisplayTime - fs.predictedDisplayPeriod;
      if (trace && prepared.trace_head) trace->start_at(time_base);  // where the replayed head starts
    }
    const double t_s = static_cast<double>(fs.predictedDisplayTime - time_base) * 1e-9;
    const auto all_objects = simulator.objects_at(fs.predictedDisplayTime - time_base);
    for (std::size_t k = 0; k < plain.size() && plain[k] < all_objects.size(); ++k) {
      objects[k] = all_objects[plain[k]];
      plugin->set_object_motion(static_cast<std::uint32_t>(k), objects[k].position_m, objects[k].velocity_m_s);
      positions[k] = objects[k].position_m;
    }
    for (std::size_t k : cluster_motion.update(scenario, all_objects)) {
      plugin->set_cluster_mesh_motion(static_cast<std::uint32_t>(k), cluster_motion.pose(k),
                                      cluster_motion.velocity_m_s(k));
      if (cluster_oracle) cluster_oracle->set_pose(k, cluster_motion.pose(k), cluster_motion.velocity_m_s(k));
    }
    const FrameDecisions& d = plugin->begin_frame(fs.predictedDisplayTime);
    const FrameDiagnostics& diag = plugin->diagnostics();
    const double select_ms = ms_since(t0);
    if (!layout_checked && !same_cluster_layout(clusters, d.cluster_first)) {
      io.err << "gazelod run: the plugin laid out the cluster meshes otherwise than they were registered\n";
      return 1;
    }
    layout_checked = true;

    std::vector<XrView>* submitted = nullptr;
    const bool counting = !exit_requested && static_cast<std::int64_t>(frames.size()) < planned;
    if (fs.shouldRender && app->locate_views(fs.predictedDisplayTime, views)) {
      if (renderer) {
        const bool save = counting && static_cast<std::int64_t>(frames.size()) == capture;
        for (std::size_t eye = 0; eye < views.size(); ++eye) {
          const std::uint32_t index = app->acquire(eye);
          renderer->render_eye(eye, index, views[eye], positions, radii, d, diag, cluster_motion.shift_m());
          if (save && eye == 0) {
            renderer->save_png(eye, index, opt.out_dir / "frame.png", key_levels);
            png_saved = true;
          }
          app->release(eye);
        }
        submitted = &views;
      }
    }
    app->end_frame(fs.predictedDisplayTime, submitted ? *submitted : std::vector<XrView>{});
    const double frame_ms = ms_since(t0);
    plugin->end_frame(frame_ms);
    if (!counting) continue;

    FrameRecord r;
    r.index = static_cast<std::int64_t>(frames.size());
    r.t_s = t_s;
    r.frame_ms = frame_ms;
    r.select_ms = select_ms;
    r.predicted_ms = diag.predicted_ms;
    r.triangles_drawn = triangles(chains, d.lod);
    r.triangles_perceptual = triangles(chains, diag.lod_perceptual);
    r.triangles_full = triangles_full;
    r.triangles_size_only = triangles(chains, diag.lod_size_only);
    r.triangles_size_eccentricity = triangles(chains, diag.lod_size_eccentricity);
    r.triangles_size_velocity = triangles(chains, diag.lod_size_velocity);
    for (std::uint8_t l : d.lod) ++r.lod_histogram[l];
    r.cluster_triangles_drawn = clusters.triangles_of(d.cluster_drawn);
    r.cluster_triangles_perceptual = clusters.triangles_of(diag.cluster_drawn_perceptual);
    r.cluster_triangles_full = clusters.full_triangles;
    r.objects = static_cast<std::int64_t>(chains.size());
    r.lod_sum_drawn = lod_sum(d.lod);
    r.lod_sum_size_only = lod_sum(diag.lod_size_only);
    r.lod_sum_size_eccentricity = lod_sum(diag.lod_size_eccentricity);
    r.lod_sum_size_velocity = lod_sum(diag.lod_size_velocity);
    const LodMapFrame lod_map = lod_map_frame(
        chains, objects, radii, diag, simulator.head_at(fs.predictedDisplayTime - time_base).linear_velocity_m_s);
    r.triangles_lod_map = lod_map.triangles;
    r.lod_sum_lod_map = lod_map.lod_sum;
    const sim::HeadState head = simulator.head_at(fs.predictedDisplayTime - time_base);
    const InViewFrame view = in_view_frame(chains, objects, radii, d, diag, lod_map.levels, head.position_m,
                                           head.orientation, scenario.display.views[0].fov);
    r.objects_in_view = view.objects;
    r.in_view_triangles = view.triangles;
    r.in_view_lod_sum = view.lod_sum;
    r.gaze_source = to_string(d.gaze_source);
    r.gaze_valid = d.gaze_valid;
    r.head_speed_dps = glm::length(diag.head_angular_velocity_rad_s) * lod::kDegPerRad;
    r.eye_motion = diag.gaze_carried ? "carried" : gaze::to_string(diag.eye_motion);
    r.plugin_suppressed = diag.gaze_suppressed;
    r.gaze_error_deg = diag.gaze_error_deg;
    // Eye-in-head movement: head turns are not saccades.
    r.saccade = saccades.update(d.gaze_valid, diag.gaze_direction_head, t_s);
    // The audit reads the simulator only (never the plugin's inputs): the oracle at the true gaze.
    const std::int64_t t_ns = fs.predictedDisplayTime - time_base;
    const bool first = frames.empty();
    if (oracle && oracle->evaluate(simulator, t_ns, diag.xi_cpd).empty()) {
      AuditFrameInput in;
      in.chains = &chains;
      in.drawn = d.lod;
      if (!first) in.previous = previous_lod, in.previous_oracle = previous_oracle;
      in.oracle = oracle->levels();
      in.in_view = oracle->in_view();
      in.suppressed = oracle->suppressed();
      // The truth names a scenario object; the audit counts plugin objects (-1: a cluster mesh).
      const int pursued = oracle->truth().pursuit_object;
      const bool known = pursued >= 0 && static_cast<std::size_t>(pursued) < plugin_id.size();
      in.pursuit_object = known ? plugin_id[static_cast<std::size_t>(pursued)] : -1;
      in.frame_s = first ? 0.0 : t_s - previous_t_s;
      r.audit = audit_frame(in);
      BreakdownFrameInput b;
      b.chains = &chains;
      b.drawn = d.lod;
      b.previous = in.previous;
      b.perceptual = diag.lod_perceptual;
      b.oracle = in.oracle;
      b.previous_oracle = in.previous_oracle;
      b.oracle_limited_by = oracle->limited_by();
      b.in_view = in.in_view;
      b.eccentricity_deg = oracle->eccentricity_deg();
      b.distance_m = oracle->distance_m();
      b.gaze = oracle->true_gaze();
      b.estimate = static_cast<std::uint8_t>(diag.eye_motion);
      b.frame_s = in.frame_s;
      add_breakdown_frame(b, breakdown);
      std::copy_n(in.oracle.begin(), std::min(in.oracle.size(), previous_oracle.size()), previous_oracle.begin());
      if (cluster_oracle)
        r.cluster_audit =
            cluster_oracle->audit(oracle->viewer(), head.position_m, head.orientation, scenario.display.views[0].fov,
                                  d.cluster_drawn, oracle->suppressed(), in.frame_s);
    }
    std::copy_n(d.lod.begin(), std::min(d.lod.size(), previous_lod.size()), previous_lod.begin());
    previous_t_s = t_s;
    if (decisions) decisions->write(r.index, t_ns, d.lod);
    if (cluster_decisions) cluster_decisions->write(r.index, t_ns, d);
    if (opt.frame_observer) opt.frame_observer(d, diag);
    const std::uint64_t frame_cluster_triangles = r.cluster_triangles_drawn;
    frames.push_back(std::move(r));

    if (!opt.quiet && (ms_since(last_progress) > 1000.0 || static_cast<std::int64_t>(frames.size()) == planned)) {
      last_progress = Clock::now();
      io.err << "gazelod run: frame " << frames.size() << "/" << planned << " ("
             << (100 * static_cast<std::int64_t>(frames.size())) / std::max<std::int64_t>(planned, 1) << "%), "
             << static_cast<int>(ms_since(started) / 1000.0) << " s elapsed";
      if (!clusters.empty())
        io.err << ", cluster triangles " << frame_cluster_triangles << " of " << clusters.full_triangles << " ("
               << (100 * frame_cluster_triangles) / std::max<std::uint64_t>(clusters.full_triangles, 1) << "%)";
      io.err << "\n";
    }
  }

  RunInfo info;
  info.scenario = prepared.label;
  info.hmd = opt.hmd.empty() ? scenario.display.name : opt.hmd;
  info.runtime = app->runtime_name();
  info.device = opt.render ? app->vk_device_name() : "none (--no-render)";
  info.criteria = criteria_text(opt.criteria);
  info.budget_ms = opt.budget_ms;
  RunSummary summary = summarize(frames, opt.budget_ms);
  if (interrupted_by != 0) summary.interrupted = StopOnSignal::name(interrupted_by);
  summary.gaze_bad_samples = plugin->diagnostics().gaze_bad_samples;
  summary.clusters.meshes = clusters.meshes.size();
  summary.clusters.clusters = clusters.cluster_count();
  for (const ClusterMesh& m : clusters.meshes)
    for (std::uint8_t depth : m.primitive->hierarchy.depth) summary.clusters.leaves += depth == 0 ? 1 : 0;
  if (summary.audit.available) summary.audit.breakdown = breakdown;
  if (!oracle) {
    summary.audit = AuditSummary{};
    summary.audit.reason = !opt.trace_path.empty() ? "no ground truth: the gaze is a replayed trace"
                           : opt.hid_gaze          ? "no ground truth: the gaze is a HID eye tracker"
                           : !ground_truth         ? "no ground truth: not the simulated runtime"
                                                   : "switched off with --no-audit";
  }
  if (source_changes_unshown > 0)
    io.err << "gazelod run: the gaze source changed " << source_changes_unshown << " more time"
           << (source_changes_unshown == 1 ? "" : "s") << " (frames.csv has each frame's source)\n";
  print_summary(info, summary, io.out, opt.breakdown);
  if (opt.result != nullptr) *opt.result = summary;
  if (opt.write_reports) {
    write_report_files(opt.out_dir, info, summary, frames);
    io.out << "files: " << (opt.out_dir / "summary.json").string() << ", frames.csv, frames.svg"
           << (summary.audit.available ? ", audit.svg" : "") << (png_saved ? ", frame.png" : "");
  }

  if (frames.empty()) {
    io.out << "\n";
    io.err << "gazelod run: the session ended before any frame was rendered\n";
    return 1;
  }
  if (decisions) {
    decisions->commit();
    io.out << ", " << decisions->path().string();
  }
  if (cluster_decisions) {
    cluster_decisions->commit();
    io.out << ", " << cluster_decisions->path();
  }
  io.out << "\n";
  if (opt.render && !png_saved)
    io.err << "gazelod run: no frame.png: --capture-frame " << capture << " is past the run's last frame ("
           << frames.size() << " frames)\n";
  // The shell's convention for a run a signal ended: 128 + its number.
  return interrupted_by != 0 ? 128 + interrupted_by : 0;
}

}  // namespace gazelod::cli
