// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/experiments.hpp"

#include <cstdio>

namespace gazelod::cli {
namespace {

std::string fmt(const char* f, double a, double b = 0.0) {
  char s[160];
  std::snprintf(s, sizeof s, f, a, b);
  return s;
}

// The point's layouts, each in its own folder; layout seeds 1..n are shared by all criteria
// so the with/without comparison is paired.
std::vector<EvalRun> layouts(const EvalOptions& o, ReddyScenario sc, const std::string& criteria, bool render,
                             const std::string& label, const Progress& progress) {
  std::vector<EvalRun> runs;
  for (int l = 1; l <= o.layouts; ++l) {
    sc.layout_seed = static_cast<std::uint64_t>(l);
    std::string name = label + "_" + criteria + "_layout" + std::to_string(l);
    for (char& c : name)
      if (c == ',')
        c = '+';
      else if (c == ' ' || c == '/')
        c = '_';
    runs.push_back(eval_run(sc, criteria, render, o.work_dir / name));
    progress(label + ", " + criteria + ", layout " + std::to_string(l) + "/" + std::to_string(o.layouts) +
             (render
                  ? fmt(": %.1f Hz, %.0f triangles/frame", runs.back().frame_rate_hz, runs.back().triangles_per_frame)
                  : fmt(": average LOD %.3f (1..4)", runs.back().lod_drawn)));
  }
  return runs;
}

// Reddy 1998's scene with n objects at the options' size scale, simulated at rate_hz.
ReddyScenario scenario(const EvalOptions& o, int n, double rate_hz) {
  ReddyScenario sc;
  sc.objects = n;
  sc.radius_scale = o.radius_scale;
  sc.frame_rate_hz = rate_hz;
  return sc;
}

}  // namespace

std::vector<Figure5Row> run_figure5(const EvalOptions& o, const Progress& progress) {
  std::vector<Figure5Row> rows;
  for (int n : o.counts) {
    const ReddyScenario sc = scenario(o, n, o.render_rate_hz);
    const std::string label = "figure5 " + std::to_string(n) + " objects";
    Figure5Row row;
    row.objects = n;
    row.none = mean_of(layouts(o, sc, "none", true, label, progress));
    row.all = mean_of(layouts(o, sc, "all", true, label, progress));
    rows.push_back(row);
  }
  return rows;
}

std::vector<Figure6Row> run_figure6(const EvalOptions& o, const Progress& progress) {
  std::vector<Figure6Row> rows;
  for (int n : o.counts) {
    const ReddyScenario sc = scenario(o, n, o.headless_rate_hz);
    const std::string label = "figure6 " + std::to_string(n) + " objects";
    Figure6Row row;
    row.objects = n;
    row.all = mean_of(layouts(o, sc, "all", false, label, progress));
    row.no_size = mean_of(layouts(o, sc, "eccentricity,velocity", false, label, progress));
    rows.push_back(row);
  }
  return rows;
}

std::vector<HeadTurnRow> run_head_turns(const EvalOptions& o, const Progress& progress) {
  std::vector<HeadTurnRow> rows;
  for (double rate : o.head_turn_deg_s) {
    ReddyScenario sc = scenario(o, o.head_turn_objects, o.headless_rate_hz);
    sc.head_turn_deg_s = rate;
    sc.surround = true;
    char label[64];
    std::snprintf(label, sizeof label, "head turn %.0f deg/s", rate);
    HeadTurnRow row;
    row.rate_deg_s = rate;
    row.all = mean_of(layouts(o, sc, "all", false, label, progress));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace gazelod::cli
