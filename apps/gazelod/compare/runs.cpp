// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/compare/runs.hpp"

#include "apps/gazelod/run/session.hpp"
#include "lod/acuity.hpp"
#include "lod/display.hpp"

namespace gazelod::cli {

void check_hmd(const std::string& hmd) {
  const lod::DisplaySpec* d = lod::find_display_preset(hmd);
  if (d == nullptr) throw UsageError("--hmd: unknown display preset '" + hmd + "' (see gazelod hmds)");
  // What the run's scenario loader requires of a display, said before any run (a one-view
  // preset failed after the presets before it had run, leaving their folders).
  if (d->view_count != 2)
    throw UsageError("--hmd: the preset '" + hmd + "' has " + std::to_string(d->view_count) +
                     " view; a run needs a display with 2 (an HMD, not a desktop)");
}

HmdComparison comparison_from_run(const std::string& hmd, const RunSummary& run) {
  check_hmd(hmd);
  HmdComparison c;
  c.hmd = hmd;
  const lod::DisplaySpec& display = *lod::find_display_preset(hmd);
  c.xi_cpd = lod::xi_cpd(display);
  c.eccentricity_threshold_deg = lod::eccentricity_threshold_deg(c.xi_cpd);
  c.velocity_threshold_dps = lod::velocity_threshold_dps(c.xi_cpd);
  c.frames = run.frames;
  c.eye_tracker = display.eye_tracking_hz > 0.0;
  c.gaze_valid_share =
      run.frames > 0 ? static_cast<double>(run.gaze_valid_frames) / static_cast<double>(run.frames) : 0.0;
  const auto set = [](const SetTotals& t) { return SetResult{t.triangles, t.average_lod}; };
  c.sets = {set(run.set_none), set(run.set_size), set(run.set_size_eccentricity), set(run.set_size_velocity),
            set(run.set_drawn)};
  c.lod_map = set(run.set_lod_map);
  c.shares = run.shares;
  c.audit = run.audit;
  return c;
}

HmdComparison run_comparison(const std::string& hmd, const CompareOptions& o) {
  check_hmd(hmd);
  RunOptions run;
  run.hmd = hmd;
  run.criteria = EnabledCriteria{};  // every criterion: the sets are the plugin's breakdown of it
  run.out_dir = o.out_dir / hmd;
  run.scenario_path = o.scenario_path;
  run.frames = o.frames;
  run.render = o.render;
  run.lod_map = true;
  return comparison_from_run(hmd, run_for_summary(run, "run for --hmd " + hmd));
}

}  // namespace gazelod::cli
