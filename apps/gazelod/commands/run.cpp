// SPDX-License-Identifier: Apache-2.0
// gazelod run: the main job. One OpenXR session (gazelod's simulated runtime unless
// --runtime system), the plugin choosing every object's LOD each frame from head pose and eye
// gaze, each eye drawn with Vulkan, and a report (summary.json, frames.csv, frames.svg,
// audit.svg, frame.png) in --out, with a visibility audit against the simulator's true gaze.
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/run/session.hpp"

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

namespace gazelod::cli {
namespace {

const Registrar reg(
    "run", "Run an OpenXR session with gaze-contingent LOD and write a report", [](CLI::App& app) -> Action {
      auto opt = std::make_shared<RunOptions>();
      auto criteria = std::make_shared<std::string>("all");
      auto out = std::make_shared<std::string>("gazelod-out");
      auto no_render = std::make_shared<bool>(false);
      auto no_eye_gaze = std::make_shared<bool>(false);
      app.add_option("--scenario", opt->scenario_path, "Scenario JSON (default: the embedded scenario)");
      app.add_option(
          "--scene", opt->scene_path,
          "A .glb baked by `gazelod bake`: its objects and LOD chains (or cluster hierarchies) replace the scenario's");
      app.add_option(
          "--scene-placement", opt->scene_placement,
          "in-front (default: the scene moved 2 radii + 1 m before the viewer's start) or file (the glTF's own "
          "placement: glTF origin = LOCAL origin, +Y up)");
      app.add_option("--hmd", opt->hmd, "Display preset replacing the scenario's (see gazelod hmds)");
      app.add_option("--frames", opt->frames, "Frames to run (default: the scenario's duration)")
          ->check(CLI::Range(std::int64_t{1}, std::int64_t{10'000'000}));
      app.add_option("--criteria", *criteria, "all, none, or a comma list of size,eccentricity,velocity");
      app.add_option("--out", *out, "Folder for summary.json, frames.csv, frames.svg, frame.png");
      app.add_option("--runtime", opt->runtime,
                     "sim (gazelod's simulated runtime) or system (the active OpenXR runtime)");
      app.add_option("--budget-ms", opt->budget_ms, "Frame-time budget to report against (ms)")
          ->check(CLI::Range(0.0, 1000.0));
      app.add_option("--gaze-error-deg", opt->gaze_error_deg,
                     "Gaze error (accuracy) assumed for every gaze source, degrees (default: 1.5 for the runtime's eye "
                     "gaze, 2.0 for --trace and --gaze hid)")
          ->check(CLI::Range(0.01, 20.0));
      app.add_flag("--paced", opt->paced, "Run at the display rate instead of as fast as possible");
      app.add_flag("--no-render", *no_render, "Select LODs only; draw nothing");
      app.add_flag("--no-eye-gaze", *no_eye_gaze, "Ignore the runtime's eye gaze (head-fixed fallback)");
      app.add_option("--trace", opt->trace_path, "Replay this gazelod gaze trace as the gaze source");
      auto trace_head = std::make_shared<std::string>("recorded");
      app.add_option("--trace-head", *trace_head,
                     "With a trace that has head poses: recorded (default: the head moves as recorded, relative to "
                     "its first pose, in place of the scenario's head effects) or scenario (the scenario's head)");
      auto gaze_source = std::make_shared<std::string>();
      app.add_option("--gaze", *gaze_source,
                     "Gaze source for the whole run: runtime (default), hid (the first HID eye tracker) or trace:FILE");
      // Not given: the middle frame. A negative frame is refused (-7 meant the middle one).
      app.add_option("--capture-frame", opt->capture_frame, "Frame saved as frame.png (default: the middle one)")
          ->check(non_negative_integer());
      app.add_flag("--quiet", opt->quiet, "No progress lines");
      app.add_flag(
          "--breakdown", opt->breakdown,
          "Print where the audit's figures come from: by true gaze state, object class and the oracle's criterion, "
          "and the offline optimum (the fewest triangles at the policy's switches, the run's future known)");
      app.add_flag("--lod-map", opt->lod_map,
                   "Also evaluate the LOD-map thesis's policy each frame (summary.json \"lod_map\"; nothing it picks "
                   "is drawn)");
      app.add_option("--decisions", opt->decisions_path,
                     "Write the drawn level of every object in every frame to this CSV (frame,t_ns,<object>...)");
      app.add_option("--cluster-decisions", opt->cluster_decisions_path,
                     "Write every frame's drawn cut of the cluster meshes to this CSV, one row per drawn cluster "
                     "(frame,t_ns,mesh,cluster,depth,triangles,limited_by,held)");
      app.add_option("--cluster-select", opt->cluster_select,
                     "Where the cluster meshes' cut is selected: cpu (default: the plugin's cut, with its switch "
                     "policy, drawn cluster by cluster) or gpu (the compute shader selects it from the plugin's viewer "
                     "and one indirect-count draw per eye draws it; checked against the plugin's cut each frame)")
          ->check(CLI::IsMember({"cpu", "gpu"}));
      auto no_audit = std::make_shared<bool>(false);
      app.add_flag("--no-audit", *no_audit, "Skip the visibility audit against the simulator's true gaze");
      return [=, &app](Io io) {
        // CLI11's range check lets NaN through (every comparison with it is false).
        if (!std::isfinite(opt->budget_ms)) throw UsageError("--budget-ms: must be a number in [0, 1000], got nan");
        if (!std::isfinite(opt->gaze_error_deg))
          throw UsageError("--gaze-error-deg: must be a number in [0.01, 20], got nan");
        if (app.count("--hmd") > 0 && opt->hmd.empty()) throw UsageError("--hmd: empty (see gazelod hmds)");
        // Its value is checked with the scene (prepare_scenario).
        if (app.count("--scene-placement") > 0 && opt->scene_path.empty())
          throw UsageError("--scene-placement: needs --scene");
        RunOptions o = *opt;
        if (*gaze_source == "hid") {
          o.hid_gaze = true;
        } else if (gaze_source->rfind("trace:", 0) == 0 && gaze_source->size() > 6) {
          if (!o.trace_path.empty() && o.trace_path != gaze_source->substr(6))
            throw UsageError("--gaze trace:" + gaze_source->substr(6) + " and --trace " + o.trace_path +
                             ": two traces; give one");
          o.trace_path = gaze_source->substr(6);
        } else if (!gaze_source->empty() && *gaze_source != "runtime") {
          throw UsageError("--gaze: '" + *gaze_source + "' (use runtime, hid or trace:FILE)");
        }
        if (o.hid_gaze && !o.trace_path.empty()) throw UsageError("--gaze hid and --trace: choose one gaze source");
        // --gaze runtime said the runtime's eye gaze, and the trace won without a word.
        if (*gaze_source == "runtime" && !o.trace_path.empty())
          throw UsageError("--gaze runtime and --trace: choose one gaze source");
        if (*trace_head != "recorded" && *trace_head != "scenario")
          throw UsageError("--trace-head: '" + *trace_head + "' (use recorded or scenario)");
        if (app.count("--trace-head") > 0 && o.trace_path.empty()) throw UsageError("--trace-head: needs --trace");
        if (app.count("--trace-head") > 0 && o.runtime != "sim")
          throw UsageError("--trace-head: only with the simulated runtime (another runtime moves the head itself)");
        o.trace_head = *trace_head == "recorded";
        o.criteria = parse_criteria(*criteria);
        o.out_dir = *out;
        o.render = !*no_render;
        o.eye_gaze = !*no_eye_gaze;
        o.audit = !*no_audit;
        return run_session(o, io);
      };
    });

}  // namespace
}  // namespace gazelod::cli
