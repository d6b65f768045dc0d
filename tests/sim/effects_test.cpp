// SPDX-License-Identifier: Apache-2.0
// Each effect's measurable property, measured from the simulator's output (not its internals):
// the still scenario, head sweeps and turns, the saccadic main sequence, pursuit gain, tracker
// latency, rate, noise, dropouts, blinks, calibration offset and drift, object motion.
#include "sim/simulator.hpp"
#include "tests/sim/sim_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace gazelod::sim {
namespace {

using namespace test;
constexpr double kPi = 3.14159265358979323846;
constexpr std::int64_t kMs = 1'000'000;

glm::dvec3 forward_of(const HeadState& h) {
  return h.orientation * glm::dvec3(0, 0, -1);
}

TEST(Effects, NoEffectsMeansStillHeadAndCentredGaze) {
  Simulator sim = make_sim(base_scenario());
  for (std::int64_t t : {std::int64_t{0}, std::int64_t{1}, 5 * kMs, std::int64_t{12'345'678'901}, 29'999 * kMs}) {
    const HeadState h = sim.head_at(t);
    EXPECT_EQ(h.orientation, glm::dquat(1, 0, 0, 0));
    EXPECT_EQ(h.angular_velocity_rad_s, glm::dvec3(0.0));
    EXPECT_EQ(h.position_m, glm::dvec3(0.0));
    const gaze::GazeSample g = sim.true_gaze_at(t);
    EXPECT_EQ(g.direction, glm::dvec3(0, 0, -1));
    EXPECT_TRUE(g.valid);
    const gaze::GazeSample s = sim.tracker_at(t);
    EXPECT_EQ(s.direction, glm::dvec3(0, 0, -1));
    EXPECT_EQ(s.t_ns, t) << "no latency, no rate: the sample is taken when asked for";
    EXPECT_TRUE(s.valid);
  }
  // The object moves at its own constant velocity.
  const std::span<const ObjectState> o = sim.objects_at(2'000 * kMs);
  ASSERT_EQ(o.size(), 1u);
  EXPECT_NEAR(o[0].position_m.x, 1.0, 1e-12);
  EXPECT_NEAR(o[0].position_m.z, -5.0, 1e-12);
}

TEST(Effects, HeadSweepReachesItsAmplitudeAndReportsItsTrueAngularVelocity) {
  Simulator sim = make_sim(base_scenario({{{"type", "head_sweep"},
                                           {"yaw_amplitude_deg", 30},
                                           {"yaw_period_s", 4},
                                           {"pitch_amplitude_deg", 10},
                                           {"pitch_period_s", 2}}}));
  // Quarter of the yaw period: yaw at +30 deg (turned left), pitch back at 0.
  const glm::dvec3 f = forward_of(sim.head_at(1000 * kMs));
  EXPECT_NEAR(yaw_deg(f), 30.0, 1e-9);
  EXPECT_NEAR(pitch_deg(f), 0.0, 1e-9);
  EXPECT_NEAR(pitch_deg(forward_of(sim.head_at(500 * kMs))), 10.0, 1e-3);
  // Angular velocity against a central difference of the orientation.
  for (std::int64_t t = 100 * kMs; t < 4000 * kMs; t += 333 * kMs) {
    const glm::dquat a = sim.head_at(t - 1000).orientation, b = sim.head_at(t + 1000).orientation;
    const glm::dquat d = b * glm::conjugate(a);  // world-frame rotation over 2 us
    const glm::dvec3 w_num = glm::dvec3(d.x, d.y, d.z) * (2.0 / 2e-6) * (d.w < 0 ? -1.0 : 1.0);
    const glm::dvec3 w = sim.head_at(t).angular_velocity_rad_s;
    EXPECT_NEAR(w.x, w_num.x, 1e-6);
    EXPECT_NEAR(w.y, w_num.y, 1e-6);
    EXPECT_NEAR(w.z, w_num.z, 1e-6);
  }
  // Peak yaw rate at t = 0: A * 2 pi / T = 30 * pi / 2 deg/s.
  EXPECT_NEAR(sim.head_at(0).angular_velocity_rad_s.y * 180.0 / kPi, 30.0 * kPi / 2.0, 1e-9);
}

TEST(Effects, HeadTurnHoldsItsRateUpTo300DegPerSecondThenStops) {
  Simulator sim =
      make_sim(base_scenario({{{"type", "head_turn"}, {"rate_deg_s", -300}, {"start_s", 1.0}, {"duration_s", 0.25}}}));
  EXPECT_NEAR(yaw_deg(forward_of(sim.head_at(1000 * kMs))), 0.0, 1e-9);
  EXPECT_NEAR(yaw_deg(forward_of(sim.head_at(1100 * kMs))), -30.0, 1e-9);
  EXPECT_NEAR(yaw_deg(forward_of(sim.head_at(1250 * kMs))), -75.0, 1e-9);
  EXPECT_NEAR(yaw_deg(forward_of(sim.head_at(5000 * kMs))), -75.0, 1e-9) << "held after the turn";
  EXPECT_NEAR(glm::length(sim.head_at(1200 * kMs).angular_velocity_rad_s) * 180.0 / kPi, 300.0, 1e-9);
  EXPECT_EQ(glm::length(sim.head_at(1300 * kMs).angular_velocity_rad_s), 0.0);
  EXPECT_EQ(glm::length(sim.head_at(900 * kMs).angular_velocity_rad_s), 0.0);
}

struct Saccade {
  std::int64_t start_ns, end_ns;
  double amplitude_deg, peak_deg_s;
};

// Finds saccades in the true gaze, sampled every 0.1 ms: any movement (fixations are exactly still).
std::vector<Saccade> find_saccades(Simulator& sim, std::int64_t from_ns, std::int64_t to_ns) {
  constexpr std::int64_t kStep = 100'000;
  std::vector<Saccade> out;
  glm::dvec3 prev = sim.true_gaze_at(from_ns).direction;
  bool moving = false;
  Saccade cur{};
  glm::dvec3 start_dir = prev;
  for (std::int64_t t = from_ns + kStep; t < to_ns; t += kStep) {
    const glm::dvec3 d = sim.true_gaze_at(t).direction;
    const double v = angle_deg(prev, d) / 1e-4;
    if (!moving && v > 1e-9) {
      moving = true;
      cur = {t - kStep, 0, 0.0, 0.0};
      start_dir = prev;
    }
    if (moving) cur.peak_deg_s = std::max(cur.peak_deg_s, v);
    if (moving && v <= 1e-9) {
      moving = false;
      cur.end_ns = t - kStep;
      cur.amplitude_deg = angle_deg(start_dir, prev);
      out.push_back(cur);
    }
    prev = d;
  }
  return out;
}

TEST(Effects, SaccadesFollowTheMainSequence) {
  Simulator sim = make_sim(base_scenario({{{"type", "saccades"},
                                           {"amplitude_min_deg", 1},
                                           {"amplitude_max_deg", 40},
                                           {"range_deg", 30},
                                           {"fixation_min_ms", 100},
                                           {"fixation_max_ms", 300}}}));
  const std::vector<Saccade> s = find_saccades(sim, 0, 20'000 * kMs);
  ASSERT_GT(s.size(), 40u);
  double max_amp = 0.0, max_peak = 0.0;
  for (const Saccade& c : s) {
    const double duration_ms = static_cast<double>(c.end_ns - c.start_ns) * 1e-6;
    // Main sequence: 2.2 ms per degree + 21 ms (Carpenter 1988), to the 0.1 ms sampling.
    EXPECT_NEAR(duration_ms, 2.2 * c.amplitude_deg + 21.0, 0.25) << "amplitude " << c.amplitude_deg;
    EXPECT_LE(c.amplitude_deg, 40.0 + 1e-6);
    // Peak velocity: above the mean velocity, and never past the ~500 deg/s saturation.
    EXPECT_GE(c.peak_deg_s, c.amplitude_deg / (duration_ms * 1e-3) * 0.99);
    EXPECT_LT(c.peak_deg_s, 560.0);
    max_amp = std::max(max_amp, c.amplitude_deg);
    max_peak = std::max(max_peak, c.peak_deg_s);
  }
  EXPECT_GT(max_amp, 20.0);
  EXPECT_GT(max_peak, 400.0) << "large saccades approach the saturation";
  // Fixations are still: between saccades the direction does not move at all.
  for (std::size_t i = 1; i < s.size(); ++i) {
    const double fix_ms = static_cast<double>(s[i].start_ns - s[i - 1].end_ns) * 1e-6;
    EXPECT_GE(fix_ms, 100.0 - 0.2);
    EXPECT_LE(fix_ms, 300.0 + 0.2);
  }
}

TEST(Effects, SmoothPursuitFollowsTheTargetWithItsGain) {
  // Target 5 m ahead moving right at 0.5 m/s; still head; gain 0.8; catch-up every 0.5 s.
  Simulator sim = make_sim(
      base_scenario({{{"type", "smooth_pursuit"}, {"object", "target"}, {"gain", 0.8}, {"catch_up_interval_s", 0.5}}}));
  auto target_yaw = [&](std::int64_t t) {
    const glm::dvec3 p = sim.objects_at(t)[0].position_m;
    return std::atan2(-p.x, -p.z) * 180.0 / kPi;
  };
  for (std::int64_t ts = 0; ts < 3000 * kMs; ts += 500 * kMs) {
    EXPECT_NEAR(yaw_deg(sim.true_gaze_at(ts).direction), target_yaw(ts), 1e-9) << "on target after catch-up";
    const std::int64_t t = ts + 400 * kMs;
    const double eye_moved = yaw_deg(sim.true_gaze_at(t).direction) - yaw_deg(sim.true_gaze_at(ts).direction);
    const double target_moved = target_yaw(t) - target_yaw(ts);
    EXPECT_NEAR(eye_moved / target_moved, 0.8, 1e-9);
  }
}

TEST(Effects, TrackerLatencyShiftsSamplesByItsDelay) {
  const nlohmann::json sacc = {{"type", "saccades"}};
  Simulator sim = make_sim(base_scenario({sacc, {{"type", "tracker_latency"}, {"latency_ms", 25}}}));
  EXPECT_FALSE(sim.tracker_at(10 * kMs).valid) << "nothing has arrived before the latency";
  EXPECT_EQ(sim.first_tracker_sample_ns(), 25 * kMs);
  for (std::int64_t t = 25 * kMs; t < 5000 * kMs; t += 7'777'777) {
    const gaze::GazeSample s = sim.tracker_at(t);
    EXPECT_EQ(s.t_ns, t - 25 * kMs);
    EXPECT_EQ(s.direction, sim.true_gaze_at(t - 25 * kMs).direction);
  }
}

TEST(Effects, TrackerRateQuantisesSampleTimes) {
  Simulator sim = make_sim(base_scenario({{{"type", "saccades"}}, {{"type", "tracker_rate"}, {"rate_hz", 200}}}));
  std::set<std::int64_t> times;
  for (std::int64_t t = 0; t < 1000 * kMs; t += 100'000) {
    const gaze::GazeSample s = sim.tracker_at(t);
    EXPECT_EQ(s.t_ns % (5 * kMs), 0);
    EXPECT_LE(s.t_ns, t);
    EXPECT_GT(s.t_ns + 5 * kMs, t) << "the newest sample";
    EXPECT_EQ(s.direction, sim.true_gaze_at(s.t_ns).direction);
    times.insert(s.t_ns);
  }
  EXPECT_EQ(times.size(), 200u);
}

TEST(Effects, TrackerRateDefaultsToThePresetsEyeTracker) {
  Simulator sim = make_sim(base_scenario({{{"type", "tracker_rate"}}}));  // questpro: 90 Hz
  EXPECT_EQ(sim.tracker_at(25 * kMs).t_ns, 22'222'222);
}

TEST(Effects, TrackerNoiseHasItsStandardDeviation) {
  Simulator sim = make_sim(base_scenario({{{"type", "tracker_noise"}, {"std_deg", 0.5}}}));
  constexpr int kN = 40000;
  double sy = 0, syy = 0, sp = 0, spp = 0;
  for (int i = 0; i < kN; ++i) {
    const glm::dvec3 d = sim.tracker_at(static_cast<std::int64_t>(i) * 1'000'003).direction;
    const double y = yaw_deg(d), p = pitch_deg(d);
    sy += y, syy += y * y, sp += p, spp += p * p;
  }
  const double my = sy / kN, mp = sp / kN;
  EXPECT_NEAR(my, 0.0, 0.02);
  EXPECT_NEAR(mp, 0.0, 0.02);
  // Standard error of a std estimate: sigma / sqrt(2N) = 0.0018 deg; allow 3 %.
  EXPECT_NEAR(std::sqrt(syy / kN - my * my), 0.5, 0.015);
  EXPECT_NEAR(std::sqrt(spp / kN - mp * mp), 0.5, 0.015);
}

TEST(Effects, DropoutsLoseTheirFractionOfTime) {
  Simulator sim = make_sim(base_scenario({{{"type", "dropouts"}, {"fraction", 0.2}, {"burst_ms", 20}}}));
  int invalid = 0, n = 0;
  for (std::int64_t t = 0; t < 200'000 * kMs; t += 5 * kMs, ++n) {
    const gaze::GazeSample s = sim.tracker_at(t);
    if (!s.valid) {
      ++invalid;
      EXPECT_EQ(s.confidence, 0.0f);
    }
  }
  // 10 000 bursts: binomial standard deviation 0.004.
  EXPECT_NEAR(double(invalid) / n, 0.2, 0.015);
}

TEST(Effects, BlinksComeAtTheirRateAndLastTheirDuration) {
  Simulator sim = make_sim(base_scenario({{{"type", "blinks"}, {"rate_per_min", 20}, {"duration_ms", 150}}}));
  int onsets = 0, invalid = 0, n = 0;
  bool prev_valid = true;
  for (std::int64_t t = 0; t < 600'000 * kMs; t += kMs, ++n) {
    const bool v = sim.tracker_at(t).valid;
    if (!v) ++invalid;
    if (prev_valid && !v) ++onsets;
    prev_valid = v;
  }
  EXPECT_EQ(onsets, 200) << "20 a minute for 10 minutes";
  EXPECT_NEAR(double(invalid) / n, 200 * 0.150 / 600.0, 1e-4);
}

TEST(Effects, CalibrationOffsetAndDrift) {
  Simulator sim = make_sim(base_scenario(
      {{{"type", "calibration_offset"}, {"yaw_deg", 2.0}, {"pitch_deg", -1.0}, {"drift_yaw_deg_per_min", 1.0}}}));
  EXPECT_NEAR(yaw_deg(sim.tracker_at(0).direction), 2.0, 1e-9);
  EXPECT_NEAR(pitch_deg(sim.tracker_at(0).direction), -1.0, 1e-9);
  EXPECT_NEAR(yaw_deg(sim.tracker_at(60'000 * kMs).direction), 3.0, 1e-9);
  EXPECT_NEAR(yaw_deg(sim.tracker_at(30'000 * kMs).direction), 2.5, 1e-9);
  EXPECT_EQ(sim.true_gaze_at(60'000 * kMs).direction, glm::dvec3(0, 0, -1)) << "the eye itself is centred";
}

TEST(Effects, ObjectMotionOscillatesOnlyItsObject) {
  nlohmann::json j = base_scenario(
      {{{"type", "object_motion"}, {"object", "target"}, {"amplitude_m", {0, 0.5, 0}}, {"frequency_hz", 0.25}}});
  j["scene"]["objects"].push_back({{"name", "other"}, {"position_m", {1, 1, -3}}, {"lods", {{{"triangles", 1}}}}});
  Simulator sim = make_sim(j);
  const std::span<const ObjectState> o = sim.objects_at(1000 * kMs);  // a quarter period
  EXPECT_NEAR(o[0].position_m.y, 0.5, 1e-12);
  EXPECT_NEAR(o[0].position_m.x, 0.5, 1e-12) << "its own velocity still applies";
  EXPECT_EQ(o[1].position_m, glm::dvec3(1, 1, -3));
  // Velocity = derivative of position.
  const double y0 = sim.objects_at(2000 * kMs - 1000)[0].position_m.y,
               y1 = sim.objects_at(2000 * kMs + 1000)[0].position_m.y;
  EXPECT_NEAR(sim.objects_at(2000 * kMs)[0].velocity_m_s.y, (y1 - y0) / 2e-6, 1e-6);
  EXPECT_NEAR(sim.objects_at(2000 * kMs)[0].velocity_m_s.y, -0.5 * 2 * kPi * 0.25, 1e-9);
}

}  // namespace
}  // namespace gazelod::sim
