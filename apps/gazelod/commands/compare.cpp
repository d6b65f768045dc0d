// SPDX-License-Identifier: Apache-2.0
// gazelod compare: what each perceptual criterion buys on each display. For every --hmd, one
// headless run of the scenario (rendering only with --render) reports the five criteria sets
// (none, size, size+eccentricity, size+velocity, all three) and the LOD-map thesis's policy:
// triangles, average LOD, the shares of the reduction, and the display's xi and thresholds.
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/commands/out_folder.hpp"
#include "apps/gazelod/compare/report.hpp"
#include "apps/gazelod/compare/runs.hpp"
#include "auxiliary/atomic_file.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <memory>

namespace gazelod::cli {
namespace {

int run_compare(const CompareOptions& o, bool json, Io io) {
  if (o.hmds.empty()) throw UsageError("--hmd: give at least one display preset (see gazelod hmds)");
  for (std::size_t i = 0; i < o.hmds.size(); ++i) {  // all names before any run
    check_hmd(o.hmds[i]);
    for (std::size_t j = 0; j < i; ++j)
      if (o.hmds[j] == o.hmds[i])
        throw UsageError("--hmd: '" + o.hmds[i] + "' twice (its runs would share one folder in --out)");
  }
  // --out first, held against another gazelod writing there: a folder that cannot be made
  // would otherwise be found after every run.
  const OutFolder out = hold_out_folder(o.out_dir, "compare", io.err);
  std::vector<HmdComparison> results;
  try {
    for (const std::string& h : o.hmds) {
      if (!json) io.err << "gazelod compare: running " << h << "\n";
      results.push_back(run_comparison(h, o));
    }
  } catch (...) {
    std::error_code ec;
    if (out.created) std::filesystem::remove(o.out_dir, ec);  // a refused run: no empty folder left
    throw;
  }
  const nlohmann::json doc = compare_json(results);
  const auto json_path = o.out_dir / "compare.json";
  aux::write_file_atomic(json_path.string(), aux::json_text(doc, 2) + "\n");  // before, a plain ofstream, unchecked
  write_compare_chart(results, o.out_dir);
  if (json) {
    io.out << aux::json_text(doc, 2) << "\n";
  } else {
    print_compare_table(results, io.out, o.breakdown);
    io.out << "files: " << json_path.string() << ", compare.svg, <hmd>/summary.json, <hmd>/frames.svg\n";
  }
  return 0;
}

const Registrar reg(
    "compare", "Compare the criteria sets (and the LOD-map thesis's policy) across display presets",
    [](CLI::App& app) -> Action {
      auto opt = std::make_shared<CompareOptions>();
      auto json = std::make_shared<bool>(false);
      auto out = std::make_shared<std::string>("gazelod-compare");
      app.add_option("--hmd", opt->hmds, "Display preset (repeat for several; see gazelod hmds)")->required();
      app.add_option("--scenario", opt->scenario_path, "Scenario JSON (default: the embedded scenario)");
      app.add_option("--frames", opt->frames, "Frames per run (default: the scenario's duration)")
          ->check(CLI::Range(std::int64_t{1}, std::int64_t{10'000'000}));
      app.add_option("--out", *out, "Folder for compare.json, compare.svg and each run's report");
      app.add_flag("--json", *json, "Print the JSON document instead of the table");
      app.add_flag("--render", opt->render, "Render with Vulkan (default: selection only)");
      app.add_flag("--breakdown", opt->breakdown,
                   "Print where each audit's figures come from (true gaze state, object class, oracle criterion)");
      return [=](Io io) {
        CompareOptions o = *opt;
        o.out_dir = *out;
        return run_compare(o, *json, io);
      };
    });

}  // namespace
}  // namespace gazelod::cli
