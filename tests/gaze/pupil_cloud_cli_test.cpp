// SPDX-License-Identifier: Apache-2.0
// `gazelod trace stats|convert` on Pupil Cloud gaze.csv files the test writes: detected
// without --format, blinks.csv beside applied, agreement with Pupil's ids reported.
#include "tests/cli_run.hpp"
#include "tests/gaze/pupil_cloud_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;

using Result = test::CliResult;
Result run(const std::vector<std::string>& args) {
  return test::run_cli(args);
}

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / ("gazelod_pupil_cloud_cli_" + std::string(info->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST(PupilCloudCli, StatsDetectsTheExportAndReportsAgreement) {
  const fs::path dir = temp_dir();
  const auto rows = testing::three_fixations_and_a_blink();
  write_text(dir / "gaze.csv", testing::pupil_cloud_gaze_csv(rows));
  write_text(dir / "blinks.csv", testing::pupil_cloud_blinks_csv(rows));
  Result r = run({"trace", "stats", (dir / "gaze.csv").string(), "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "pupil_cloud");
  EXPECT_EQ(j["samples"].get<std::size_t>(), rows.size());
  EXPECT_NEAR(j["rate_hz"].get<double>(), 200.0, 1e-9);
  EXPECT_NEAR(j["invalid_fraction"].get<double>(), 30.0 / static_cast<double>(rows.size()), 1e-12);
  const auto& a = j["agreement"];
  EXPECT_EQ(a["blinks_file"], (dir / "blinks.csv").string());
  EXPECT_EQ(a["samples_in_blinks"].get<int>(), 30);
  for (const char* c : {"ivt", "ivdt"}) {
    SCOPED_TRACE(c);
    EXPECT_EQ(a[c]["fixation"]["reference_events"].get<int>(), 3);
    EXPECT_EQ(a[c]["fixation"]["reference_overlapped"].get<int>(), 3);
    EXPECT_GT(a[c]["fixation"]["kappa"].get<double>(), 0.7);
    EXPECT_EQ(a[c]["blink"]["both"].get<int>(), 30);
  }
  EXPECT_NE(a["ivdt"]["classifier"].get<std::string>().find("plugin"), std::string::npos);
  // The text form says the same, naming both classifiers.
  r = run({"trace", "stats", (dir / "gaze.csv").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("(pupil_cloud)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("agreement with Pupil Cloud's fixation id / blink id"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("I-VT (trace stats' classifier"), std::string::npos);
  EXPECT_NE(r.out.find("I-VDT (gaze_conditioner"), std::string::npos);
  EXPECT_NE(r.out.find("Pupil's overlapped by ours 3"), std::string::npos) << r.out;
}

TEST(PupilCloudCli, ConvertKeepsBlinksAsInvalidSamples) {
  const fs::path dir = temp_dir();
  const auto rows = testing::three_fixations_and_a_blink();
  write_text(dir / "s1_gaze.csv", testing::pupil_cloud_gaze_csv(rows));
  write_text(dir / "s1_blinks.csv", testing::pupil_cloud_blinks_csv(rows));
  const fs::path out = dir / "converted.csv";
  Result r = run({"trace", "convert", (dir / "s1_gaze.csv").string(), out.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run({"trace", "stats", out.string(), "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "gazelod");
  EXPECT_EQ(j["samples"].get<std::size_t>(), rows.size());
  EXPECT_NEAR(j["invalid_fraction"].get<double>(), 30.0 / static_cast<double>(rows.size()), 1e-12);
  EXPECT_NEAR(j["duration_s"].get<double>(), static_cast<double>(rows.size() - 1) * 0.005, 1e-12);
  EXPECT_FALSE(j.contains("agreement"));
}

TEST(PupilCloudCli, BadRowExitsNonZeroNamingLineAndColumn) {
  const fs::path dir = temp_dir();
  auto rows = testing::three_fixations_and_a_blink();
  rows[5].t_unix_ns = rows[4].t_unix_ns;  // line 7: a repeated timestamp
  write_text(dir / "gaze.csv", testing::pupil_cloud_gaze_csv(rows));
  const fs::path out = dir / "never.csv";
  for (const auto& args : {std::vector<std::string>{"trace", "stats", (dir / "gaze.csv").string()},
                           std::vector<std::string>{"trace", "convert", (dir / "gaze.csv").string(), out.string()}}) {
    const Result r = run(args);
    EXPECT_EQ(r.rc, 2);
    const std::size_t col = std::string(testing::kSection).size() + std::string(testing::kRecording).size() + 3;
    EXPECT_NE(r.err.find((dir / "gaze.csv").string() + ":7:" + std::to_string(col) +
                         ": timestamp [ns]: " + std::to_string(rows[5].t_unix_ns) + " repeats"),
              std::string::npos)
        << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(run({"trace", "stats", (dir / "gaze.csv").string(), "--format", "pupil-cloud"}).rc, 2);
}

}  // namespace
}  // namespace gazelod::gaze
