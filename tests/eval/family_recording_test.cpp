// SPDX-License-Identifier: Apache-2.0
// gazelod eval family --recording: a recorded person's eyes and head under the family's
// displays, trackers and fields (apps/gazelod/eval/family_recording.hpp). The scenario rewrite
// on its own, then end to end on the Vive Pro Eye log in ../shared/data/gaze (evaluation data,
// not in the repository: skipped without it, required under CI).
#include "apps/gazelod/eval/family.hpp"
#include "apps/gazelod/eval/family_recording.hpp"
#include "sim/scenario_family.hpp"
#include "tests/eval/eval_cli.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace gazelod::cli {
namespace {

namespace fs = std::filesystem;
using testing::Result;

std::set<std::string> effect_types(const nlohmann::json& scenario) {
  std::set<std::string> types;
  for (const nlohmann::json& e : scenario.at("effects")) types.insert(e.at("type").get<std::string>());
  return types;
}

// Seed 2002: head sweeps and turns, eyes carried, blinks, a 142 Hz tracker 33 ms late.
TEST(FamilyRecording, TheSeedKeepsItsTrackerDisplayAndFieldAndTakesTheRecordedEyesAndHead) {
  const sim::FamilyScenario f = sim::family_scenario(2002);
  const nlohmann::json before = nlohmann::json::parse(f.json);
  ASSERT_TRUE(effect_types(before).count("head_sweep") && effect_types(before).count("saccades") &&
              effect_types(before).count("blinks"))
      << f.json;
  FamilyRecording rec;
  rec.path = "/data/vive.csv";
  rec.format = gaze::TraceFormat::sranipal;
  rec.has_head = true;
  rec.span_s = 13.86;
  const nlohmann::json after = nlohmann::json::parse(with_recording(f.json, rec));
  EXPECT_EQ(effect_types(after),
            (std::set<std::string>{"head_track", "gaze_track", "tracker_rate", "tracker_latency", "tracker_noise"}));
  EXPECT_EQ(after.at("effects")[0].at("file"), "/data/vive.csv");
  EXPECT_EQ(after.at("effects")[0].at("format"), "sranipal");
  EXPECT_TRUE(after.at("effects")[0].at("relative").get<bool>());
  EXPECT_DOUBLE_EQ(after.at("duration_s").get<double>(), 13.8) << "no longer than the recording";
  for (const char* kept : {"display", "scene", "runtime", "seed"}) EXPECT_EQ(after.at(kept), before.at(kept)) << kept;
  // The tracker's effects are the seed's own, values included.
  for (const nlohmann::json& e : before.at("effects")) {
    if (e.at("type").get<std::string>().starts_with("tracker_")) {
      EXPECT_NE(std::find(after.at("effects").begin(), after.at("effects").end(), e), after.at("effects").end()) << e;
    }
  }

  rec.has_head = false;  // a head-worn tracker without poses: gaze only, the head still
  EXPECT_EQ(effect_types(nlohmann::json::parse(with_recording(f.json, rec))).count("head_track"), 0u);
  EXPECT_DOUBLE_EQ(recording_duration_s(20.0, rec), 13.8);
  rec.span_s = 42.96;
  EXPECT_DOUBLE_EQ(recording_duration_s(20.0, rec), 20.0);

  EXPECT_EQ(recording_summary("sweeps+turns, eyes carried, pursuit 12 deg/s, questpro, 142 Hz 33 ms 0.56 deg, "
                              "open field",
                              rec),
            "recorded eyes, still head, questpro, 142 Hz 33 ms 0.56 deg, open field");
  rec.has_head = true;
  EXPECT_EQ(recording_summary("still, fixations, psvr2, 120 Hz 35 ms 0.80 deg, deep field", rec),
            "recorded eyes and head, psvr2, 120 Hz 35 ms 0.80 deg, deep field");
}

// A walking seed's walk is the field coming toward the viewer: with a recorded head the field
// stands still (the pursuit target keeps its own crossing motion).
TEST(FamilyRecording, AWalkingSeedStopsWalking) {
  const sim::FamilyScenario f = sim::family_scenario(2001);
  ASSERT_TRUE(f.summary.starts_with("walk ")) << f.summary;
  const nlohmann::json before = nlohmann::json::parse(f.json);
  const double walk = before.at("scene").at("generators")[0].at("forward_speed_m_s").get<double>();
  ASSERT_GT(walk, 0.5);
  FamilyRecording rec;
  rec.path = "/data/vive.csv";
  rec.has_head = true;
  rec.span_s = 13.86;
  const nlohmann::json after = nlohmann::json::parse(with_recording(f.json, rec));
  EXPECT_EQ(after.at("scene").at("generators")[0].at("forward_speed_m_s").get<double>(), 0.0);
  const nlohmann::json& v0 = before.at("scene").at("objects")[0].at("velocity_m_s");
  const nlohmann::json& v1 = after.at("scene").at("objects")[0].at("velocity_m_s");
  EXPECT_DOUBLE_EQ(v0[2].get<double>(), -walk);
  EXPECT_DOUBLE_EQ(v1[2].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(v1[0].get<double>(), v0[0].get<double>());
  EXPECT_EQ(recording_summary(f.summary, rec).find("walk"), std::string::npos);
}

// What read_family_recording makes of odd but readable traces.
TEST(FamilyRecording, TheRecordingsSpanIsItsValidSamplesAndItsHeadItsPoses) {
  const fs::path dir = testing::scratch("family-recording.");
  const auto write = [&](const std::string& name, const std::string& rows, bool head) {
    const fs::path p = dir / name;
    std::ofstream(p) << "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z,valid"
                     << (head ? ",head_qw,head_qx,head_qy,head_qz,head_px,head_py,head_pz,head_valid" : "") << "\n"
                     << rows;
    return p.string();
  };
  // Negative times, 1.5 s apart.
  const FamilyRecording neg = read_family_recording(
      write("neg.csv", "-5000000000,0,0,-1,1\n-3500000000,0,0,-1,1\n", false), gaze::TraceFormat::gazelod);
  EXPECT_DOUBLE_EQ(neg.span_s, 1.5);
  EXPECT_FALSE(neg.has_head);
  // One valid sample, or valid samples 10 ms apart and 20 s of invalid ones after them.
  EXPECT_THROW(
      read_family_recording(write("one.csv", "0,0,0,-1,1\n1000000000,0,0,-1,0\n", false), gaze::TraceFormat::gazelod),
      UsageError);
  try {
    read_family_recording(write("tail.csv", "0,0,0,-1,1\n10000000,0,0,-1,1\n20000000000,0,0,-1,0\n", false),
                          gaze::TraceFormat::gazelod);
    FAIL() << "a recording that is all blink was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("valid samples span less than 1 s"), std::string::npos) << e.what();
  }
  // Head columns, no valid pose: no head to replay.
  const FamilyRecording unposed = read_family_recording(
      write("unposed.csv", "0,0,0,-1,1,1,0,0,0,0,0,0,0\n2000000000,0,0,-1,1,1,0,0,0,0,0,0,0\n", true),
      gaze::TraceFormat::gazelod);
  EXPECT_FALSE(unposed.has_head);
  const FamilyRecording posed = read_family_recording(
      write("posed.csv", "0,0,0,-1,1,1,0,0,0,0,0,0,1\n2000000000,0,0,-1,1,1,0,0,0,0,0,0,1\n", true),
      gaze::TraceFormat::gazelod);
  EXPECT_TRUE(posed.has_head);
}

TEST(FamilyRecording, AnUnreadableRecordingIsRefusedBeforeAnySeed) {
  const fs::path dir = testing::scratch("family-recording.");
  testing::use_simulated_runtime();
  const Result missing = testing::cli({"eval", "family", "--seeds", "1-2", "--recording", (dir / "none.csv").string(),
                                       "--out", (dir / "out").string()});
  EXPECT_EQ(missing.rc, 2) << missing.out;  // bad input, as run --trace (it was 1)
  EXPECT_NE(missing.err.find("--recording"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("none.csv"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find("[1/2]"), std::string::npos) << "no seed ran\n" << missing.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "family.json"));

  const fs::path bad = dir / "bad.csv";
  std::ofstream(bad) << "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z,valid\n0,0,0,-1,1\nx,0,0,-1,1\n";
  const Result broken =
      testing::cli({"eval", "family", "--seeds", "1-2", "--recording", bad.string(), "--out", (dir / "out").string()});
  EXPECT_EQ(broken.rc, 2);
  EXPECT_NE(broken.err.find("bad.csv:4"), std::string::npos) << "file:line\n" << broken.err;

  // A folder where the recording file goes: bad input too (it was 1, run --trace DIR 2).
  const Result folder =
      testing::cli({"eval", "family", "--seeds", "1-2", "--recording", dir.string(), "--out", (dir / "out").string()});
  EXPECT_EQ(folder.rc, 2);
  EXPECT_NE(folder.err.find("is a directory"), std::string::npos) << folder.err;

  const Result format = testing::cli({"eval", "family", "--seeds", "1-2", "--recording", bad.string(),
                                      "--recording-format", "tobii", "--out", (dir / "out").string()});
  EXPECT_EQ(format.rc, 2);
  EXPECT_NE(format.err.find("--recording-format"), std::string::npos) << format.err;

  const Result empty =
      testing::cli({"eval", "family", "--seeds", "1-2", "--recording", "", "--out", (dir / "out").string()});
  EXPECT_EQ(empty.rc, 2) << "refused, not ignored";
  EXPECT_NE(empty.err.find("--recording"), std::string::npos) << empty.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "family.json"));
}

// The Vive Pro Eye log (13.9 s, head poses) under ten held-out seeds' trackers: over 2000-2099
// measured 0.011 % degraded (median; worst 0.313 %), triangles 1.08, switches 0.14, all 100
// within the three targets (docs/evaluation.md, "Real eyes"); here the medians over 2000-2009
// against the targets.
TEST(FamilyRecording, ViveProEyeUnderTheFamilysTrackers) {
  const fs::path file =
      fs::path(GAZELOD_SOURCE_DIR) / ".." / "shared" / "data" / "gaze" / "htc_vive_pro_eye_unity_log.csv";
  if (!fs::is_regular_file(file)) GAZELOD_SKIP_OR_FAIL("no " << file << " (../shared/data/gaze)");
  const fs::path dir = testing::scratch("family-recording.");
  testing::use_simulated_runtime();
  // Size and eccentricity by default with a recording (its noise is no eye's velocity).
  const Result r = testing::cli({"eval", "family", "--seeds", "2000-2009", "--recording", file.string(), "--work",
                                 (dir / "work").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  std::ifstream in(dir / "out" / "family.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const std::string abs = fs::absolute(file).lexically_normal().string();
  EXPECT_EQ(j.at("settings_changed")[0], "criteria=size,eccentricity");
  EXPECT_EQ(j.at("settings_changed")[1], "recording=" + abs);
  // Another run of the same seeds with the family's own eyes is other scenarios: refused.
  const Result own = testing::cli({"eval", "family", "--seeds", "2000-2009", "--duration", "13.8", "--out",
                                   (dir / "own").string(), "--against", (dir / "out" / "family.json").string()});
  EXPECT_EQ(own.rc, 2);
  EXPECT_NE(own.err.find("its eyes were " + abs + ", this run's the family's own"), std::string::npos) << own.err;
  EXPECT_DOUBLE_EQ(j.at("duration_s").get<double>(), 13.8);
  ASSERT_EQ(j.at("members").size(), 10u);
  for (const nlohmann::json& m : j.at("members"))
    EXPECT_TRUE(m.at("scenario").get<std::string>().starts_with("recorded eyes and head, ")) << m.at("scenario");
  std::ifstream seed(dir / "work" / "seed-2000" / "family.json");
  EXPECT_TRUE(effect_types(nlohmann::json::parse(seed)).count("gaze_track"));
  const nlohmann::json& d = j.at("distribution");
  EXPECT_LE(d.at("visible degradations (fixation object-frames)").at("median").get<double>(), kTargetDegradedShare);
  EXPECT_LE(d.at("triangles drawn / oracle").at("median").get<double>(), kTargetTriangleRatio);
  EXPECT_LE(d.at("switches per object-second outside suppression").at("median").get<double>(),
            kTargetSwitchesPerObjectS);
  EXPECT_GE(j.at("within_all_targets").get<int>(), 9);
}

}  // namespace
}  // namespace gazelod::cli
