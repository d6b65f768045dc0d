// SPDX-License-Identifier: Apache-2.0
// The visibility audit on real eye movements: the two recordings in ../shared/data/gaze (not
// part of the repository; skipped without them, required under CI) replayed as the true eye
// (gaze_track; the Vive Pro Eye log's head too, head_track), seen through a simulated 120 Hz
// tracker 50 ms late with 0.5 deg of noise, and the plugin held to the targets against
// the oracle at the recorded gaze. Size and eccentricity only: the recordings' own noise,
// differentiated, is no eye's velocity (the oracle's own switch rate with velocity on is 7.6
// and 12.5 per object-second, docs/evaluation.md, "Real eyes").
#include "apps/gazelod/run/audit.hpp"
#include "run_test_util.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace gazelod::test {
namespace {

namespace fs = std::filesystem;

fs::path recording(const char* name) {
  return fs::path(GAZELOD_SOURCE_DIR) / ".." / "shared" / "data" / "gaze" / name;
}

// The default scenario's field of 200 objects, the recording as the eye (and the head, if it
// has one), the tracker on top.
fs::path write_scenario(const fs::path& dir, const fs::path& file, bool head, double duration_s, const char* display) {
  nlohmann::json effects = nlohmann::json::array();
  if (head)
    effects.push_back({{"type", "head_track"}, {"file", file.string()}, {"format", "auto"}, {"relative", true}});
  effects.push_back({{"type", "gaze_track"}, {"file", file.string()}, {"format", "auto"}});
  effects.push_back({{"type", "tracker_rate"}, {"rate_hz", 120}});
  effects.push_back({{"type", "tracker_latency"}, {"latency_ms", 50}});
  effects.push_back({{"type", "tracker_noise"}, {"std_deg", 0.5}});
  const nlohmann::json j = {{"version", 1},
                            {"name", "real-eyes"},
                            {"display", display},
                            {"duration_s", duration_s},
                            {"frame_rate_hz", 90},
                            {"seed", 0},
                            {"scene",
                             {{"generators",
                               {{{"type", "random_field"},
                                 {"count", 200},
                                 {"min_m", {-20, -4, -120}},
                                 {"max_m", {20, 4, -5}},
                                 {"radius_min_m", 0.2},
                                 {"radius_max_m", 1.5},
                                 {"lod_count", 4},
                                 {"triangles", 20000},
                                 {"triangle_ratio", 4}}}}}},
                            {"effects", effects},
                            {"runtime", {{"eye_gaze_supported", true}, {"paced", false}}}};
  const fs::path out = dir / "real.json";
  std::ofstream(out) << j.dump(2);
  return out;
}

nlohmann::json audit_of(const char* name, bool head, double duration_s, const char* display) {
  const fs::path file = recording(name);  // the caller checked it is there
  const fs::path dir = scratch_dir();
  const fs::path scenario = write_scenario(dir, fs::absolute(file), head, duration_s, display);
  use_simulated_runtime("");
  const CliResult r = run_cli({"run", "--scenario", scenario.string(), "--no-render", "--quiet", "--criteria",
                               "size,eccentricity", "--out", (dir / "out").string()});
  EXPECT_EQ(r.rc, 0) << r.err;
  return nlohmann::json::parse(read_text(dir / "out" / "summary.json")).at("audit");
}

void expect_within_targets(const nlohmann::json& a, double min_suppressed, double max_suppressed) {
  ASSERT_TRUE(a.at("available").get<bool>()) << a.dump(2);
  // The recording's own saccades and blinks make the suppression windows, and enough is left
  // outside them to judge.
  const double suppressed = a.at("suppression_window").at("share_of_frames").get<double>();
  EXPECT_GT(suppressed, min_suppressed) << a.dump(2);
  EXPECT_LT(suppressed, max_suppressed) << a.dump(2);
  EXPECT_GT(a.at("visible_degradations").at("object_frames").get<std::int64_t>(), 50000);
  EXPECT_LE(a.at("visible_degradations").at("share").get<double>(), cli::kTargetDegradedShare);
  EXPECT_LE(a.at("triangles_in_view").at("drawn_over_oracle").get<double>(), cli::kTargetTriangleRatio);
  EXPECT_GE(a.at("triangles_in_view").at("drawn_over_oracle").get<double>(), 1.0);
  EXPECT_LE(a.at("switches").at("outside_suppression").at("per_object_second").get<double>(),
            cli::kTargetSwitchesPerObjectS);
}

// HTC Vive Pro Eye (SRanipal through Unity, 120 Hz, 13.9 s, head poses): fixations held by the
// reflex through head turns. Measured: 0.01 % degraded, 1.08 times the oracle's triangles,
// 0.08 switches per object-second, 30 % of the frames suppressed.
TEST(RealEyes, ViveProEyeWithItsHeadMeetsTheTargets) {
  if (!fs::is_regular_file(recording("htc_vive_pro_eye_unity_log.csv")))
    GAZELOD_SKIP_OR_FAIL("no " << recording("htc_vive_pro_eye_unity_log.csv") << " (../shared/data/gaze)");
  expect_within_targets(audit_of("htc_vive_pro_eye_unity_log.csv", true, 13.5, "viveproeye"), 0.15, 0.45);
}

// Pupil Invisible (Pupil Cloud export, 200 Hz, 43 s, no head pose: a still head here): 206
// I-VT saccades (noise among them) and long invalid runs: 79 % of the frames suppressed, so
// this judges the fifth outside them. Measured: 0.00 % degraded, 1.20 times the oracle's
// triangles, 0.20 switches.
TEST(RealEyes, PupilInvisibleMeetsTheTargets) {
  if (!fs::is_regular_file(recording("pupil_cloud_invisible_gaze.csv")))
    GAZELOD_SKIP_OR_FAIL("no " << recording("pupil_cloud_invisible_gaze.csv") << " (../shared/data/gaze)");
  expect_within_targets(audit_of("pupil_cloud_invisible_gaze.csv", false, 40.0, "questpro"), 0.15, 0.85);
}

}  // namespace
}  // namespace gazelod::test
