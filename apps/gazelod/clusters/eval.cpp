// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/eval.hpp"

#include "apps/gazelod/clusters/eval_baseline.hpp"
#include "apps/gazelod/clusters/eval_report.hpp"
#include "apps/gazelod/commands/out_folder.hpp"
#include "apps/gazelod/eval/work.hpp"
#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/run/session.hpp"
#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/json_text.hpp"

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace gazelod::cli {
namespace {

namespace fs = std::filesystem;

struct ClusterEvalFlags {
  std::string out = "gazelod-eval-clusters";
  std::string work;          // "": a temporary folder, removed at the end
  std::string scene_source;  // "": the generated terrain
  std::string scenario = "sim/scenarios/terrain-walk.json";
  std::string hmd;
  std::uint64_t triangles = 1'000'000;
  std::uint64_t seed = 1;
  int tiles = 1;
  std::int64_t frames = 0;  // 0: the scenario's duration
  int render_frames = 60;   // 0: no rendered runs
  int render_rounds = 3;    // rendered runs per column, the columns taking turns
};

std::string join(const std::vector<std::string>& args) {
  std::string s = "gazelod";
  for (const std::string& a : args) s += " " + a;
  return s;
}

// One gazelod command in this process; its output is kept for the error message only.
void invoke(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int rc = run(args, out, err);
  if (rc != 0) {
    std::string why = err.str();
    while (!why.empty() && why.back() == '\n') why.pop_back();
    throw UsageError("`" + join(args) + "` failed (exit " + std::to_string(rc) + "): " + why, rc == 2 ? 2 : 1);
  }
}

std::string fmt(const char* format, double a, double b = 0.0) {
  char s[200];
  std::snprintf(s, sizeof s, format, a, b);
  return s;
}

int run_eval_clusters(const ClusterEvalFlags& flags, const CLI::App& app, Io io) {
  if (!flags.scene_source.empty())
    for (const char* option : {"--triangles", "--seed", "--tiles"})
      if (app.count(option) > 0)
        throw UsageError(std::string(option) + ": only for the generated terrain, not with --scene-source");
  if (!fs::is_regular_file(flags.scenario))
    throw UsageError("--scenario: '" + flags.scenario +
                     "' is not a file (run from the repository root, or give --scenario FILE)");
  if (!flags.scene_source.empty() && !fs::is_regular_file(flags.scene_source))
    throw UsageError("--scene-source: '" + flags.scene_source + "' is not a file");
  const fs::path out = flags.out;
  const OutFolder out_folder = hold_out_folder(out, "eval clusters", io.err);  // made and held first
  const WorkDir work(flags.work, "gazelod-eval-clusters");
  const fs::path& w = work.path();
  // Ctrl-C or SIGTERM stops between steps, a run at its next frame: no report (three columns
  // or none), the temporary work folder removed as the stack unwinds. A bake in progress
  // finishes first (seconds to a minute at the default size); a second signal ends the
  // process at once.
  StopOnSignal stop;
  const auto stop_if_asked = [&](const std::string& during) {
    if (const int sig = stop.requested()) {
      stop.acted_on();
      throw UsageError(
          std::string("stopped by ") + StopOnSignal::name(sig) + " during " + during + "; no report written",
          128 + sig);
    }
  };

  const auto started = std::chrono::steady_clock::now();
  auto progress = [&](const std::string& line) {
    const auto s = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - started).count();
    io.err << "gazelod eval clusters [" << s << " s]: " << line << "\n" << std::flush;
  };
  auto step = [&](const std::vector<std::string>& args) {
    stop_if_asked(join(args));
    progress(join(args));
    try {
      invoke(args);
    } catch (const UsageError&) {
      stop_if_asked(join(args));  // a step the signal cut short failed: the stop says why
      throw;
    }
    stop_if_asked(join(args));
  };

  ClusterEvalReport report;
  report.scenario = flags.scenario;
  report.machine = cpu_model();
  std::string source = flags.scene_source;
  if (source.empty()) {
    source = (w / "terrain.glb").string();
    step({"scene", "generate", "terrain", source, "--triangles", std::to_string(flags.triangles), "--seed",
          std::to_string(flags.seed), "--tiles", std::to_string(flags.tiles)});
    report.scene = "generated terrain (gazelod scene generate terrain --triangles " + std::to_string(flags.triangles) +
                   " --seed " + std::to_string(flags.seed) + " --tiles " + std::to_string(flags.tiles) + ")";
  } else {
    report.scene = flags.scene_source;
  }
  // The three bakes: per-object LOD as `gazelod bake` makes it (the baseline), the same chains
  // under the cluster rule (clusters/eval_baseline.hpp), and the cluster hierarchy.
  report.columns = {{"per_object", "per-object LOD (bake: MSFT_lod chain, object rule)", false, {}, "", {}, 0.0, 0.0},
                    {"per_object_cluster_rule",
                     "per-object LOD under the cluster rule (the same chain, one cluster per level)",
                     true,
                     {},
                     "",
                     {},
                     0.0,
                     0.0},
                    {"clusters", "cluster LOD (bake --clusters)", true, {}, "", {}, 0.0, 0.0}};
  const std::string glbs[3] = {(w / "per-object.glb").string(), (w / "per-object-cluster-rule.glb").string(),
                               (w / "clusters.glb").string()};
  const std::string dirs[3] = {"per-object", "per-object-cluster-rule", "clusters"};
  step({"bake", source, "-o", glbs[0]});
  progress("the same chains as one cluster per level -> " + glbs[1]);
  bake_chain_as_clusters(source, glbs[1]);
  stop_if_asked("the bake of " + glbs[1]);
  step({"bake", "--clusters", source, "-o", glbs[2]});

  // The runs are function calls (run_for_summary); each keeps its report in the work folder.
  auto run_column = [&](std::size_t i, const fs::path& dir, bool render) {
    RunOptions o;
    o.scene_path = glbs[i];
    o.scene_placement = "file";
    o.scenario_path = flags.scenario;
    o.out_dir = dir;
    o.hmd = flags.hmd;
    if (render)
      o.frames = flags.render_frames;
    else if (flags.frames > 0)
      o.frames = flags.frames;
    o.render = render;
    std::vector<FrameRecord> records;
    o.frames_result = &records;
    const std::string what = "the run of " + glbs[i];
    stop_if_asked(what);
    progress("run " + glbs[i] + (render ? " (rendered)" : "") + " -> " + dir.string());
    RunSummary summary;
    try {
      summary = run_for_summary(o, what);
    } catch (const UsageError&) {
      stop_if_asked(what);  // the run stopped at the signal (exit 130): the stop says why
      throw;
    }
    stop_if_asked(what);
    return std::pair{summary, std::move(records)};
  };
  for (std::size_t i = 0; i < 3; ++i) {
    ClusterEvalColumn& c = report.columns[i];
    const auto [summary, records] = run_column(i, w / dirs[i], false);
    try {
      c.side = cluster_eval_side(summary, records, c.clusters, glbs[i]);
      progress(c.title +
               fmt(": %.0f triangles per frame (%.2f%% of full detail)", c.side->triangles_per_frame,
                   100.0 * c.side->triangles_per_frame / std::max(1.0, c.side->full_triangles_per_frame)) +
               fmt(", visible degradations %.3f%%", 100.0 * c.side->degraded_share));
    } catch (const UsageError& e) {
      if (!c.clusters) throw;  // the baseline must be there
      c.missing = e.what();
      progress(c.title + ": " + c.missing);
    }
  }
  if (flags.render_frames > 0) {
    // The columns take turns, round after round, so that a machine that slows down or speeds
    // up during the eval moves every column alike; each column's figure is its rounds' median.
    report.rendered_frames = flags.render_frames;
    report.rendered_rounds = flags.render_rounds;
    for (int round = 0; round < flags.render_rounds; ++round)
      for (std::size_t i = 0; i < 3; ++i) {
        ClusterEvalColumn& c = report.columns[i];
        if (!c.side) continue;
        const fs::path dir = w / (dirs[i] + "-rendered-" + std::to_string(round + 1));
        const auto [summary, records] = run_column(i, dir, true);
        c.frame_ms_rounds.push_back(summary.mean_frame_ms);
        c.rendered_triangles = cluster_eval_side(summary, records, c.clusters, glbs[i]).triangles_per_frame;
        progress(c.title + " rendered, round " + std::to_string(round + 1) +
                 fmt(": mean frame %.1f ms, %.0f triangles per frame", c.frame_ms_rounds.back(), c.rendered_triangles));
      }
    for (ClusterEvalColumn& c : report.columns) c.frame_ms = median_of(c.frame_ms_rounds);
  }

  const std::string md = "<!-- written by: gazelod eval clusters -->\n\n" + cluster_eval_markdown(report);
  write_report(out, {{"clusters.md", md}, {"clusters.json", aux::json_text(cluster_eval_json(report), 2) + "\n"}});
  write_cluster_eval_svg(report, out / "clusters.svg");
  io.out << md << "\nfiles: clusters.md, clusters.json, clusters.svg in " << out.string() << "\n";
  for (const ClusterEvalColumn& c : report.columns)
    if (!c.side) {
      io.err << "gazelod eval clusters: not measured: " << c.title << ": " << c.missing << "\n";
      return 1;
    }
  return 0;
}

}  // namespace

EvalSubcommand add_eval_clusters(CLI::App& eval) {
  auto flags = std::make_shared<ClusterEvalFlags>();
  CLI::App* app = eval.add_subcommand(
      "clusters", "Cluster LOD (bake --clusters) against per-object LOD (MSFT_lod chains) on a large terrain");
  app->add_option("--out", flags->out, "Folder for clusters.md, clusters.json, clusters.svg");
  app->add_option("--work", flags->work,
                  "Folder for the scenes, bakes and run reports (default: a temporary one, removed)");
  app->add_option("--scene-source", flags->scene_source, "A glTF to bake and walk instead of the generated terrain");
  app->add_option("--scenario", flags->scenario, "The walk (default sim/scenarios/terrain-walk.json)");
  app->add_option("--hmd", flags->hmd, "Display preset replacing the scenario's (see gazelod hmds)");
  app->add_option("--triangles", flags->triangles, "Generated terrain: at least this many triangles (default 1000000)")
      ->check(CLI::Range(std::uint64_t{2}, std::uint64_t{20'000'000}));
  app->add_option("--seed", flags->seed, "Generated terrain: seed (default 1)");
  app->add_option("--tiles", flags->tiles, "Generated terrain: N x N meshes (default 1)")->check(CLI::Range(1, 64));
  app->add_option("--frames", flags->frames, "Frames of the headless runs (default: the scenario's)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{10'000'000}));
  app->add_option("--render-frames", flags->render_frames, "Frames of each rendered run (default 60; 0: none)")
      ->check(CLI::Range(0, 100000));
  app->add_option("--render-rounds", flags->render_rounds,
                  "Rendered runs per column, the columns taking turns; the median counts (default 3)")
      ->check(CLI::Range(1, 20));
  return {app, [flags, app](Io io) { return run_eval_clusters(*flags, *app, io); }};
}

}  // namespace gazelod::cli
