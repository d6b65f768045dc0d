// SPDX-License-Identifier: Apache-2.0
// Replay: angular interpolation, slerp, no interpolation across invalid samples or saccades,
// bounded hold-last-good.
#include "auxiliary/angles.hpp"
#include "gaze/replay_source.hpp"
#include "gaze/trace_reader.hpp"
#include "tests/gaze/synth.hpp"

#include <gtest/gtest.h>

namespace gazelod::gaze {
namespace {

constexpr std::int64_t kMs = 1'000'000;

TraceRecord rec(std::int64_t t_ns, double yaw_deg, bool valid = true) {
  TraceRecord r;
  r.gaze.t_ns = t_ns;
  r.gaze.direction = direction_from_yaw_pitch_deg(yaw_deg, 0.0);
  r.gaze.valid = valid;
  r.gaze.confidence = valid ? 1.0f : 0.0f;
  return r;
}

double yaw_of(const glm::dvec3& d) {
  return std::atan2(d.x, -d.z) * aux::kDegPerRad;
}

TEST(Replay, InterpolatesByAngle) {
  // Slow drift (2 deg per 4 ms would be a saccade; 0.04 deg per 4 ms is not).
  std::vector<TraceRecord> rs;
  for (int i = 0; i < 20; ++i) rs.push_back(rec(i * 4 * kMs, 0.04 * i));
  ReplaySource src(rs);
  const auto s = src.sample_at(41 * kMs);  // a quarter of the way from sample 10 to 11
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(yaw_of(s->direction), 0.41, 1e-9);
  EXPECT_NEAR(glm::length(s->direction), 1.0, 1e-14);
  EXPECT_EQ(s->t_ns, 41 * kMs);
  // Exactly on a sample: that sample.
  EXPECT_EQ(src.sample_at(8 * kMs)->direction, rs[2].gaze.direction);
  // Backward query after forward ones gives the same answer (binary search path).
  EXPECT_NEAR(yaw_of(src.sample_at(6 * kMs)->direction), 0.06, 1e-9);
  EXPECT_NEAR(yaw_of(src.sample_at(41 * kMs)->direction), 0.41, 1e-9);
}

TEST(Replay, BeforeStartUnavailableAfterEndHeldThenUnavailable) {
  std::vector<TraceRecord> rs;
  for (int i = 0; i < 10; ++i) rs.push_back(rec(1000 * kMs + i * 4 * kMs, 1.0));
  ReplaySource src(rs, {.hold_max_ns = 100 * kMs});
  EXPECT_FALSE(src.sample_at(999 * kMs).has_value());
  EXPECT_NE(src.status().find("before"), std::string::npos);
  const auto held = src.sample_at(1036 * kMs + 100 * kMs);
  ASSERT_TRUE(held.has_value());
  EXPECT_EQ(held->t_ns, 1036 * kMs);  // reports when it was taken
  EXPECT_FALSE(src.sample_at(1036 * kMs + 100 * kMs + 1).has_value());
  EXPECT_NE(src.status().find("no valid gaze"), std::string::npos);
  EXPECT_FALSE(ReplaySource({}).sample_at(0).has_value());
  EXPECT_THROW(ReplaySource({rec(5, 0.0), rec(4, 0.0)}), std::invalid_argument);
}

TEST(Replay, BlinkHoldsLastGoodNeverInterpolatesIntoIt) {
  std::vector<TraceRecord> rs;
  std::int64_t t = 0;
  for (int i = 0; i < 20; ++i, t += 4 * kMs) rs.push_back(rec(t, 0.0));
  const std::int64_t last_good = t - 4 * kMs;
  for (int i = 0; i < 25; ++i, t += 4 * kMs) rs.push_back(rec(t, 30.0, false));  // 100 ms
  for (int i = 0; i < 20; ++i, t += 4 * kMs) rs.push_back(rec(t, 5.0));
  ReplaySource src(rs, {.hold_max_ns = 150 * kMs});
  // Between the last good sample and the first invalid one: held, not interpolated.
  auto s = src.sample_at(last_good + 2 * kMs);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->direction, rs[19].gaze.direction);
  s = src.sample_at(last_good + 90 * kMs);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->t_ns, last_good);
  // A blink longer than hold_max: unavailable after the bound.
  std::vector<TraceRecord> long_blink(rs.begin(), rs.begin() + 20);
  for (int i = 0; i < 100; ++i) long_blink.push_back(rec(last_good + (i + 1) * 4 * kMs, 0, false));
  ReplaySource src2(long_blink, {.hold_max_ns = 150 * kMs});
  EXPECT_TRUE(src2.sample_at(last_good + 150 * kMs).has_value());
  EXPECT_FALSE(src2.sample_at(last_good + 151 * kMs).has_value());
}

TEST(Replay, NoInterpolationAcrossSaccade) {
  testing::Synth s;
  s.noise_deg = 0.0;
  s.fixate(0.2);
  s.saccade(10.0, 0.0);
  s.fixate(0.2);
  std::vector<TraceRecord> rs;
  for (const auto& g : s.out) rs.push_back(TraceRecord{g, false, {}});
  ReplaySource src(rs);
  int saccade_samples = 0;
  for (std::size_t i = 0; i + 1 < rs.size(); ++i) {
    if (src.label(i) != GazeLabel::saccade && src.label(i + 1) != GazeLabel::saccade) continue;
    ++saccade_samples;
    const std::int64_t mid = (rs[i].gaze.t_ns + rs[i + 1].gaze.t_ns) / 2;
    EXPECT_EQ(src.sample_at(mid)->direction, rs[i].gaze.direction) << i;  // held, not blended
  }
  EXPECT_GT(saccade_samples, 5);
}

TEST(Replay, TimeOffsetMapsTraceToHostTime) {
  std::vector<TraceRecord> rs{rec(0, 0.0), rec(4 * kMs, 0.01)};
  ReplaySource src(rs, {.time_offset_ns = 5'000 * kMs});
  EXPECT_FALSE(src.sample_at(2 * kMs).has_value());
  EXPECT_TRUE(src.sample_at(5'002 * kMs).has_value());
}

TEST(Replay, HeadSlerpTakesShortPathAcrossSignFlip) {
  const double half = 10.0 / 2.0 / aux::kDegPerRad;  // 10 deg about +Y
  TraceRecord a = rec(0, 0.0), b = rec(4 * kMs, 0.0);
  a.has_head = b.has_head = true;
  a.head.valid = b.head.valid = true;
  a.head.orientation = glm::dquat(1, 0, 0, 0);
  b.head.orientation = -glm::dquat(std::cos(half), 0, std::sin(half), 0);  // same rotation, -q
  b.head.position_m = {0.0, 0.0, -0.004};
  ReplaySource src({a, b});
  const auto h = src.head_at(2 * kMs);
  ASSERT_TRUE(h.has_value());
  // Expected: 5 deg about +Y (either sign of q).
  const glm::dquat e(std::cos(half / 2), 0, std::sin(half / 2), 0);
  EXPECT_NEAR(std::fabs(glm::dot(h->orientation, e)), 1.0, 1e-12);
  EXPECT_NEAR(h->position_m.z, -0.002, 1e-15);
}

}  // namespace
}  // namespace gazelod::gaze
