// SPDX-License-Identifier: Apache-2.0
// gazelod eval: Reddy 1998's experiments reproduced with gazelod's renderer and simulator, plus
// the head-turn case the paper predicts and the LOD-map thesis's policy beside Reddy's criteria.
// Writes eval_tables.md and figure5.svg / figure6.svg / head_turns.svg into --out; each run's
// own report goes under --work. Quick by default; --full is the paper's protocol (20 layouts,
// every frame of the 5 s paths at 72 Hz).
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/commands/out_folder.hpp"
#include "apps/gazelod/clusters/eval.hpp"
#include "apps/gazelod/eval/experiments.hpp"
#include "apps/gazelod/eval/family.hpp"
#include "apps/gazelod/eval/gltfpack.hpp"
#include "apps/gazelod/eval/tables.hpp"
#include "auxiliary/atomic_file.hpp"

#include <chrono>
#include <sstream>
#include <memory>

namespace gazelod::cli {
namespace {

struct EvalFlags {
  std::string out = "gazelod-eval";
  std::string work;
  bool full = false;
  bool no_render = false;
  int layouts = 0;
  double radius_scale = 1.0;
  std::vector<int> counts;
};

int run_eval(const EvalFlags& flags, Io io) {
  EvalOptions o;
  if (flags.full) {
    o.layouts = 20;
    o.render_rate_hz = 72.0;
  }
  if (flags.layouts > 0) o.layouts = flags.layouts;
  if (!flags.counts.empty()) o.counts = flags.counts;
  o.frame_rates = !flags.no_render;
  o.radius_scale = flags.radius_scale;
  const std::filesystem::path out = flags.out;
  o.work_dir = flags.work.empty() ? out / "runs" : std::filesystem::path(flags.work);
  const OutFolder out_folder = hold_out_folder(out, "eval", io.err);  // made and held first

  const auto started = std::chrono::steady_clock::now();
  const Progress progress = [&](const std::string& line) {
    const auto s = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - started).count();
    io.err << "gazelod eval [" << s << " s]: " << line << "\n" << std::flush;
  };
  const auto f6 = run_figure6(o, progress);
  const auto turns = run_head_turns(o, progress);
  const auto f5 = o.frame_rates ? run_figure5(o, progress) : std::vector<Figure5Row>{};

  const auto md_path = out / "eval_tables.md";
  std::ostringstream md;  // written whole at the end (auxiliary/atomic_file.hpp)
  md << "<!-- written by: gazelod eval" << (flags.full ? " --full" : "") << ", " << o.layouts
     << " layouts per point, radius scale " << o.radius_scale << " -->\n\n";
  if (!f5.empty()) {
    md << "### Figure 5: frame rate without and with perceptual LOD (rendered, " << o.render_rate_hz * 5.0
       << " frames per 5 s path)\n\n";
    figure5_table(f5, md);
    md << "\n";
  }
  md << "### Figure 6: average LOD with and without size (selection only, still head, " << o.headless_rate_hz * 5.0
     << " frames per path)\n\n";
  figure6_table(f6, md);
  md << "\n### Head turns (" << o.head_turn_objects << " objects around the observer, selection only)\n\n";
  head_turn_table(turns, md);
  try {
    aux::write_file_atomic(md_path.string(), md.str());
  } catch (const aux::WriteError& e) {
    throw UsageError(e.what(), 1);
  }
  write_eval_plots(f5, f6, turns, out);

  std::ifstream back(md_path);
  io.out << back.rdbuf();
  io.out << "\nfiles: " << md_path.string() << ", " << (f5.empty() ? "" : "figure5.svg, ")
         << "figure6.svg, head_turns.svg in " << out.string() << "\n";
  return 0;
}

const Registrar reg(
    "eval", "Reproduce Reddy 1998's experiments (frame rate, average LOD, head turns) with the LOD-map thesis's policy",
    [](CLI::App& app) -> Action {
      auto flags = std::make_shared<EvalFlags>();
      app.add_option("--out", flags->out, "Folder for eval_tables.md and the SVG plots");
      app.add_option("--work", flags->work, "Folder for each run's report (default: OUT/runs)");
      app.add_flag("--full", flags->full, "The paper's protocol: 20 layouts, 72 Hz frames (slow)");
      app.add_option("--layouts", flags->layouts, "Random layouts per point (default 2, --full 20)")
          ->check(CLI::Range(1, 1000));
      app.add_option("--counts", flags->counts, "Object counts (default 10 20 50 100 200 500 1000)")
          ->check(CLI::Range(1, 100000));
      app.add_option("--radius-scale", flags->radius_scale, "Scale the objects' radii (default 1: 0.3 to 1.5 m)")
          ->check(CLI::Range(0.01, 100.0));
      app.add_flag("--no-render", flags->no_render, "Skip the rendered frame-rate runs (Figure 5)");
      const EvalSubcommand clusters = add_eval_clusters(app);  // gazelod eval clusters (clusters/eval.hpp)
      const EvalSubcommand gltfpack = add_eval_gltfpack(app);  // gazelod eval gltfpack (eval/gltfpack.hpp)
      const EvalSubcommand family = add_eval_family(app);      // gazelod eval family (eval/family.hpp)
      return [=](Io io) {
        if (family.app->parsed()) return family.action(io);
        if (clusters.app->parsed()) return clusters.action(io);
        if (gltfpack.app->parsed()) return gltfpack.action(io);
        return run_eval(*flags, io);
      };
    });

}  // namespace
}  // namespace gazelod::cli
