// SPDX-License-Identifier: Apache-2.0
// Recording a scenario as a gazelod trace and reading it back (gaze/trace_reader.hpp); and
// head_track replaying a recorded head: a round trip through the trace format.
#include "gaze/trace_error.hpp"
#include "gaze/trace_reader.hpp"
#include "sim/record_trace.hpp"
#include "tests/sim/sim_test_util.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::sim {
namespace {

using namespace test;
constexpr std::int64_t kMs = 1'000'000;

std::vector<gaze::TraceRecord> read_back(const std::string& text) {
  std::istringstream in(text);
  gaze::TraceReader reader(in, "recorded.csv");
  std::vector<gaze::TraceRecord> out;
  gaze::TraceRecord r;
  while (reader.next(r)) out.push_back(r);
  return out;
}

TEST(RecordTrace, OneRowPerTrackerSampleWithTheHeadAtThatTime) {
  nlohmann::json j = base_scenario({{{"type", "head_sweep"}, {"yaw_amplitude_deg", 20}},
                                    {{"type", "saccades"}},
                                    {{"type", "tracker_rate"}, {"rate_hz", 60}},
                                    {{"type", "tracker_latency"}, {"latency_ms", 20}},
                                    {{"type", "blinks"}, {"rate_per_min", 30}}});
  j["duration_s"] = 4;
  j["frame_rate_hz"] = 90;
  Simulator sim = make_sim(j);
  std::ostringstream out;
  const RecordStats st = record_trace(sim, out);
  const std::vector<gaze::TraceRecord> rows = read_back(out.str());
  ASSERT_EQ(rows.size(), st.rows);
  // 90 Hz questions of a 60 Hz tracker for 4 s: every sample taken in [0, 4 s - 20 ms) once.
  EXPECT_NEAR(double(rows.size()), 60 * 3.98, 1.0);
  EXPECT_EQ(rows.front().gaze.t_ns, 0);
  EXPECT_EQ(rows.front().gaze.valid, sim.tracker_at(20 * kMs).valid);
  EXPECT_GT(st.invalid_rows, 0u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const gaze::TraceRecord& r = rows[i];
    if (i > 0) {
      EXPECT_GT(r.gaze.t_ns, rows[i - 1].gaze.t_ns);
    }
    const gaze::GazeSample expect = sim.tracker_at(r.gaze.t_ns + 20 * kMs);
    EXPECT_EQ(expect.t_ns, r.gaze.t_ns);
    EXPECT_EQ(r.gaze.valid, expect.valid);
    if (expect.valid) {
      EXPECT_LT(angle_deg(r.gaze.direction, expect.direction), 1e-9);
    }
    ASSERT_TRUE(r.has_head);
    const glm::dquat q = sim.head_at(r.gaze.t_ns).orientation;
    EXPECT_NEAR(std::abs(glm::dot(q, r.head.orientation)), 1.0, 1e-12);
  }
}

// A recording is bounded before it starts (1e11 rows ran on, unbounded), and one stopped on the
// way (Ctrl-C in `gazelod scenario record`) leaves no file, partial or temporary.
TEST(RecordTrace, BoundedUpFrontAndAStoppedOneLeavesNoFile) {
  Simulator sim = make_sim(base_scenario(nlohmann::json::array()));
  RecordOptions o;
  o.duration_s = 1e6;
  o.step_hz = 1e5;
  std::ostringstream out;
  EXPECT_THROW(record_trace(sim, out, o), std::invalid_argument);
  EXPECT_TRUE(out.str().empty());
  const std::string dir = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/record_stopped";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  o.duration_s = 100;
  o.step_hz = 2000;  // 200 000 steps: asked three times
  int asked = 0;
  o.progress = [&](double done_s, double total_s) {
    EXPECT_LT(done_s, total_s);
    return ++asked < 2;
  };
  EXPECT_THROW(record_trace_file(sim, dir + "/t.csv", o), RecordStopped);
  EXPECT_EQ(asked, 2);
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a stopped recording left a file";
}

TEST(RecordTrace, HeadTrackReplaysARecordedHead) {
  nlohmann::json j = base_scenario({{{"type", "head_sweep"},
                                     {"yaw_amplitude_deg", 30},
                                     {"yaw_period_s", 3},
                                     {"pitch_amplitude_deg", 10},
                                     {"pitch_period_s", 2}}});
  j["duration_s"] = 3;
  j["frame_rate_hz"] = 500;  // dense rows, so interpolation error is small
  Simulator original = make_sim(j);
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/recorded_head.csv";
  {
    std::ofstream out(path);
    record_trace(original, out);
  }
  nlohmann::json replay = base_scenario({{{"type", "head_track"}, {"file", path}}});
  Simulator sim = make_sim(replay);
  for (std::int64_t t = 0; t < 2990 * kMs; t += 37 * kMs) {
    const HeadState a = original.head_at(t), b = sim.head_at(t);
    const glm::dquat d = glm::conjugate(a.orientation) * b.orientation;
    EXPECT_LT(2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w)), 1e-5) << t;
    // Segment velocity of a 2 ms segment vs the script's instantaneous one.
    EXPECT_LT(glm::length(a.angular_velocity_rad_s - b.angular_velocity_rad_s), 0.01) << t;
  }
  // Before and after: held.
  EXPECT_EQ(sim.head_at(10'000 * kMs).angular_velocity_rad_s, glm::dvec3(0.0));
}

// "relative": the recorded head's motion from its first pose, that pose's heading turned to -Z
// and its position to the scenario's head; "start_s": when the first row plays.
TEST(RecordTrace, HeadTrackRelativeTurnsTheFirstHeadingForwardAndKeepsTheMotion) {
  const double deg = std::acos(-1.0) / 180.0;
  const glm::dvec3 up(0, 1, 0), right(1, 0, 0), forward(0, 0, -1);
  // Row 0: 40 deg left, pitched 10 deg down, at (3, 1.7, -2); row 1 (1 s later): 20 deg further
  // left, moved 1 m along the recording's -Z.
  const glm::dquat q0 = glm::angleAxis(40 * deg, up) * glm::angleAxis(-10 * deg, right);
  const glm::dquat q1 = glm::angleAxis(60 * deg, up) * glm::angleAxis(-10 * deg, right);
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/relative_head.csv";
  {
    std::ofstream out(path);
    out.precision(17);
    out << "# gazelod-trace "
           "1\nt_ns,gaze_x,gaze_y,gaze_z,valid,head_qw,head_qx,head_qy,head_qz,head_px,head_py,head_pz\n";
    out << "5000000000,0,0,-1,1," << q0.w << "," << q0.x << "," << q0.y << "," << q0.z << ",3,1.7,-2\n";
    out << "6000000000,0,0,-1,1," << q1.w << "," << q1.x << "," << q1.y << "," << q1.z << ",3,1.7,-3\n";
  }
  const glm::dvec3 home = make_sim(base_scenario()).head_at(0).position_m;
  Simulator sim =
      make_sim(base_scenario({{{"type", "head_track"}, {"file", path}, {"relative", true}, {"start_s", 0.5}}}));
  const auto heading_deg = [&](const glm::dquat& q) {
    const glm::dvec3 f = q * forward;
    return std::atan2(-f.x, -f.z) / deg;
  };
  const auto pitch_deg = [&](const glm::dquat& q) {
    const glm::dvec3 f = q * forward;
    return std::atan2(f.y, std::hypot(f.x, f.z)) / deg;
  };
  const HeadState first = sim.head_at(500 * kMs), later = sim.head_at(1500 * kMs), before = sim.head_at(0);
  EXPECT_NEAR(heading_deg(first.orientation), 0.0, 1e-9);  // the first pose faces -Z
  EXPECT_NEAR(pitch_deg(first.orientation), -10.0, 1e-9);  // and keeps its pitch
  EXPECT_LT(glm::length(first.position_m - home), 1e-12);
  EXPECT_NEAR(heading_deg(later.orientation), 20.0, 1e-9);  // turned 20 deg left since
  EXPECT_NEAR(pitch_deg(later.orientation), -10.0, 1e-9);
  // The 1 m step along the recording's -Z was 40 deg right of the first heading; so it is here.
  const glm::dvec3 step = later.position_m - home;
  EXPECT_NEAR(step.x, std::sin(40 * deg), 1e-9);
  EXPECT_NEAR(step.y, 0.0, 1e-9);
  EXPECT_NEAR(step.z, -std::cos(40 * deg), 1e-9);
  EXPECT_NEAR(heading_deg(before.orientation), 0.0, 1e-9);  // held before start_s
  // Without "relative" the same track plays in the recording's own frame.
  Simulator absolute = make_sim(base_scenario({{{"type", "head_track"}, {"file", path}, {"start_s", 0.5}}}));
  EXPECT_NEAR(heading_deg(absolute.head_at(500 * kMs).orientation), 40.0, 1e-9);
}

TEST(RecordTrace, HeadTrackErrorsNameTheParameter) {
  nlohmann::json j = base_scenario({{{"type", "head_track"}, {"file", "/nonexistent/head.csv"}}});
  try {
    (void)load_scenario_json(j.dump(), "s.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("s.json: effects[0].file: "));
  }
  j["effects"][0]["file"] = "x.csv";
  j["effects"][0]["format"] = "tobii9";
  EXPECT_THROW((void)load_scenario_json(j.dump(), "s.json"), ScenarioError);
}

}  // namespace
}  // namespace gazelod::sim
