// `gazelod scenario validate | print | record`: exit codes and messages.
#include "tests/cli_run.hpp"
#include "apps/gazelod/command.hpp"
#include "sim/simulator.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

using ::testing::HasSubstr;

using Result = test::CliResult;
using test::run_cli;

TEST(ScenarioCli, ValidateReportsTheScenarioOrItsError) {
  const std::string good = std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/all_effects.json";
  Result r = run_cli({"scenario", "validate", good});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("ok"));
  EXPECT_THAT(r.out, HasSubstr("tracker_latency"));
  const std::string bad = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/cli_bad.json";
  std::ofstream(bad) << R"({"version": 1, "display": "questpro", "effects": [{"type": "head_sweep"}, {"type": "nod"}]})";
  r = run_cli({"scenario", "validate", bad});
  EXPECT_EQ(r.rc, 2);
  EXPECT_THAT(r.err, HasSubstr(bad + ": effects[1].type: unknown effect \"nod\""));
  r = run_cli({"scenario", "validate"});
  EXPECT_EQ(r.rc, 2) << "neither a file nor --default";
}

TEST(ScenarioCli, PrintDefaultIsTheEmbeddedScenario) {
  const Result r = run_cli({"scenario", "print", "--default"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NO_THROW((void)sim::load_scenario_json(r.out, "printed"));
}

TEST(ScenarioCli, RecordWritesATrace) {
  const std::string out = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/cli_default_trace.csv";
  Result r = run_cli({"scenario", "record", "--default", "--duration", "2", "--out", out});
  ASSERT_EQ(r.rc, 0) << r.err;
  std::ifstream in(out);
  std::string line;
  int lines = 0;
  while (std::getline(in, line)) ++lines;
  // The default tracker runs at 90 Hz: ~180 samples in 2 s, plus the header lines.
  EXPECT_NEAR(lines, 180, 5);
  r = run_cli({"scenario", "record", "--default", "--out", "/nonexistent/dir/t.csv"});
  EXPECT_NE(r.rc, 0);
  EXPECT_THAT(r.err, HasSubstr("/nonexistent/dir/t.csv"));
}

}  // namespace
}  // namespace gazelod::cli
