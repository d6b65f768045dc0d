// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/report.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

FrameRecord frame(std::int64_t i, double ms, std::uint64_t drawn, std::uint64_t size_only, std::uint64_t size_ecc,
                  std::uint64_t size_vel) {
  FrameRecord f;
  f.index = i;
  f.t_s = static_cast<double>(i) / 90.0;
  f.frame_ms = ms;
  f.triangles_full = 1000;
  f.triangles_drawn = drawn;
  f.triangles_perceptual = drawn;  // no switch policy or budget in these frames
  f.triangles_size_only = size_only;
  f.triangles_size_eccentricity = size_ecc;
  f.triangles_size_velocity = size_vel;
  f.lod_histogram[0] = 1;
  f.lod_histogram[3] = 3;
  f.gaze_valid = i % 2 == 0;
  return f;
}

TEST(RunReport, SharesFollowTheCriteriaSets) {
  // Full 1000; all criteria 400 (R=600); size alone 700 (R=300);
  // size+ecc 500 (R=500) so velocity adds 100; size+vel 600 (R=400) so eccentricity adds 200.
  std::vector<FrameRecord> frames{frame(0, 2.0, 400, 700, 500, 600)};
  const RunSummary s = summarize(frames, 0.0);
  EXPECT_DOUBLE_EQ(s.shares.size, 0.5);
  EXPECT_DOUBLE_EQ(s.shares.eccentricity, 200.0 / 600.0);
  EXPECT_DOUBLE_EQ(s.shares.velocity, 100.0 / 600.0);
  EXPECT_NEAR(s.shares.interaction, 0.0, 1e-12);
}

TEST(RunReport, NoReductionGivesZeroSharesNotNaN) {
  std::vector<FrameRecord> frames{frame(0, 1.0, 1000, 1000, 1000, 1000)};
  const RunSummary s = summarize(frames, 0.0);
  EXPECT_EQ(s.shares.size, 0.0);
  EXPECT_EQ(s.shares.interaction, 0.0);
}

TEST(RunReport, PercentileMeanAndBudgetCount) {
  std::vector<FrameRecord> frames;
  for (int i = 0; i < 100; ++i) frames.push_back(frame(i, 1.0 + i, 500, 600, 550, 580));
  const RunSummary s = summarize(frames, 90.5);
  EXPECT_DOUBLE_EQ(s.mean_frame_ms, 50.5);
  EXPECT_DOUBLE_EQ(s.p95_frame_ms, 95.0);  // nearest rank: the 95th of 100
  EXPECT_DOUBLE_EQ(s.max_frame_ms, 100.0);
  EXPECT_EQ(s.frames_over_budget, 10);
  EXPECT_EQ(s.gaze_valid_frames, 50);
  EXPECT_EQ(s.lod_histogram[3], 300u);
  EXPECT_EQ(s.triangles_full, 100000u);
}

TEST(RunReport, WritesSummaryCsvAndPlot) {
  const auto dir = std::filesystem::temp_directory_path() / "gazelod_run_report_test";
  std::filesystem::remove_all(dir);
  std::vector<FrameRecord> frames{frame(0, 2.0, 400, 700, 500, 600), frame(1, 3.0, 450, 700, 500, 600)};
  frames[1].saccade = true;
  RunInfo info{"default", "questpro", "sim", "llvmpipe", "size,eccentricity,velocity", 0.0};
  write_report_files(dir, info, summarize(frames, 0.0), frames);
  std::ifstream js(dir / "summary.json");
  const auto j = nlohmann::json::parse(js);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["triangles_drawn"], 850);
  EXPECT_EQ(j["triangles_full"], 2000);
  EXPECT_TRUE(j["frame_time_ms"].contains("p95"));
  EXPECT_TRUE(j["shares"].contains("velocity"));
  std::ifstream csv(dir / "frames.csv");
  std::string line;
  int lines = 0;
  while (std::getline(csv, line)) ++lines;
  EXPECT_EQ(lines, 3);  // header + 2 frames
  std::ifstream svg(dir / "frames.svg");
  std::stringstream svg_text;
  svg_text << svg.rdbuf();
  EXPECT_NE(svg_text.str().find("saccade"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(RunReport, UnwritableFolderIsAnErrorNamingIt) {
  const std::filesystem::path dir = "/proc/gazelod-cannot-write-here";
  std::vector<FrameRecord> frames{frame(0, 2.0, 400, 700, 500, 600)};
  RunInfo info;
  try {
    write_report_files(dir, info, summarize(frames, 0.0), frames);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/gazelod-cannot-write-here"), std::string::npos);
  }
}

}  // namespace
}  // namespace gazelod::cli
