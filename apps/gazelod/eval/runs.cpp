// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/runs.hpp"
#include "auxiliary/atomic_file.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/run/session.hpp"

#include <fstream>
#include <vector>

namespace gazelod::cli {

EvalRun eval_run(const ReddyScenario& scenario, const std::string& criteria, bool render,
                 const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  // The scenario goes to a file because the simulated runtime, loaded by the OpenXR loader,
  // reads it from one; the run itself is a function call. Not scenario.json: that is the run's
  // own record of the scenario as run, which it may not write over its input.
  const auto scenario_path = dir / "reddy.json";
  try {
    aux::write_file_atomic(scenario_path.string(), reddy_scenario_json(scenario));
  } catch (const aux::WriteError& e) {
    throw UsageError(e.what(), 1);
  }
  RunOptions o;
  o.scenario_path = scenario_path.string();
  o.criteria = parse_criteria(criteria);
  o.out_dir = dir;
  o.render = render;
  o.lod_map = true;
  const RunSummary s = run_for_summary(o, "gazelod run on " + scenario_path.string());
  if (s.frames <= 0) throw UsageError(scenario_path.string() + ": the run had no frames", 1);
  const double frames = static_cast<double>(s.frames);
  EvalRun r;
  r.mean_frame_ms = s.mean_frame_ms;
  r.frame_rate_hz = r.mean_frame_ms > 0.0 ? 1000.0 / r.mean_frame_ms : 0.0;
  // Objects in the view frustum only: what Reddy 1998's renderer drew and averaged over
  // (RunSummary::in_view: none, size, size+eccentricity, size+velocity, drawn, lod map).
  const auto& v = s.in_view;
  r.objects_in_view = s.objects_in_view_mean;
  r.triangles_per_frame = static_cast<double>(v[4].triangles) / frames;
  r.full_triangles_per_frame = static_cast<double>(v[0].triangles) / frames;
  r.lod_drawn = 1.0 + v[4].average_lod;
  r.lod_size = 1.0 + v[1].average_lod;
  r.lod_size_ecc = 1.0 + v[2].average_lod;
  r.lod_size_vel = 1.0 + v[3].average_lod;
  r.lod_map = 1.0 + v[5].average_lod;
  r.triangles_size = static_cast<double>(v[1].triangles) / frames;
  r.triangles_size_ecc = static_cast<double>(v[2].triangles) / frames;
  r.triangles_size_vel = static_cast<double>(v[3].triangles) / frames;
  r.triangles_map = static_cast<double>(v[5].triangles) / frames;
  r.shares = s.in_view_shares;
  return r;
}

EvalRun mean_of(const std::vector<EvalRun>& runs) {
  EvalRun m;
  if (runs.empty()) return m;
  m = EvalRun{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, {}, 0};
  const double n = static_cast<double>(runs.size());
  for (const EvalRun& r : runs) {
    m.mean_frame_ms += r.mean_frame_ms / n;
    m.frame_rate_hz += r.frame_rate_hz / n;  // the paper averages the trials' frame rates
    m.triangles_per_frame += r.triangles_per_frame / n;
    m.objects_in_view += r.objects_in_view / n;
    m.full_triangles_per_frame += r.full_triangles_per_frame / n;
    m.lod_drawn += r.lod_drawn / n;
    m.lod_size += r.lod_size / n;
    m.lod_size_ecc += r.lod_size_ecc / n;
    m.lod_size_vel += r.lod_size_vel / n;
    m.lod_map += r.lod_map / n;
    m.triangles_size += r.triangles_size / n;
    m.triangles_size_ecc += r.triangles_size_ecc / n;
    m.triangles_size_vel += r.triangles_size_vel / n;
    m.triangles_map += r.triangles_map / n;
    m.shares.size += r.shares.size / n;
    m.shares.eccentricity += r.shares.eccentricity / n;
    m.shares.velocity += r.shares.velocity / n;
    m.shares.interaction += r.shares.interaction / n;
  }
  return m;
}

}  // namespace gazelod::cli
