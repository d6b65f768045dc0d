// SPDX-License-Identifier: Apache-2.0
// The layer's pure parts: the configuration (every key, and errors naming the JSON path or
// byte), the decision, the eye-gaze pose of a sample, and the trace feed's session clock.
#include "layer/decision.hpp"
#include "layer/gaze_feed.hpp"
#include "layer/layer_config.hpp"
#include "layer/pose_math.hpp"

#include "gaze/trace_reader.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::layer {
namespace {

LayerConfig parse_ok(const std::string& text) {
  const ConfigResult r = parse_config_json(text, "c.json", {});
  EXPECT_EQ(r.error, "");
  return r.config;
}

std::string parse_error(const std::string& text) {
  return parse_config_json(text, "c.json", {}).error;
}

TEST(LayerConfig, EveryKey) {
  const LayerConfig c = parse_ok(R"({"override": true, "freshness_ms": 40, "trace_format": "pupil",
      "head_offset": {"position_m": [0.01, -0.02, 0.03], "rotation_deg": [90, 0, 0]},
      "hid": {"path": "/dev/hidraw7", "layout": "dmf", "screen_mm": [120, 80]}})");
  EXPECT_TRUE(c.override_runtime);
  EXPECT_EQ(c.freshness_ns, 40'000'000);
  EXPECT_EQ(c.trace_format, gaze::TraceFormat::pupil);
  EXPECT_DOUBLE_EQ(c.tracker_position_m.y, -0.02);
  // Yaw 90 (to the right): the tracker's forward (-Z) is the head's +X.
  const glm::dvec3 fwd = c.tracker_orientation * glm::dvec3(0, 0, -1);
  EXPECT_NEAR(fwd.x, 1.0, 1e-12);
  EXPECT_EQ(c.hid_path, "/dev/hidraw7");
  EXPECT_EQ(c.hid_layout, "dmf");
  EXPECT_DOUBLE_EQ(c.hid_screen_width_m, 0.12);
  EXPECT_EQ(c.effective_freshness_ns(), 40'000'000);
}

TEST(LayerConfig, DefaultsPerSource) {
  LayerConfig c;
  EXPECT_EQ(c.effective_freshness_ns(), kHidFreshnessNs);
  c.trace_path = "t.csv";
  EXPECT_EQ(c.effective_freshness_ns(), kTraceFreshnessNs);
  const ConfigResult r = load_config("t.csv", nullptr);
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.config.trace_path, "t.csv");
  EXPECT_FALSE(r.config.override_runtime);
}

TEST(LayerConfig, ErrorsSayWhatAndWhere) {
  EXPECT_EQ(parse_error(R"({"override": 1})"), "c.json: override: must be true or false, got 1");
  EXPECT_EQ(parse_error(R"({"override": true, "override": false})"),
            "c.json: override: the key appears twice in one object (which one counts is undefined)");
  EXPECT_EQ(parse_error(R"({"freshness_ms": 0})"), "c.json: freshness_ms: must be in (0, 10000], got 0");
  EXPECT_EQ(parse_error(R"({"head_offset": {"position_m": [0, 0]}})"),
            "c.json: head_offset.position_m: must be an array of 3 numbers, got [0,0]");
  EXPECT_EQ(parse_error(R"({"head_offset": {"rotation_deg": [0, 0, 200]}})"),
            "c.json: head_offset.rotation_deg[2]: must be in [-180, 180], got 200");
  EXPECT_EQ(parse_error(R"({"hid": {"screen": 1}})"),
            "c.json: hid.screen: unknown key (known: path, layout, screen_mm)");
  EXPECT_EQ(parse_error(R"({"overide": true})").rfind("c.json: overide: unknown key (known: override,", 0), 0u);
  EXPECT_EQ(parse_error(R"([1])"), "c.json: (top level): must be a JSON object, got [1]");
  EXPECT_EQ(parse_error(R"({"trace_format": "csv"})"),
            "c.json: trace_format: must be \"auto\", \"gazelod\", \"gazebasevr\", \"pupil\", \"pupil_cloud\" or "
            "\"sranipal\", got \"csv\"");
  const std::string syntax = parse_error("{\"override\": tru}");
  EXPECT_EQ(syntax.rfind("c.json:1:17: JSON syntax error: ", 0), 0u) << syntax;
  EXPECT_EQ(load_config(nullptr, "/no/such/dir/c.json")
                .error.rfind("GAZELOD_LAYER_CONFIG=/no/such/dir/c.json: cannot open: ", 0),
            0u);
}

TEST(LayerDecision, PassThroughEmulateOrNoGaze) {
  DecisionInputs in;
  in.application_enables_extension = false;
  EXPECT_EQ(decide(in).mode, LayerMode::pass_through);
  EXPECT_FALSE(needs_source(in));
  in.application_enables_extension = true;
  in.runtime_has_extension = true;
  EXPECT_EQ(decide(in).mode, LayerMode::pass_through);
  EXPECT_FALSE(needs_source(in));
  in.override_runtime = true;
  EXPECT_TRUE(needs_source(in));
  in.source = "trace t.csv";
  Decision d = decide(in);
  EXPECT_EQ(d.mode, LayerMode::emulate);
  EXPECT_TRUE(d.gaze_available);
  EXPECT_EQ(d.why, "overriding the runtime's XR_EXT_eye_gaze_interaction with gaze from trace t.csv");
  in.runtime_has_extension = false;
  in.override_runtime = false;
  in.source_error = "GAZELOD_LAYER_TRACE: t.csv: missing";
  d = decide(in);
  EXPECT_EQ(d.mode, LayerMode::emulate);  // the application enabled the extension: never break it
  EXPECT_FALSE(d.gaze_available);
  EXPECT_NE(d.why.find("gaze unavailable (GAZELOD_LAYER_TRACE: t.csv: missing)"), std::string::npos);
}

TEST(LayerPose, GazeOrientationPointsMinusZAlongTheSampleWithoutRoll) {
  gaze::GazeSample s;
  s.valid = true;
  s.direction = gaze::direction_from_yaw_pitch_deg(20.0, -10.0);
  s.origin_m = {0.0, 0.0, 0.01};
  const auto p = eye_pose(s);
  ASSERT_TRUE(p.has_value());
  const glm::dvec3 fwd = p->orientation * glm::dvec3(0, 0, -1);
  EXPECT_LT(glm::length(fwd - s.direction), 1e-12);
  EXPECT_NEAR((p->orientation * glm::dvec3(1, 0, 0)).y, 0.0, 1e-12);  // +X stays level
  // Invalid or degenerate samples give no pose (no NaN reaches a pose).
  s.direction = {0.0, 0.0, 0.0};
  EXPECT_FALSE(eye_pose(s).has_value());
  s.direction = {std::nan(""), 0.0, -1.0};
  EXPECT_FALSE(eye_pose(s).has_value());
  s.direction = {0.0, 0.0, -1.0};
  s.valid = false;
  EXPECT_FALSE(eye_pose(s).has_value());
  // compose / inverse round trip.
  const Pose a{glm::normalize(glm::dquat(0.9, 0.1, -0.3, 0.2)), {1.0, 2.0, 3.0}};
  const Pose id = compose(a, inverse(a));
  EXPECT_LT(glm::length(id.position), 1e-12);
  EXPECT_NEAR(std::abs(id.orientation.w), 1.0, 1e-12);
}

TEST(LayerTraceFeed, FirstSampleSitsOnTheSessionsFirstFrame) {
  std::vector<gaze::TraceRecord> records;
  for (int i = 0; i < 100; ++i) {
    gaze::TraceRecord r;
    r.gaze.t_ns = 5'000'000'000 + i * 10'000'000;  // 100 Hz from t = 5 s
    r.gaze.direction = gaze::direction_from_yaw_pitch_deg(i * 0.1, 0.0);
    r.gaze.valid = true;
    records.push_back(r);
  }
  TraceFeed feed("t.csv", records, 30'000'000);
  EXPECT_FALSE(feed.sample_at(1'000'000'000).has_value());  // no frame yet
  EXPECT_FALSE(feed.fresh());
  const std::int64_t first = 7'000'000'000;
  feed.on_frame(first, true);
  const auto s0 = feed.sample_at(first);
  ASSERT_TRUE(s0.has_value());
  EXPECT_EQ(s0->t_ns, first);
  EXPECT_LT(glm::length(s0->direction - records[0].gaze.direction), 1e-12);
  EXPECT_TRUE(feed.fresh());
  // Held for the freshness time past the last sample, then stale.
  const std::int64_t last = first + 99 * 10'000'000;
  EXPECT_EQ(feed.sample_at(last + 20'000'000)->t_ns, last);
  EXPECT_FALSE(feed.sample_at(last + 40'000'000).has_value());
  feed.on_frame(last + 40'000'000, false);
  EXPECT_FALSE(feed.fresh());
  // A new session starts the trace again at its first frame.
  feed.on_frame(first + 100'000'000'000, true);
  EXPECT_TRUE(feed.fresh());
  EXPECT_NE(feed.describe().find("100 samples"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::layer
