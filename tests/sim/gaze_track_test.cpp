// SPDX-License-Identifier: Apache-2.0
// gaze_track: a recorded gaze replayed as the true eye, with the truth's saccades and blinks
// labelled from the recording. A round trip: a scripted scenario (reflex-held fixations and
// saccades through a head sweep, blinks) is recorded densely and without tracker error, then
// replayed; the replayed truth must match the script's.
#include "sim/record_trace.hpp"
#include "tests/sim/sim_test_util.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace gazelod::sim {
namespace {

using namespace test;
constexpr std::int64_t kMs = 1'000'000;

nlohmann::json scripted() {
  nlohmann::json j = base_scenario({{{"type", "head_sweep"},
                                     {"yaw_amplitude_deg", 25},
                                     {"yaw_period_s", 3},
                                     {"pitch_amplitude_deg", 5},
                                     {"pitch_period_s", 2}},
                                    {{"type", "saccades"},
                                     {"fixation_min_ms", 200},
                                     {"fixation_max_ms", 400},
                                     {"amplitude_min_deg", 4},
                                     {"amplitude_max_deg", 15}},
                                    {{"type", "vor"}},
                                    {{"type", "tracker_rate"}, {"rate_hz", 500}},
                                    {{"type", "blinks"}, {"rate_per_min", 20}, {"duration_ms", 150}}});
  j["duration_s"] = 6;
  j["frame_rate_hz"] = 500;  // one row per tracker sample
  return j;
}

std::string record(Simulator& sim, const std::string& name) {
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/" + name;
  std::ofstream out(path);
  record_trace(sim, out);
  return path;
}

TEST(GazeTrack, ReplaysTheRecordedEyeWithItsSaccadesAndBlinks) {
  Simulator original = make_sim(scripted());
  const std::string path = record(original, "gaze_track_round_trip.csv");
  nlohmann::json replay = base_scenario({{{"type", "head_track"}, {"file", path}},
                                         {{"type", "gaze_track"}, {"file", path}},
                                         {{"type", "tracker_rate"}, {"rate_hz", 500}}});
  replay["duration_s"] = 6;
  Simulator sim = make_sim(replay);

  int end_frames = 0, end_agree = 0, in_blink_frames = 0, in_blink_agree = 0;
  int frames = 0, saccade_agree = 0, saccades_original = 0, saccades_seen = 0, blink_frames = 0, blink_agree = 0;
  bool was_in_saccade = false, seen_this_one = false;
  for (std::int64_t t = 20 * kMs; t < 5980 * kMs; t += kMs) {
    const EyeTruth a = original.eye_truth_at(t), b = sim.eye_truth_at(t);
    ++frames;
    saccade_agree += a.in_saccade == b.in_saccade ? 1 : 0;
    // (A saccade made with the eye closed is not in the recording: not counted.)
    if (a.in_saccade && !was_in_saccade && !a.in_blink) ++saccades_original, seen_this_one = false;
    if (a.in_saccade && b.in_saccade && !seen_this_one) ++saccades_seen, seen_this_one = true;
    was_in_saccade = a.in_saccade;
    if (a.in_blink) {
      ++blink_frames;
      blink_agree += b.in_blink ? 1 : 0;
    }
    // Outside saccades and blinks the direction is the script's (interpolated between 2 ms rows).
    if (!a.in_saccade && !a.in_blink && !b.in_blink) {
      const double err = angle_deg(original.true_gaze_at(t).direction, sim.true_gaze_at(t).direction);
      EXPECT_LT(err, 0.05) << t;
    }
    // The last saccade's end: within a few samples of the script's, except after a saccade made
    // with the eye closed, which no recording sees (the blinks here are the script's own).
    if (a.last_saccade_end_ns > 0 && b.last_saccade_end_ns > 0 && !a.in_saccade && !b.in_saccade && !a.in_blink) {
      if (!original.eye_truth_at(a.last_saccade_end_ns - kMs).in_blink) {
        ++end_frames;
        end_agree += std::abs(a.last_saccade_end_ns - b.last_saccade_end_ns) < 12 * kMs ? 1 : 0;
      } else if (!b.in_blink) {  // (the replay reopens at its first valid row, up to 2 ms later)
        // Made with the eye closed: the replay ends it where the eye reopens, after the
        // script's end and within the blink's 150 ms.
        ++in_blink_frames;
        const std::int64_t late = b.last_saccade_end_ns - a.last_saccade_end_ns;
        in_blink_agree += late >= 0 && late <= 150 * kMs ? 1 : 0;
      }
    }
  }
  ASSERT_GT(saccades_original, 10);
  EXPECT_EQ(saccades_seen, saccades_original) << "every scripted saccade is labelled in the replay";
  EXPECT_GT(saccade_agree, frames * 97 / 100) << "the labels agree but for a few ms at each end";
  ASSERT_GT(end_frames, 4000);
  EXPECT_GT(end_agree, end_frames * 97 / 100);
  ASSERT_GT(in_blink_frames, 50) << "a scripted saccade made in a blink";
  EXPECT_EQ(in_blink_agree, in_blink_frames);
  ASSERT_GT(blink_frames, 100);
  EXPECT_GT(blink_agree, blink_frames * 97 / 100);

  // A tracker sample taken inside a recorded blink is invalid, as the recording was.
  int invalid = 0, in_blink = 0;
  for (std::int64_t t = 0; t < 6000 * kMs; t += 2 * kMs) {
    const gaze::GazeSample s = sim.tracker_at(t);
    if (sim.eye_truth_at(s.t_ns).in_blink) {
      ++in_blink;
      invalid += s.valid ? 0 : 1;
    }
  }
  ASSERT_GT(in_blink, 50);
  EXPECT_EQ(invalid, in_blink);
}

// In the head a reflex-held fixation through a fast head sweep (50 deg/s at its peak) moves like
// a small saccade; the labels come from the world gaze, so the replayed sweep has none.
TEST(GazeTrack, AReflexHeldTurnIsNoSaccade) {
  nlohmann::json j = base_scenario({{{"type", "head_sweep"}, {"yaw_amplitude_deg", 8}, {"yaw_period_s", 1}},
                                    {{"type", "vor"}},
                                    {{"type", "tracker_rate"}, {"rate_hz", 500}}});
  j["duration_s"] = 3;
  j["frame_rate_hz"] = 500;
  Simulator original = make_sim(j);
  const std::string path = record(original, "gaze_track_turn.csv");
  nlohmann::json replay =
      base_scenario({{{"type", "head_track"}, {"file", path}}, {{"type", "gaze_track"}, {"file", path}}});
  replay["duration_s"] = 3;
  Simulator sim = make_sim(replay);
  for (std::int64_t t = 100 * kMs; t < 2900 * kMs; t += 5 * kMs) {
    ASSERT_FALSE(original.eye_truth_at(t).in_saccade);
    EXPECT_FALSE(sim.eye_truth_at(t).in_saccade) << t;
  }
}

// A hand-written trace: the eye at A until 100 ms, closed from 110 to 290 ms, open at B (20 deg
// right) from 300 ms; at 400 ms an invalid row and a valid one share a time.
TEST(GazeTrack, HoldsThroughABlinkAndEndsTheSaccadeInItWhereTheEyeReopens) {
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/gaze_track_blink.csv";
  const double b_rad = 20.0 * 3.14159265358979323846 / 180.0;
  const glm::dvec3 a(0, 0, -1), b(std::sin(b_rad), 0, -std::cos(b_rad));
  {
    std::ofstream out(path);
    out << "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z,valid\n";
    for (int ms = 0; ms <= 600; ms += 10) {
      const glm::dvec3 d = ms < 300 ? a : b;
      if (ms == 400) out << ms * kMs << ",0,0,-1,0\n";  // the invalid twin comes first
      out << ms * kMs << "," << d.x << "," << d.y << "," << d.z << "," << (ms > 100 && ms < 300 ? 0 : 1) << "\n";
    }
  }
  Simulator sim = make_sim(base_scenario({{{"type", "gaze_track"}, {"file", path}}}));
  EXPECT_LT(angle_deg(sim.true_gaze_at(50 * kMs).direction, a), 1e-9);
  // Between the last valid row and the blink, and in it: held, not drifting toward B.
  EXPECT_LT(angle_deg(sim.true_gaze_at(105 * kMs).direction, a), 1e-9);
  EXPECT_LT(angle_deg(sim.true_gaze_at(200 * kMs).direction, a), 1e-9);
  EXPECT_TRUE(sim.eye_truth_at(200 * kMs).in_blink);
  EXPECT_FALSE(sim.eye_truth_at(200 * kMs).in_saccade);
  EXPECT_LT(angle_deg(sim.true_gaze_at(305 * kMs).direction, b), 1e-3);  // (6 digits in the file)
  // The eye reopened 20 deg away: a saccade in the blink, over at 300 ms.
  EXPECT_FALSE(sim.eye_truth_at(300 * kMs).in_blink);
  EXPECT_EQ(sim.eye_truth_at(350 * kMs).last_saccade_end_ns, 300 * kMs);
  EXPECT_EQ(sim.eye_truth_at(250 * kMs).last_saccade_end_ns, INT64_MIN) << "not before it reopens";
  // The duplicate's valid row wins: no blink at 400 ms, and a tracker sample there is valid.
  EXPECT_FALSE(sim.eye_truth_at(400 * kMs).in_blink);
  EXPECT_TRUE(sim.tracker_at(400 * kMs).valid);

  // A blink the eye reopens from where it closed holds no saccade.
  nlohmann::json near = base_scenario({{{"type", "gaze_track"}, {"file", path}, {"blink_saccade_deg", 25}}});
  EXPECT_EQ(make_sim(near).eye_truth_at(350 * kMs).last_saccade_end_ns, INT64_MIN);
}

// A trace with head columns but no valid pose: no world to label in, so the head it is (the
// saccades are still found; before, every world sample was invalid and none was).
TEST(GazeTrack, HeadColumnsWithoutAPoseAreLabelledInTheHead) {
  nlohmann::json j = scripted();
  j["effects"].erase(0);  // no head sweep: head and world agree
  Simulator original = make_sim(j);
  const std::string path = record(original, "gaze_track_no_pose.csv");
  std::ifstream in(path);
  std::string text, line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#' && line.back() == '1' && line.find("t_ns") == std::string::npos)
      line.back() = '0';  // head_valid, the last column
    text += line + "\n";
  }
  in.close();
  std::ofstream(path) << text;
  ASSERT_NE(text.find("head_valid"), std::string::npos);
  Simulator sim = make_sim(base_scenario({{{"type", "gaze_track"}, {"file", path}}}));
  int frames = 0, agree = 0, saccade_frames = 0;
  for (std::int64_t t = 20 * kMs; t < 5980 * kMs; t += kMs) {
    const EyeTruth a = original.eye_truth_at(t), b = sim.eye_truth_at(t);
    if (a.in_blink) continue;
    ++frames;
    agree += a.in_saccade == b.in_saccade ? 1 : 0;
    saccade_frames += b.in_saccade ? 1 : 0;
  }
  EXPECT_GT(saccade_frames, 200);
  EXPECT_GT(agree, frames * 97 / 100);
}

TEST(GazeTrack, ABadFileIsRefusedAtTheEffect) {
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/gaze_track_invalid.csv";
  {
    std::ofstream out(path);
    out << "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z,valid\n0,0,0,-1,0\n1000000,0,0,-1,0\n";
  }
  try {
    make_sim(base_scenario({{{"type", "gaze_track"}, {"file", path}}}));
    FAIL() << "a trace without a valid sample was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("no valid gaze sample"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("effects[0]"), std::string::npos) << e.what();
  }
  try {
    make_sim(base_scenario({{{"type", "gaze_track"}, {"file", path + ".missing"}}}));
    FAIL() << "a missing file was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gazelod::sim
