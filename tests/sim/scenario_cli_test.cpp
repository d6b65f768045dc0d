// SPDX-License-Identifier: Apache-2.0
// `gazelod scenario validate | print | record`: exit codes and messages.
#include "tests/cli_run.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "sim/simulator.hpp"

#include <nlohmann/json.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

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
  std::ofstream(bad)
      << R"({"version": 1, "display": "questpro", "effects": [{"type": "head_sweep"}, {"type": "nod"}]})";
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

// Files `gazelod run` (or the plugin, or the runtime) used to be the first to refuse: validate
// now refuses them too, exit 2, naming the file and the JSON path.
TEST(ScenarioCli, ValidateRefusesWhatRunRefusesWithExit2) {
  const std::string bad = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/cli_refused.json";
  auto validate = [&](const nlohmann::json& j) {
    std::ofstream(bad) << j.dump();
    return run_cli({"scenario", "validate", bad});
  };
  auto scenario = [] {
    return nlohmann::json{{"version", 1},
                          {"display", "questpro"},
                          {"scene", {{"objects", {{{"name", "a"}, {"lods", {{{"triangles", 100}}}}}}}}}};
  };
  struct Case {
    const char* what;
    std::function<void(nlohmann::json&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"256 levels",
       [](nlohmann::json& j) {
         auto& lods = j["scene"]["objects"][0]["lods"];
         for (int k = 1; k < 256; ++k) lods.push_back({{"detail", 1000.0 / k}});
       },
       ": scene.objects[0].lods: a chain needs 1 to 255 levels, got 256"},
      {"non-monotone",
       [](nlohmann::json& j) {
         j["scene"]["objects"][0]["lods"] = {{{"detail", 0}}, {{"detail", 2}}, {{"detail", 3}}};
       },
       ": scene.objects[0].lods[2]: must remove no finer detail than level 1"},
      {"geometric error 0",
       [](nlohmann::json& j) {
         j["scene"]["objects"][0]["lods"] = {{{"detail_kind", "geometric_error_m"}},
                                             {{"detail_kind", "geometric_error_m"}, {"detail", 0}}};
       },
       ": scene.objects[0].lods[1]: detail must be finite and > 0, got 0"},
      {"one view",
       [](nlohmann::json& j) {
         j["display"] = {{"preset", "questpro"}, {"views", 1}};
       },
       ": display.views: must be 2"},
      {"shorter than a frame", [](nlohmann::json& j) { j["duration_s"] = 0.002; },
       ": duration_s: must be at least one frame (1 / 90 Hz = 0.0111111 s), got 0.002"},
      {"memory bomb",
       [](nlohmann::json& j) {
         for (int i = 0; i < 50; ++i)
           j["scene"]["generators"].push_back({{"type", "random_field"},
                                               {"count", 1'000'000},
                                               {"lod_count", 16},
                                               {"name_prefix", std::string("g").append(std::to_string(i))}});
       },
       ": scene.generators[0].count: must be <= 999999 objects"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    nlohmann::json j = scenario();
    c.edit(j);
    const Result r = validate(j);
    EXPECT_EQ(r.rc, 2);
    EXPECT_THAT(r.err, HasSubstr("gazelod scenario: " + bad + c.expected));
    EXPECT_EQ(r.out, "");
  }
  EXPECT_EQ(validate(scenario()).rc, 0);
  Result r = run_cli({"scenario", "validate", "/dev/zero"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_THAT(r.err, HasSubstr("/dev/zero: is not a regular file"));
  r = run_cli({"scenario", "validate", GAZELOD_BINARY_DIR});
  EXPECT_EQ(r.rc, 2);
  EXPECT_THAT(r.err, HasSubstr(": is a directory, not a scenario file"));
}

// record writes its trace atomically: on any failure no file is left, partial or temporary,
// and the message says why.
TEST(ScenarioCli, RecordLeavesNoPartialFile) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(GAZELOD_BINARY_DIR) / "tests" / "sim" / "record_atomic";
  fs::remove_all(dir);
  fs::create_directories(dir / "adir.csv");
  Result r = run_cli({"scenario", "record", "--default", "--duration", "1", "--out", (dir / "adir.csv").string()});
  EXPECT_EQ(r.rc, 2);  // a folder named for the file: bad input, refused before the recording
  EXPECT_THAT(r.err, HasSubstr("--out: cannot write '" + (dir / "adir.csv").string() + "': is a directory"));
  r = run_cli({"scenario", "record", "--default", "--duration", "1", "--out", (dir / "no" / "t.csv").string()});
  EXPECT_EQ(r.rc, 1);
  EXPECT_THAT(r.err, HasSubstr("': No such file or directory (creating a temporary file in '"));
  r = run_cli({"scenario", "record", "--default", "--duration", "1", "--out", "/dev/full"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_THAT(r.err, HasSubstr("cannot write '/dev/full': No space left on device"));
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"adir.csv"});
  // A full file system (a 64 KiB tmpfs: root with CAP_SYS_ADMIN only).
  const fs::path tiny = dir / "tiny";
  fs::create_directory(tiny);
  if (::mount("tmpfs", tiny.c_str(), "tmpfs", 0, "size=64k") != 0)
    GTEST_SKIP() << "cannot mount a 64 KiB tmpfs here (" << std::strerror(errno) << "): needs CAP_SYS_ADMIN";
  r = run_cli({"scenario", "record", "--default", "--duration", "5", "--out", (tiny / "t.csv").string()});
  ::umount(tiny.c_str());
  EXPECT_EQ(r.rc, 1);
  EXPECT_THAT(r.err, HasSubstr("cannot write '" + (tiny / "t.csv").string() + "': No space left on device"));
}

}  // namespace
}  // namespace gazelod::cli
