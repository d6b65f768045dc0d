// SPDX-License-Identifier: Apache-2.0
// The vor effect, measured from the simulator's output: fixations held on a world point while
// the head moves (gain 1), half of it at gain 0.5, saccades landing where the saccades effect
// puts them, a continuous gaze, the ground truth of its saccades, quick phases that keep the eye
// in the oculomotor range, the start_s / end_s window, and the same bits in any query order.
#include "sim/simulator.hpp"
#include "tests/sim/sim_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

namespace gazelod::sim {
namespace {

using namespace test;
constexpr std::int64_t kMs = 1'000'000;
constexpr std::int64_t kStep = 100'000;  // 0.1 ms

const glm::dvec3 kForward{0, 0, -1};

glm::dvec3 eye(Simulator& sim, std::int64_t t) {
  return sim.true_gaze_at(t).direction;
}
glm::dvec3 world_gaze(Simulator& sim, std::int64_t t) {
  return sim.head_at(t).orientation * eye(sim, t);
}
double head_yaw_deg(Simulator& sim, std::int64_t t) {
  return yaw_deg(sim.head_at(t).orientation * kForward);
}
// The angle of the head's rotation from t0 to t1.
double head_turned_deg(Simulator& sim, std::int64_t t0, std::int64_t t1) {
  const glm::dquat d = glm::conjugate(sim.head_at(t1).orientation) * sim.head_at(t0).orientation;
  return 2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w)) * 180.0 / 3.14159265358979323846;
}

nlohmann::json saccades(double fix_min_ms = 250, double fix_max_ms = 600, double range_deg = 10) {
  return {{"type", "saccades"},     {"fixation_min_ms", fix_min_ms}, {"fixation_max_ms", fix_max_ms},
          {"amplitude_min_deg", 2}, {"amplitude_max_deg", 15},       {"range_deg", range_deg}};
}
nlohmann::json sweep(double pitch_deg = 8) {
  return {{"type", "head_sweep"},
          {"yaw_amplitude_deg", 20},
          {"yaw_period_s", 4},
          {"pitch_amplitude_deg", pitch_deg},
          {"pitch_period_s", 3}};
}

// Intervals [a, b) in which the eye does not move at all (fixations of the saccades effect),
// sampled every 0.1 ms, at least min_ns long.
std::vector<std::pair<std::int64_t, std::int64_t>> still_intervals(Simulator& sim, std::int64_t from, std::int64_t to,
                                                                   std::int64_t min_ns = 50 * kMs) {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  glm::dvec3 prev = eye(sim, from);
  std::int64_t start = from;
  for (std::int64_t t = from + kStep; t < to; t += kStep) {
    const glm::dvec3 d = eye(sim, t);
    if (d != prev) {
      if (t - kStep - start >= min_ns) out.emplace_back(start, t - kStep);
      start = t;
    }
    prev = d;
  }
  if (to - start >= min_ns) out.emplace_back(start, to);
  return out;
}

// When the eye has landed in a fixation [a, b) of the incoming direction: the first time from a
// at which the world gaze stops moving (gain 1); -1 if it never does.
std::int64_t landing(Simulator& sim, std::int64_t a, std::int64_t b) {
  for (std::int64_t t = a; t + kStep < b; t += kStep)
    if (angle_deg(world_gaze(sim, t), world_gaze(sim, t + kStep)) < 1e-7) return t;
  return -1;
}

TEST(Vor, FixationsStayOnAWorldPointWhileTheEyeCounterRotatesInTheHead) {
  Simulator ref = make_sim(base_scenario({sweep(), saccades()}));
  Simulator sim = make_sim(base_scenario({sweep(), saccades(), {{"type", "vor"}}}));
  const auto fixations = still_intervals(ref, 0, 10'000 * kMs, 200 * kMs);
  ASSERT_GT(fixations.size(), 12u);
  int moved = 0;
  for (const auto& [a, b] : fixations) {
    const std::int64_t landed = landing(sim, a, b);
    ASSERT_GE(landed, a) << "fixation from " << a;
    EXPECT_LT(landed - a, 60 * kMs) << "lands soon after the incoming saccade";
    const glm::dvec3 w0 = world_gaze(sim, landed), e0 = eye(sim, landed);
    double eye_moved = 0.0, ref_world_moved = 0.0;
    for (std::int64_t t = landed; t <= b; t += kMs / 2) {
      EXPECT_LT(angle_deg(world_gaze(sim, t), w0), 1e-8) << "fixation from " << a << ", t " << t;
      // The eye turns in the head by no more than the head turned.
      EXPECT_LE(angle_deg(eye(sim, t), e0), head_turned_deg(sim, landed, t) + 1e-9);
      eye_moved = std::max(eye_moved, angle_deg(eye(sim, t), e0));
      ref_world_moved = std::max(ref_world_moved, angle_deg(world_gaze(ref, t), world_gaze(ref, landed)));
      EXPECT_LT(angle_deg(eye(sim, t), kForward), 40.0) << "no quick phase needed in this scenario";
    }
    if (eye_moved > 1.0) {
      ++moved;
      EXPECT_GT(ref_world_moved, 1.0) << "without vor the head drags the gaze along";
    }
  }
  EXPECT_GT(moved, 6) << "the head sweep moves the eye in the head during most fixations";
}

TEST(Vor, GainHalfCounterRotatesHalfTheHeadTurn) {
  for (const double gain : {0.5, 1.0}) {
    Simulator ref = make_sim(base_scenario({sweep(0), saccades()}));
    Simulator sim = make_sim(base_scenario({sweep(0), saccades(), {{"type", "vor"}, {"gain", gain}}}));
    int checked = 0;
    for (const auto& [a0, b] : still_intervals(ref, 0, 8'000 * kMs, 150 * kMs)) {
      const std::int64_t a = a0 + 100 * kMs;  // landed (the vor's saccade may outlast the incoming one)
      for (std::int64_t t = a + 10 * kMs; t <= b; t += 10 * kMs) {
        const double head = head_yaw_deg(sim, t) - head_yaw_deg(sim, a);
        // A yaw-only head: the counter-rotation is about the head's own Y axis, exactly.
        EXPECT_NEAR(yaw_deg(eye(sim, t)) - yaw_deg(eye(sim, a)), -gain * head, 1e-9) << gain;
        EXPECT_NEAR(pitch_deg(eye(sim, t)), pitch_deg(eye(sim, a)), 1e-9);
        EXPECT_NEAR(yaw_deg(world_gaze(sim, t)) - yaw_deg(world_gaze(sim, a)), (1.0 - gain) * head, 1e-9);
        ++checked;
      }
    }
    EXPECT_GT(checked, 200);
  }
}

TEST(Vor, SaccadesStillLandWhereTheSaccadesEffectPutsThemInTheHead) {
  Simulator ref = make_sim(base_scenario({sweep(), saccades()}));
  Simulator sim = make_sim(base_scenario({sweep(), saccades(), {{"type", "vor"}}}));
  const auto fixations = still_intervals(ref, 0, 10'000 * kMs, 20 * kMs);
  ASSERT_GT(fixations.size(), 12u);
  double max_peak = 0.0;
  for (std::size_t i = 1; i < fixations.size(); ++i) {
    const auto [a, b] = fixations[i];
    const std::int64_t sac_start = fixations[i - 1].second, landed = landing(sim, a, b);
    ASSERT_GE(landed, a) << "saccade " << i;
    // Landed on the saccades effect's target in the head: at some time s (when the eye landed,
    // which may be before the incoming saccade ended), the world point now held was seen there.
    const glm::dvec3 held = world_gaze(sim, landed);
    double miss = 180.0;
    for (std::int64_t t = landed; t > sac_start; t -= kStep)
      miss = std::min(miss, angle_deg(glm::conjugate(sim.head_at(t).orientation) * held, eye(ref, a)));
    EXPECT_LT(miss, 0.005) << "saccade " << i;
    // Still a saccade: fast, and within the main sequence's ~550 deg/s, in the head.
    double peak = 0.0;
    for (std::int64_t t = sac_start; t < landed; t += kStep)
      peak = std::max(peak, angle_deg(eye(sim, t), eye(sim, t + kStep)) / 1e-4);
    const double amplitude = angle_deg(eye(ref, sac_start), eye(ref, a));
    if (amplitude > 3.0) {
      EXPECT_GT(peak, 100.0) << "saccade " << i << " of " << amplitude << " deg";
    }
    max_peak = std::max(max_peak, peak);
  }
  EXPECT_LT(max_peak, 560.0);
}

TEST(Vor, GazeIsContinuousAndFollowsOnlyTheHeadBetweenSaccades) {
  Simulator ref = make_sim(base_scenario({sweep(), saccades()}));
  Simulator sim = make_sim(base_scenario({sweep(), saccades(), {{"type", "vor"}}}));
  double max_speed = 0.0;
  glm::dvec3 prev = eye(sim, 0);
  for (std::int64_t t = kStep; t < 10'000 * kMs; t += kStep) {
    const glm::dvec3 d = eye(sim, t);
    max_speed = std::max(max_speed, angle_deg(prev, d) / 1e-4);
    prev = d;
  }
  EXPECT_LT(max_speed, 600.0) << "no jumps: a saccade's peak is ~550 deg/s";
  EXPECT_GT(max_speed, 200.0) << "but saccades";
  // Once landed, the eye moves only as fast as the head turns (gain 1).
  for (const auto& [a, b] : still_intervals(ref, 0, 10'000 * kMs, 100 * kMs)) {
    for (std::int64_t t = landing(sim, a, b); t + kStep <= b; t += kStep)
      EXPECT_LE(angle_deg(eye(sim, t), eye(sim, t + kStep)), head_turned_deg(sim, t, t + kStep) + 1e-9) << t;
  }
}

TEST(Vor, TruthMarksItsSaccadesAndWhenTheyLanded) {
  Simulator ref = make_sim(base_scenario({sweep(), saccades()}));
  Simulator sim = make_sim(base_scenario({sweep(), saccades(), {{"type", "vor"}}}));
  int onsets = 0, ref_onsets = 0, held = 0;
  bool prev = false, ref_prev = false;
  for (std::int64_t t = 0; t < 10'000 * kMs; t += kMs) {
    const glm::dvec3 w = world_gaze(sim, t);  // a gaze query first (see vor.cpp, apply_truth)
    const EyeTruth tr = sim.eye_truth_at(t), rt = ref.eye_truth_at(t);
    onsets += tr.in_saccade && !prev;
    ref_onsets += rt.in_saccade && !ref_prev;
    prev = tr.in_saccade;
    ref_prev = rt.in_saccade;
    if (!tr.in_saccade && tr.last_saccade_end_ns > 0) {
      EXPECT_LE(tr.last_saccade_end_ns, t);
      EXPECT_LT(angle_deg(w, world_gaze(sim, tr.last_saccade_end_ns)), 0.01) << "held since it landed, t " << t;
      ++held;
    }
  }
  EXPECT_EQ(onsets, ref_onsets) << "one saccade per incoming saccade, no quick phase here";
  EXPECT_GT(onsets, 12);
  EXPECT_GT(held, 8000);
}

TEST(Vor, QuickPhasesKeepTheEyeInTheOculomotorRange) {
  for (const double range : {45.0, 30.0}) {
    // A 240 deg turn during long fixations: the counter-rotation cannot follow it all.
    nlohmann::json vor = {{"type", "vor"}};
    if (range != 45.0) vor["range_deg"] = range;
    Simulator sim = make_sim(base_scenario(
        {{{"type", "head_turn"}, {"rate_deg_s", 60}, {"start_s", 0.5}, {"duration_s", 4}}, saccades(3000, 5000), vor}));
    double max_ecc = 0.0, max_speed = 0.0;
    int quick_phases = 0;
    bool fast = false;
    glm::dvec3 prev = eye(sim, 0);
    for (std::int64_t t = kStep; t < 6'000 * kMs; t += kStep) {
      const glm::dvec3 d = eye(sim, t);
      max_ecc = std::max(max_ecc, angle_deg(d, kForward));
      const double speed = angle_deg(prev, d) / 1e-4;
      max_speed = std::max(max_speed, speed);
      if (!fast && speed > 150.0) ++quick_phases;
      fast = speed > 150.0;
      prev = d;
    }
    EXPECT_LE(max_ecc, range + 1e-6);
    EXPECT_GT(max_ecc, range - 0.1) << "the eye goes out to the range before it resets";
    EXPECT_GE(quick_phases, 3) << range;
    EXPECT_LT(max_speed, 600.0) << "quick phases are saccades, not jumps";
    // Between quick phases the gaze is held in the world: over 100 ms at 60 deg/s the head
    // turns 6 deg; the world gaze moves not at all in most such stretches.
    int held = 0;
    for (std::int64_t t = 600 * kMs; t < 4'400 * kMs; t += 100 * kMs)
      if (angle_deg(world_gaze(sim, t), world_gaze(sim, t + 100 * kMs)) < 1e-8) ++held;
    EXPECT_GT(held, 15);
  }
}

TEST(Vor, WindowLeavesTheGazeAloneOutsideAndEndsWithAQuickPhase) {
  Simulator ref = make_sim(base_scenario({sweep(), saccades()}));
  Simulator sim = make_sim(base_scenario({sweep(), saccades(), {{"type", "vor"}, {"start_s", 2}, {"end_s", 5}}}));
  for (std::int64_t t = 0; t < 2'000 * kMs; t += 7 * kMs) EXPECT_EQ(eye(sim, t), eye(ref, t));
  for (std::int64_t t = 5'300 * kMs; t < 8'000 * kMs; t += 7 * kMs) EXPECT_EQ(eye(sim, t), eye(ref, t));
  double differs = 0.0, max_speed = 0.0;
  glm::dvec3 prev = eye(sim, 1'900 * kMs);
  for (std::int64_t t = 1'900 * kMs; t < 5'300 * kMs; t += kStep) {
    const glm::dvec3 d = eye(sim, t);
    differs = std::max(differs, angle_deg(d, eye(ref, t)));
    max_speed = std::max(max_speed, angle_deg(prev, d) / 1e-4);
    prev = d;
  }
  EXPECT_GT(differs, 1.0);
  EXPECT_LT(max_speed, 600.0) << "continuous at start_s and end_s";
}

TEST(Vor, RefusesBadParameters) {
  EXPECT_THROW(make_sim(base_scenario({saccades(), {{"type", "vor"}, {"gain", 3}}})), ScenarioError);
  EXPECT_THROW(make_sim(base_scenario({saccades(), {{"type", "vor"}, {"range_deg", 0}}})), ScenarioError);
  EXPECT_THROW(make_sim(base_scenario({saccades(), {{"type", "vor"}, {"gian", 1}}})), ScenarioError);
  EXPECT_THROW(make_sim(base_scenario({saccades(), {{"type", "vor"}, {"start_s", 3}, {"end_s", 2}}})), ScenarioError);
}

bool same_bits(const glm::dvec3& a, const glm::dvec3& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(Vor, SameSeedSameBitsInAnyQueryOrder) {
  // The default scenario lists vor (with head sweeps, a fast turn and a pursuit).
  const Scenario sc = load_scenario_json(default_scenario_json(), "<default>");
  Simulator a(sc), b(sc), c(sc);
  std::vector<std::int64_t> times;
  for (std::int64_t t = 0; t < a.duration_ns(); t += 3'333'333) times.push_back(t);
  std::vector<glm::dvec3> truth, tracked;
  for (std::int64_t t : times) {
    truth.push_back(a.true_gaze_at(t).direction);
    tracked.push_back(a.tracker_at(t).direction);
  }
  std::vector<std::size_t> order(times.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (std::size_t i : order) {
    ASSERT_TRUE(same_bits(b.true_gaze_at(times[i]).direction, truth[i])) << times[i];
    ASSERT_TRUE(same_bits(b.tracker_at(times[i]).direction, tracked[i])) << times[i];
  }
  for (std::size_t i = times.size(); i-- > 0;) ASSERT_TRUE(same_bits(c.true_gaze_at(times[i]).direction, truth[i]));
  // The vor actually acts in the default: the eye differs from the same scenario without it.
  nlohmann::json j = nlohmann::json::parse(default_scenario_json());
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : j["effects"])
    if (e["type"] != "vor") effects.push_back(e);
  j["effects"] = effects;
  Simulator novor(load_scenario_json(j.dump(), "novor"));
  double differs = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i)
    differs = std::max(differs, angle_deg(novor.true_gaze_at(times[i]).direction, truth[i]));
  EXPECT_GT(differs, 1.0);
}

}  // namespace
}  // namespace gazelod::sim
