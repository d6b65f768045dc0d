// SPDX-License-Identifier: Apache-2.0
// gazelod thresholds and gazelod hmds through gazelod::cli::run.
#include "tests/cli_run.hpp"
#include "lod/acuity.hpp"
#include "apps/gazelod/commands/command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

namespace gazelod::cli {
namespace {

using Result = test::CliResult;
using test::run_cli;

TEST(CliThresholds, DesktopJsonMatchesReferenceTable) {
  const Result r = run_cli({"thresholds", "--hmd", "desktop", "--at-eccentricity", "10", "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["xi_h_cpd"].get<double>(), 12.05, 0.01);
  EXPECT_NEAR(j["xi_v_cpd"].get<double>(), 12.45, 0.01);
  EXPECT_NEAR(j["xi_cpd"].get<double>(), 12.45, 0.01);
  EXPECT_NEAR(j["eccentricity_threshold_deg"].get<double>(), 16.69, 0.01);
  EXPECT_NEAR(j["velocity_threshold_dps"].get<double>(), 42.50, 0.01);
  EXPECT_NEAR(j["velocity_threshold_at_eccentricity_dps"].get<double>(), 13.15, 0.01);
}

TEST(CliThresholds, PixelsAndFovMatchIGlasses) {
  const Result r =
      run_cli({"thresholds", "--pixels", "263x230", "--fov", "30x24", "--at-eccentricity", "15", "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["xi_h_cpd"].get<double>(), 4.38, 0.01);
  EXPECT_NEAR(j["xi_v_cpd"].get<double>(), 4.79, 0.01);
  EXPECT_NEAR(j["eccentricity_threshold_deg"].get<double>(), 28.95, 0.01);
  EXPECT_NEAR(j["velocity_threshold_dps"].get<double>(), 80.20, 0.01);
  EXPECT_NEAR(j["velocity_threshold_at_eccentricity_dps"].get<double>(), 23.99, 0.01);
}

TEST(CliThresholds, JsonWithoutEccentricityHasNoJointField) {
  const Result r = run_cli({"thresholds", "--hmd", "quest3", "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.contains("velocity_threshold_at_eccentricity_dps"));
  EXPECT_NEAR(j["xi_cpd"].get<double>(), 2208 / (2 * 96.0), 1e-9);
}

TEST(CliThresholds, ReadableTable) {
  const Result r = run_cli({"thresholds", "--hmd", "iglasses", "--at-eccentricity", "15"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("28.95"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("80.20"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("23.99"), std::string::npos) << r.out;
}

// A display coarser than the far periphery resolves: no eccentricity threshold within the
// visual field (it printed 1333.68 deg, past the opposite direction).
TEST(CliThresholds, NoEccentricityThresholdPast180Degrees) {
  Result r = run_cli({"thresholds", "--pixels", "1x1", "--fov", "179x179"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("eccentricity threshold (v = 0)  none within 180 deg"), std::string::npos) << r.out;
  r = run_cli({"thresholds", "--pixels", "1x1", "--fov", "179x179", "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out).at("eccentricity_threshold_deg").is_null()) << r.out;
}

void expect_refused(std::vector<std::string> args, const std::string& names) {
  const Result r = run_cli(args);
  EXPECT_NE(r.rc, 0) << names;
  EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(CliThresholds, BadArgumentsNameTheArgument) {
  expect_refused({"thresholds", "--hmd", "rift"}, "--hmd: unknown HMD 'rift'");
  expect_refused({"thresholds", "--pixels", "0x0", "--fov", "90x90"}, "--pixels");
  expect_refused({"thresholds", "--pixels", "100x", "--fov", "90x90"}, "--pixels");
  expect_refused({"thresholds", "--pixels", "abcxdef", "--fov", "90x90"}, "not a finite number");
  expect_refused({"thresholds", "--pixels", "100x100", "--fov", "0x90"}, "--fov");
  expect_refused({"thresholds", "--pixels", "100x100", "--fov", "180x90"},
                 "--fov: horizontal FOV must be in [0.001, 179] deg, got 180");
  // The limits of scenario files (lod::validate_described_view): one rule.
  expect_refused({"thresholds", "--pixels", "100x100", "--fov", "179.9x90"}, "must be in [0.001, 179] deg, got 179.9");
  expect_refused({"thresholds", "--pixels", "100x100", "--fov", "90x1e-300"},
                 "--fov: vertical FOV must be in [0.001, 179] deg, got 1e-300");
  expect_refused({"thresholds", "--pixels", "100x100", "--fov", "90x-5"}, "--fov: vertical FOV");
  expect_refused({"thresholds", "--pixels", "100x100", "--fov", "90xnan"}, "--fov");
  expect_refused({"thresholds", "--pixels", "100x100"}, "--fov: required");
  expect_refused({"thresholds", "--hmd", "quest3", "--at-eccentricity", "x"}, "--at-eccentricity");
  expect_refused({"thresholds", "--hmd", "quest3", "--at-eccentricity", "-1"}, "[0, 180]");
  expect_refused({"thresholds", "--hmd", "quest3", "--pixels", "1x1", "--fov", "1x1"}, "not both");
  expect_refused({"thresholds"}, "--hmd");
}

TEST(CliThresholds, FovLimitsThemselvesAreAccepted) {
  const Result r = run_cli({"thresholds", "--pixels", "1000x1000", "--fov", "179x0.001", "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["xi_cpd"].get<double>(), 1000 / (2 * 0.001), 1e-3);
}

TEST(CliHmds, ListsEveryPresetWithSource) {
  const Result r = run_cli({"hmds", "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 10u);
  for (const auto& d : j) {
    EXPECT_FALSE(d["source"].get<std::string>().empty());
    EXPECT_GT(d["xi_cpd"].get<double>(), 0.0);
    EXPECT_GT(d["pixels"][0].get<int>(), 0);
  }
  const Result t = run_cli({"hmds"});
  ASSERT_EQ(t.rc, 0);
  for (const char* name : {"desktop", "iglasses", "quest3", "questpro", "index", "viveproeye", "varjoxr4", "visionpro",
                           "psvr2", "pimaxcrystal"})
    EXPECT_NE(t.out.find(name), std::string::npos) << name;
}

}  // namespace
}  // namespace gazelod::cli
