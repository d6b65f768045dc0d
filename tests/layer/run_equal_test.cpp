// SPDX-License-Identifier: Apache-2.0
// `gazelod run --runtime system` on the simulated runtime without eye gaze, with the layer
// replaying a trace: the plugin reports the OpenXR gaze source, and its decisions equal those
// of a run that gives the same trace to the plugin as its external source (--trace), once both
// assume the same gaze accuracy (--gaze-error-deg). With the plugin's defaults the accuracy
// differs per source (openxr_gaze_error_deg 1.5, external_gaze_error_deg 2.0): the narrower
// foveal cone makes the layer's run coarser, never finer, which is what the second half checks.
#include "tests/cli_run.hpp"
#include "tests/layer/layer_test_util.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace gazelod::layer_test {
namespace {

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line, cell;
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::istringstream l(line);
    while (std::getline(l, cell, ',')) row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

struct Runs {
  std::string dir, trace;
  // One `gazelod run --runtime system`; `via_layer`: the layer serves the trace as eye gaze,
  // else the plugin reads it itself (--trace). Returns the decisions file.
  std::string run(bool via_layer, const std::vector<std::string>& extra, const std::string& name) {
    LayerSetup setup;
    setup.duration_s = 10.0;  // longer than the run: it ends the session itself
    setup.layer = via_layer;
    if (via_layer) setup.trace = trace;
    apply(setup);
    unsetenv("GAZELOD_SIM_SCENARIO");  // the embedded default scenario, as the run's own
    std::vector<std::string> args = {"run",      "--runtime",     "system",      "--no-render",
                                     "--frames", "360",           "--decisions", dir + "/" + name + ".csv",
                                     "--out",    dir + "/" + name};
    if (!via_layer) args.insert(args.end(), {"--trace", trace});
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = test::run_cli(args);
    EXPECT_EQ(r.rc, 0) << r.err;
    const std::string source = via_layer ? "gaze source openxr" : "gaze source external";
    EXPECT_NE(r.err.find(source), std::string::npos) << r.err;
    return dir + "/" + name + ".csv";
  }
};

TEST(LayerGazelodRun, DecisionsEqualThoseOfTheTraceAsExternalSource) {
  Runs runs;
  runs.dir = scratch_dir();
  runs.trace = runs.dir + "/trace.csv";
  const auto rec = test::run_cli({"scenario", "record", "--default", "--out", runs.trace, "--duration", "5"});
  ASSERT_EQ(rec.rc, 0) << rec.err;

  const auto external = read_csv(runs.run(false, {"--gaze-error-deg", "2"}, "external"));
  const auto layered = read_csv(runs.run(true, {"--gaze-error-deg", "2"}, "layer"));
  ASSERT_EQ(external.size(), 361u);  // header + 360 frames
  ASSERT_EQ(layered.size(), external.size());
  for (std::size_t i = 0; i < external.size(); ++i) ASSERT_EQ(layered[i], external[i]) << "decisions row " << i;

  // The plugin's per-source defaults: same gaze, the OpenXR source trusted more (1.5 deg).
  const auto external_default = read_csv(runs.run(false, {}, "external_default"));
  const auto layered_default = read_csv(runs.run(true, {}, "layer_default"));
  ASSERT_EQ(layered_default.size(), external_default.size());
  int coarser = 0, finer = 0;
  for (std::size_t i = 1; i < external_default.size(); ++i)
    for (std::size_t c = 2; c < external_default[i].size(); ++c) {
      const int e = std::stoi(external_default[i][c]), l = std::stoi(layered_default[i][c]);
      coarser += l > e ? 1 : 0;
      finer += l < e ? 1 : 0;
    }
  EXPECT_GT(coarser, 0);
  EXPECT_EQ(finer, 0);
  LayerSetup off;
  off.layer = false;
  apply(off);
}

// The option the comparison needs (apps/gazelod/commands/run.cpp): a finite number in [0.01, 20].
TEST(LayerGazelodRun, GazeErrorOptionRefusesBadValues) {
  for (const char* bad : {"nan", "0", "25", "x"}) {
    const auto r = test::run_cli({"run", "--no-render", "--frames", "1", "--gaze-error-deg", bad});
    EXPECT_EQ(r.rc, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--gaze-error-deg"), std::string::npos) << bad << ": " << r.err;
  }
}

}  // namespace
}  // namespace gazelod::layer_test
