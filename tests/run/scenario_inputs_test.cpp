// SPDX-License-Identifier: Apache-2.0
// Scenario files as users hand them over: a named scenario whose trace files sit beside it, run
// from another working folder; a file name that is not UTF-8; a recording written over its own
// scenario. Each failed before: the effects were given the scenario's name, not its file, so run
// read a file of the same name in the working folder (or failed in the runtime, which reads the
// copy in --out); the name reached nlohmann's dump() and ended the run after its report was
// printed, with summary.json missing; record turned the scenario into a CSV trace, and wrote a
// trace of no rows where the tracker was as late as the recording was long.
#include "run_test_util.hpp"
#include "sim/simulator.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gazelod::test {
namespace {

namespace fs = std::filesystem;

// Restores the working folder however the test ends.
struct InFolder {
  explicit InFolder(const fs::path& dir) : before(fs::current_path()) { fs::current_path(dir); }
  ~InFolder() { fs::current_path(before); }
  fs::path before;
};

nlohmann::json default_scenario() {
  return nlohmann::json::parse(sim::default_scenario_json());
}

TEST(ScenarioInputs, RelativeTraceFilesAreFoundBesideTheScenario) {
  use_simulated_runtime("");
  const fs::path dir = fs::absolute(scratch_dir());
  fs::create_directories(dir / "scen");
  fs::create_directories(dir / "cwd");
  CliResult r =
      run_cli({"scenario", "record", "--default", "--duration", "2", "--out", (dir / "scen" / "head.csv").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  std::ofstream(dir / "cwd" / "head.csv") << "not a trace\n";  // the same name where the command runs
  nlohmann::json sc = default_scenario();
  sc["name"] = "walk";
  sc["duration_s"] = 1.0;
  sc["effects"] = nlohmann::json::array({{{"type", "head_track"}, {"file", "head.csv"}}});
  std::ofstream(dir / "scen" / "s.json") << sc.dump(2);

  std::vector<CliResult> results;
  {
    const InFolder here(dir / "cwd");
    results.push_back(run_cli({"scenario", "validate", "../scen/s.json"}));
    results.push_back(
        run_cli({"run", "--scenario", "../scen/s.json", "--no-render", "--quiet", "--frames", "5", "--out", "../out"}));
    results.push_back(run_cli({"scenario", "record", "../scen/s.json", "--duration", "1", "--out", "rec.csv"}));
    results.push_back(
        run_cli({"compare", "--scenario", "../scen/s.json", "--hmd", "questpro", "--frames", "3", "--out", "../cmp"}));
  }
  for (const CliResult& c : results) EXPECT_EQ(c.rc, 0) << c.err;
  // The copy the runtime read names the file beside the scenario, so it runs from anywhere.
  std::ifstream copy(dir / "out" / "scenario.json");
  const nlohmann::json ran = nlohmann::json::parse(copy);
  const std::string file = ran.at("effects").at(0).at("file");
  EXPECT_TRUE(fs::path(file).is_absolute()) << file;
  EXPECT_TRUE(fs::equivalent(file, dir / "scen" / "head.csv")) << file;
}

// A scenario file whose name is Latin-1 (no "name": the label is the path) runs and writes its
// whole report; the bad byte is written as U+FFFD.
TEST(ScenarioInputs, AFileNameThatIsNotUtf8) {
  use_simulated_runtime("");
  const fs::path dir = scratch_dir();
  nlohmann::json sc = default_scenario();
  sc.erase("name");
  const fs::path file = dir / "caf\xe9.json";
  std::ofstream(file) << sc.dump(2);
  CliResult r = run_cli(
      {"run", "--scenario", file.string(), "--no-render", "--quiet", "--frames", "4", "--out", (dir / "out").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  std::ifstream summary(dir / "out" / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  EXPECT_EQ(j.at("frames"), 4);
  EXPECT_NE(j.dump().find("caf\xef\xbf\xbd.json"), std::string::npos) << "the name, with U+FFFD for the bad byte";
  r = run_cli({"scenario", "print", file.string()});
  EXPECT_EQ(r.rc, 0) << r.err;
}

TEST(ScenarioInputs, RecordOverItsOwnScenarioIsRefused) {
  const fs::path dir = scratch_dir();
  std::ofstream(dir / "s.json") << default_scenario().dump(2);
  const CliResult r =
      run_cli({"scenario", "record", (dir / "s.json").string(), "--duration", "1", "--out", (dir / "s.json").string()});
  EXPECT_EQ(r.rc, 2) << r.err;
  EXPECT_NE(r.err.find("is the scenario being recorded"), std::string::npos) << r.err;
  std::ifstream kept(dir / "s.json");
  EXPECT_EQ(nlohmann::json::parse(kept), default_scenario()) << "the scenario was overwritten";
}

// A tracker as late as the whole recording: no sample arrives, so no trace is written (it said
// "wrote 0 rows" and exited 0, and `run --trace` refused the file later).
TEST(ScenarioInputs, ARecordingWithNoSampleIsRefused) {
  const fs::path dir = scratch_dir();
  nlohmann::json sc = default_scenario();
  sc["duration_s"] = 0.5;
  sc["effects"].push_back({{"type", "tracker_latency"}, {"latency_ms", 600}});
  std::ofstream(dir / "late.json") << sc.dump(2);
  const CliResult r =
      run_cli({"scenario", "record", (dir / "late.json").string(), "--out", (dir / "late.csv").string()});
  EXPECT_EQ(r.rc, 2) << r.err;
  EXPECT_NE(r.err.find("no sample arrives within the recording's 0.5 s"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "late.csv"));
}

}  // namespace
}  // namespace gazelod::test
