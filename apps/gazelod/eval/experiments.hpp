// SPDX-License-Identifier: Apache-2.0
// The experiments of `gazelod eval` (Reddy 1998 section 5 and the head-turn case it predicts),
// each a table of points averaged over random layouts. Plain data; commands/eval.cpp prints it.
#pragma once

#include "apps/gazelod/eval/runs.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gazelod::cli {

struct EvalOptions {
  std::vector<int> counts{10, 20, 50, 100, 200, 500, 1000};
  int layouts = 2;                 // random layouts per point (the paper: 20)
  double render_rate_hz = 6.0;     // frames per simulated second in the rendered runs
  double headless_rate_hz = 72.0;  // ... in the selection-only runs (the paper's refresh)
  std::vector<double> head_turn_deg_s{0.0, 90.0, 135.0, 180.0};
  int head_turn_objects = 200;
  double radius_scale = 1.0;       // object radii x this (1: 0.3 to 1.5 m)
  bool frame_rates = true;         // false: skip the rendered (slow) Figure 5 runs
  std::filesystem::path work_dir;  // each run's report
};

using Progress = std::function<void(const std::string&)>;

struct Figure5Row {  // frame rate without / with perceptual LOD, rendered
  int objects = 0;
  EvalRun none, all;
};
struct Figure6Row {  // average LOD with / without size, selection only, still head
  int objects = 0;
  EvalRun all;      // size + eccentricity + velocity, with the breakdown and the LOD map
  EvalRun no_size;  // eccentricity + velocity
};
struct HeadTurnRow {
  double rate_deg_s = 0.0;
  EvalRun all;
};

std::vector<Figure5Row> run_figure5(const EvalOptions& o, const Progress& progress);
std::vector<Figure6Row> run_figure6(const EvalOptions& o, const Progress& progress);
std::vector<HeadTurnRow> run_head_turns(const EvalOptions& o, const Progress& progress);

}  // namespace gazelod::cli
