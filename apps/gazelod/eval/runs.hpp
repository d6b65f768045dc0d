// SPDX-License-Identifier: Apache-2.0
// One measured point of `gazelod eval`: a run of a Reddy 1998 scenario, called as a function
// (run_for_summary). Several layouts of a point are averaged by the caller.
#pragma once

#include "apps/gazelod/eval/scenario.hpp"
#include "apps/gazelod/run/shares.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::cli {

struct EvalRun {
  double mean_frame_ms = 0.0;  // measured: selection + rendering + submit
  double frame_rate_hz = 0.0;  // 1000 / mean_frame_ms (unpaced: as fast as it goes)
  // Over the objects in the view frustum (summary.json "in_view"), per frame and eye.
  double triangles_per_frame = 0.0;
  double full_triangles_per_frame = 0.0;
  // Average level on the paper's 1..4 scale (level 0 = 1) for each set of the breakdown.
  double lod_drawn = 1.0, lod_size = 1.0, lod_size_ecc = 1.0, lod_size_vel = 1.0, lod_map = 1.0;
  double triangles_size = 0.0, triangles_size_ecc = 0.0, triangles_size_vel = 0.0, triangles_map = 0.0;
  ReductionShares shares;        // of what was drawn in view (RunSummary::in_view_shares)
  double objects_in_view = 0.0;  // per frame
};

// Writes the scenario to dir/scenario.json (the simulated runtime reads it there) and runs a
// session on it with CRITERIA (rendering unless !render), its report in dir. Throws UsageError
// on failure.
EvalRun eval_run(const ReddyScenario& scenario, const std::string& criteria, bool render,
                 const std::filesystem::path& dir);

// Field-wise mean of `runs` (empty: a default EvalRun).
EvalRun mean_of(const std::vector<EvalRun>& runs);

}  // namespace gazelod::cli
