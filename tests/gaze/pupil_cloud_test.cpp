// SPDX-License-Identifier: Apache-2.0
// Pupil Cloud gaze.csv importer, its blinks file, layout detection in open_trace, and the
// agreement of our classifiers with Pupil Cloud's own fixation / blink ids.
#include "auxiliary/angles.hpp"
#include "gaze/gaze_agreement.hpp"
#include "gaze/import_pupil_cloud.hpp"
#include "gaze/trace_open.hpp"
#include "gaze/trace_stats.hpp"
#include "tests/gaze/pupil_cloud_util.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <thread>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;
using testing::kPupilCloudGazeHeader;
using testing::kUnixStartNs;

std::vector<TraceRecord> read_all(const std::string& text, PupilCloudBlinks blinks = {}, ReadOptions o = {}) {
  std::istringstream in(text);
  PupilCloudReader r(in, "gaze.csv", o, std::move(blinks));
  std::vector<TraceRecord> out;
  TraceRecord rec;
  while (r.next(rec)) out.push_back(rec);
  return out;
}

std::string error_of(const std::string& text) {
  try {
    read_all(text);
  } catch (const TraceError& e) {
    return e.what();
  }
  return "(no error)";
}

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / ("gazelod_pupil_cloud_" + std::string(info->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// A row with made-up ids: "s,r,<t>,500,400,<worn>,<fix>,<blink>,<az>,<el>".
std::string row(std::int64_t t, const std::string& rest = "1,,,0,0") {
  return "s,r," + std::to_string(t) + ",500,400," + rest + "\n";
}

TEST(PupilCloud, AzimuthRightElevationUpInOpenXrAxes) {
  const auto r = read_all(std::string(kPupilCloudGazeHeader) + row(kUnixStartNs, "1,,,10,0") +
                          row(kUnixStartNs + 5'000'000, "1,,,0,10") + row(kUnixStartNs + 10'000'000, "1,,,-20,-15"));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_GT(r[0].gaze.direction.x, 0.0);  // azimuth positive = right = +x
  EXPECT_LT(r[0].gaze.direction.z, 0.0);  // forward = -z
  EXPECT_GT(r[1].gaze.direction.y, 0.0);  // elevation positive = up = +y
  const glm::dvec3 d = r[2].gaze.direction;
  EXPECT_NEAR(glm::length(d), 1.0, 1e-15);
  EXPECT_NEAR(std::atan2(d.x, -d.z) * aux::kDegPerRad, -20.0, 1e-12);
  EXPECT_NEAR(std::atan2(d.y, std::hypot(d.x, d.z)) * aux::kDegPerRad, -15.0, 1e-12);
  for (const auto& rec : r) EXPECT_TRUE(rec.gaze.valid);
}

TEST(PupilCloud, RebasesUnixNanosecondsExactly) {
  // Odd nanoseconds 1.65e18 from the epoch: a double would lose them (its step there is 256 ns).
  const auto r = read_all(std::string(kPupilCloudGazeHeader) + row(kUnixStartNs) + row(kUnixStartNs + 4'012'345) +
                          row(kUnixStartNs + 8'024'691));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].gaze.t_ns, 0);
  EXPECT_EQ(r[1].gaze.t_ns, 4'012'345);
  EXPECT_EQ(r[2].gaze.t_ns, 8'024'691);
}

TEST(PupilCloud, ColumnsByNameNeonWithoutIdsAndExtraColumns) {
  const std::string text =
      "timestamp [ns],elevation [deg],extra,azimuth [deg],worn,gaze y [px],gaze x [px],recording id\n" +
      std::to_string(kUnixStartNs) + ",5,x,-3,1,1,2,r\n" + std::to_string(kUnixStartNs + 5'000'000) +
      ",5,x,-3,0,1,2,r\n" + std::to_string(kUnixStartNs + 10'000'000) + ",,x,,1,1,2,r\n";
  std::istringstream in(text);
  PupilCloudReader reader(in, "neon.csv");
  EXPECT_FALSE(reader.has_fixation_ids());
  EXPECT_FALSE(reader.has_blink_ids());
  TraceRecord rec;
  ASSERT_TRUE(reader.next(rec));
  EXPECT_TRUE(rec.gaze.valid);
  EXPECT_NEAR(
      std::atan2(rec.gaze.direction.y, std::hypot(rec.gaze.direction.x, rec.gaze.direction.z)) * aux::kDegPerRad, 5.0,
      1e-12);
  EXPECT_LT(rec.gaze.direction.x, 0.0);
  ASSERT_TRUE(reader.next(rec));
  EXPECT_FALSE(rec.gaze.valid);  // worn = 0
  EXPECT_EQ(rec.gaze.confidence, 0.0f);
  ASSERT_TRUE(reader.next(rec));
  EXPECT_FALSE(rec.gaze.valid);  // empty angles: no gaze, not an error
  EXPECT_FALSE(reader.next(rec));
}

TEST(PupilCloud, KeepsPupilsIdsPerSample) {
  std::istringstream in(std::string(kPupilCloudGazeHeader) + row(kUnixStartNs, "1,7,,0,0") +
                        row(kUnixStartNs + 1, "1,7,3,0,0") + row(kUnixStartNs + 2, "1,,,0,0"));
  PupilCloudReader reader(in, "gaze.csv");
  TraceRecord rec;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ids;
  while (reader.next(rec)) ids.emplace_back(reader.last_ids().fixation_id, reader.last_ids().blink_id);
  EXPECT_EQ(ids, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{7, 0}, {7, 3}, {0, 0}}));
}

TEST(PupilCloud, BlinkIntervalsMarkSamplesInvalidHalfOpen) {
  std::string text = kPupilCloudGazeHeader;
  for (int i = 0; i < 10; ++i) text += row(kUnixStartNs + i * 5'000'000);
  // Two blinks sharing a boundary (as blinks 18 and 19 of the sample export), given out of order.
  std::istringstream blinks_in(std::string(testing::kPupilCloudBlinksHeader) +
                               "s,r,2,1650316509618345895,1650316509628345895,10\n"
                               "s,r,1,1650316509608345895,1650316509618345895,10\n");
  const PupilCloudBlinks blinks = read_pupil_cloud_blinks(blinks_in, "blinks.csv");
  ASSERT_EQ(blinks.intervals.size(), 2u);
  EXPECT_EQ(blinks.intervals[0].start_ns, kUnixStartNs + 10'000'000);
  std::istringstream in(text);
  PupilCloudReader reader(in, "gaze.csv", {}, blinks);
  std::string valid;
  TraceRecord rec;
  while (reader.next(rec)) valid += rec.gaze.valid ? '1' : '0';
  EXPECT_EQ(valid, "1100001111");  // samples 2..5: start <= t < end of either blink
  EXPECT_EQ(reader.samples_in_blinks(), 4u);
}

TEST(PupilCloud, BlinksFilePairsWithTheGazeFile) {
  EXPECT_EQ(pupil_cloud_blinks_path("/x/y/gaze.csv"), "/x/y/blinks.csv");
  EXPECT_EQ(pupil_cloud_blinks_path("run3_gaze.csv"), "run3_blinks.csv");
  EXPECT_EQ(pupil_cloud_blinks_path("/d/pupil_cloud_invisible_gaze.csv"), "/d/pupil_cloud_invisible_blinks.csv");
  EXPECT_FALSE(pupil_cloud_blinks_path("/x/gaze_positions.csv").has_value());
  EXPECT_FALSE(pupil_cloud_blinks_path("_gaze.csv").has_value());
}

TEST(PupilCloud, ErrorsNameFileLineColumnAndColumnName) {
  const std::string h = kPupilCloudGazeHeader;
  const std::size_t t_col = std::string("s,r,").size() + 1;
  EXPECT_NE(error_of("section id,timestamp [ns],gaze x [px],gaze y [px]\n")
                .find("gaze.csv:1: missing required Pupil Cloud gaze.csv column(s): 'azimuth [deg]', "
                      "'elevation [deg]' (gaze x/y [px] alone"),
            std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs) + row(kUnixStartNs))
                .find("gaze.csv:3:" + std::to_string(t_col) + ": timestamp [ns]: " + std::to_string(kUnixStartNs) +
                      " repeats the previous sample's time"),
            std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs) + row(kUnixStartNs - 1)).find("gaze.csv:3:5: timestamp [ns]: "),
            std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs) + row(kUnixStartNs + 1, "2,,,0,0")).find("gaze.csv:3:"), std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs, "2,,,0,0")).find("worn: expected 0 or 1"), std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs, "1,x,,0,0")).find("fixation id: 'x' is not an integer"), std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs, "1,,0,0,0")).find("blink id: must be empty or an integer"),
            std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs, "1,,,200,0")).find("azimuth [deg]: must be in [-180, 180]"),
            std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs, "1,,,0,abc")).find("elevation [deg]: 'abc' is not a number"),
            std::string::npos);
  EXPECT_NE(error_of(h + row(-5)).find("timestamp [ns]: negative Unix time"), std::string::npos);
  EXPECT_NE(error_of(h + "s,r,1,2\n").find("gaze.csv:2: row has 4 fields, header has 10"), std::string::npos);
  EXPECT_NE(error_of(h + row(kUnixStartNs) + "s,r2," + std::to_string(kUnixStartNs + 1) + ",500,400,1,,,0,0\n")
                .find("gaze.csv:3:3: recording id: changes from 'r' to 'r2'"),
            std::string::npos);
  // Lenient: the repeated sample is skipped and listed, the next one read.
  const auto r = read_all(h + row(kUnixStartNs) + row(kUnixStartNs) + row(kUnixStartNs + 7), {}, {.lenient = true});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].gaze.t_ns, 7);
}

TEST(PupilCloud, BlinksFileErrorsNameThatFile) {
  auto error = [](const std::string& text) {
    std::istringstream in(text);
    try {
      read_pupil_cloud_blinks(in, "b.csv");
    } catch (const TraceError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error("blink id,start timestamp [ns]\n")
                .find("b.csv:1: missing required Pupil Cloud blinks.csv column(s): 'end timestamp [ns]'"),
            std::string::npos);
  EXPECT_NE(error(std::string(testing::kPupilCloudBlinksHeader) + "s,r,1,20,10,0\n")
                .find("b.csv:2:10: end timestamp [ns]: before start timestamp [ns]"),
            std::string::npos);
  EXPECT_NE(
      error(std::string(testing::kPupilCloudBlinksHeader) + "s,r,1,x,10,0\n").find("b.csv:2:7: start timestamp [ns]:"),
      std::string::npos);
}

TEST(TraceOpen, DetectsEachLayoutFromItsHeader) {
  using V = std::vector<std::string>;
  EXPECT_EQ(detect_trace_format(V{"section id", "timestamp [ns]", "azimuth [deg]"}, false), TraceFormat::pupil_cloud);
  EXPECT_EQ(detect_trace_format(V{"timestamp [ns]", "gaze x [px]", "gaze y [px]"}, false), TraceFormat::pupil_cloud);
  EXPECT_EQ(detect_trace_format(V{"gaze_timestamp", "confidence"}, false), TraceFormat::pupil);
  EXPECT_EQ(detect_trace_format(V{"n", "x", "y", "lx"}, false), TraceFormat::gazebasevr);
  EXPECT_EQ(detect_trace_format(V{"t_ns", "x", "y", "n"}, false), TraceFormat::gazelod);
  EXPECT_EQ(detect_trace_format(V{"timestamp [ns]", "azimuth [deg]"}, true), TraceFormat::gazelod);
  EXPECT_EQ(detect_trace_format(V{"what"}, false), TraceFormat::gazelod);
  EXPECT_EQ(parse_trace_format("pupil_cloud"), TraceFormat::pupil_cloud);
  EXPECT_EQ(parse_trace_format("auto"), TraceFormat::automatic);
}

TEST(TraceOpen, AutomaticOpensAPupilCloudFileWithItsBlinks) {
  const fs::path dir = temp_dir();
  const auto rows = testing::three_fixations_and_a_blink();
  write_text(dir / "gaze.csv", "\xEF\xBB\xBF" + testing::pupil_cloud_gaze_csv(rows));  // with a BOM
  write_text(dir / "blinks.csv", testing::pupil_cloud_blinks_csv(rows));
  auto s = open_trace((dir / "gaze.csv").string(), TraceFormat::automatic);
  EXPECT_EQ(opened_trace_format(*s), TraceFormat::pupil_cloud);
  std::size_t n = 0, invalid = 0, marked = 0;
  TraceRecord rec;
  while (s->next(rec)) {
    invalid += !rec.gaze.valid;
    marked += rows[n++].blink_id != 0;
  }
  EXPECT_EQ(n, rows.size());
  EXPECT_EQ(invalid, 30u);  // 0.15 s at 200 Hz
  EXPECT_EQ(invalid, marked);
  // The gazelod format still opens as before, and a bad blinks file is an error naming it.
  write_text(dir / "t.csv", "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n");
  EXPECT_EQ(opened_trace_format(*open_trace((dir / "t.csv").string(), TraceFormat::automatic)), TraceFormat::gazelod);
  write_text(dir / "blinks.csv", "blink id\n1\n");
  try {
    open_trace((dir / "gaze.csv").string(), TraceFormat::automatic);
    ADD_FAILURE() << "no error";
  } catch (const TraceError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "blinks.csv").string() + ":1: missing required"), std::string::npos)
        << e.what();
  }
}

TEST(TraceOpen, AutomaticReadsAPipeOnce) {
  const fs::path dir = temp_dir();
  const fs::path fifo = dir / "pipe_gaze.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string text = testing::pupil_cloud_gaze_csv(testing::three_fixations_and_a_blink());
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << text; });
  std::size_t n = 0;
  {
    auto s = open_trace(fifo.string(), TraceFormat::automatic);
    EXPECT_EQ(opened_trace_format(*s), TraceFormat::pupil_cloud);
    TraceRecord rec;
    while (s->next(rec)) ++n;
  }
  writer.join();
  EXPECT_EQ(n, testing::three_fixations_and_a_blink().size());
}

TEST(GazeAgreement, CountsKappaAndEventOverlap) {
  const std::vector<std::uint32_t> ours{0, 1, 1, 0, 2, 2, 0, 0, 0};
  const std::vector<std::uint32_t> reference{0, 5, 5, 5, 0, 7, 7, 0, 9};
  const EventAgreement a = compare_events(ours, reference);
  EXPECT_EQ(a.samples.both, 3u);
  EXPECT_EQ(a.samples.ours_only, 1u);
  EXPECT_EQ(a.samples.reference_only, 3u);
  EXPECT_EQ(a.samples.neither, 2u);
  EXPECT_NEAR(a.agreement, 5.0 / 9.0, 1e-15);
  // p_ours 4/9, p_reference 6/9: chance = (24 + 15) / 81; kappa = (45/81 - 39/81) / (42/81).
  ASSERT_TRUE(a.kappa.has_value());
  EXPECT_NEAR(*a.kappa, 6.0 / 42.0, 1e-15);
  EXPECT_EQ(a.ours_events, 2u);
  EXPECT_EQ(a.reference_events, 3u);
  EXPECT_EQ(a.reference_overlapped, 2u);  // 9 is missed
  EXPECT_EQ(a.ours_overlapped, 2u);
}

TEST(GazeAgreement, DegenerateInputsGiveNoNaN) {
  const std::vector<std::uint32_t> none(5, 0), all(5, 4);
  EXPECT_FALSE(compare_events(none, none).kappa.has_value());  // 0 / 0
  EXPECT_EQ(compare_events(none, none).agreement, 1.0);
  const EventAgreement opposite = compare_events(all, none);
  ASSERT_TRUE(opposite.kappa.has_value());
  EXPECT_EQ(*opposite.kappa, 0.0);
  EXPECT_EQ(opposite.agreement, 0.0);
  const EventAgreement empty = compare_events({}, {});
  EXPECT_EQ(empty.samples.total(), 0u);
  EXPECT_FALSE(empty.kappa.has_value());
  EXPECT_THROW(compare_events(none, std::span<const std::uint32_t>(all).subspan(0, 2)), std::invalid_argument);
}

TEST(TraceStatsAgreement, OursAgreeWithPupilsFixationsAndBlinks) {
  const fs::path dir = temp_dir();
  const auto rows = testing::three_fixations_and_a_blink();
  write_text(dir / "rec_gaze.csv", testing::pupil_cloud_gaze_csv(rows));
  write_text(dir / "rec_blinks.csv", testing::pupil_cloud_blinks_csv(rows));
  auto s = open_trace((dir / "rec_gaze.csv").string(), TraceFormat::automatic);
  const TraceStats st = compute_trace_stats(*s);
  ASSERT_TRUE(st.agreement.has_value());
  const ReferenceAgreement& a = *st.agreement;
  EXPECT_EQ(a.blinks_file, (dir / "rec_blinks.csv").string());
  EXPECT_EQ(a.blinks_in_file, 1u);
  EXPECT_EQ(a.samples_in_blinks, 30u);
  for (const ClassifierAgreement* c : {&a.ivt, &a.ivdt}) {
    ASSERT_TRUE(c->fixation && c->blink);
    EXPECT_EQ(c->fixation->reference_events, 3u);
    EXPECT_EQ(c->fixation->ours_events, 3u);
    EXPECT_EQ(c->fixation->reference_overlapped, 3u);
    EXPECT_GT(*c->fixation->kappa, 0.7);
    EXPECT_GT(c->fixation->agreement, 0.9);
    // The blink samples are invalid from the blinks file: both classifiers call them blinks.
    EXPECT_EQ(c->blink->samples.both, 30u);
    EXPECT_EQ(c->blink->samples.reference_only, 0u);
    EXPECT_EQ(c->blink->ours_events, 1u);
  }
  EXPECT_EQ(a.ivt.blink->samples.ours_only, 0u);
  EXPECT_EQ(*a.ivt.blink->kappa, 1.0);

  // Without the blinks file (a pipe, a renamed export) the gaze's own blink id marks the same
  // 30 samples. They were read valid: the still eye gave no sign of the blink, ours found none
  // (kappa 0) and the fixations on either side of it merged.
  fs::remove(dir / "rec_blinks.csv");
  auto s2 = open_trace((dir / "rec_gaze.csv").string(), TraceFormat::automatic);
  const TraceStats st2 = compute_trace_stats(*s2);
  ASSERT_TRUE(st2.agreement.has_value());
  EXPECT_TRUE(st2.agreement->blinks_file.empty());
  EXPECT_EQ(st2.agreement->samples_in_blinks, 30u);
  EXPECT_EQ(st2.agreement->ivt.blink->ours_events, 1u);
  EXPECT_EQ(*st2.agreement->ivt.blink->kappa, 1.0);
  EXPECT_EQ(st2.agreement->ivt.fixation->ours_events, 3u);
  // Other layouts carry no reference.
  write_text(dir / "t.csv", "t_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n");
  auto s3 = open_trace((dir / "t.csv").string(), TraceFormat::automatic);
  EXPECT_FALSE(compute_trace_stats(*s3).agreement.has_value());
}

}  // namespace
}  // namespace gazelod::gaze
