// SPDX-License-Identifier: Apache-2.0
// The gaze conditioner's carried habit (ConditionerConfig::carried_prior_fixations): after a run
// of fixations carried by a sweeping head, the saccade and the next fixation are read as
// carried from their first sample rather than 40-70 ms into the fixation; a fixation held in
// the world ends the habit.
#include "gaze/gaze_conditioner.hpp"

#include "auxiliary/angles.hpp"
#include "auxiliary/yaw_pitch.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace gazelod::gaze {
namespace {

constexpr std::int64_t kT0 = 1'000'000'000;  // stream start, ns
constexpr double kRateHz = 120.0;
constexpr double kNoisePerAxisDeg = 0.5;
constexpr double kHeadDegS = 80.0;  // the head's sweep, constant: above carried_shift_deg_s, so no pursuit
constexpr double kFixationS = 0.3;
constexpr double kSaccadeS = 0.045;  // a 10 deg saccade (main sequence: ~43 ms)
constexpr double kSaccadeDeg = 10.0;
constexpr double kLatencyS = 0.015;  // display time - sample time

glm::dquat head_at(double t) {
  return glm::angleAxis(kHeadDegS * t * aux::kRadPerDeg, glm::dvec3(0, 1, 0));
}

// One sample's frame: where the phase was and what the conditioner said at the sample's time.
struct Read {
  int fixation = -1;    // index of the fixation (or the saccade before it: -1 - index)
  double into_s = 0.0;  // time into that phase
  ConditionedGaze out;
};

// Fixations of kFixationS, each carried by the head (true) or held in the world by the reflex
// (false), with a kSaccadeDeg saccade of the eye in the head before each but the first.
std::vector<Read> run(const ConditionerConfig& config, const std::vector<bool>& carried, unsigned seed) {
  GazeConditioner c(config);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, kNoisePerAxisDeg);
  std::vector<Read> reads;
  double t = 0.0;
  double eye_in_head_deg = 0.0;  // at the start of the phase
  double world_deg = 0.0;        // where a world-held fixation looks
  const double dt = 1.0 / kRateHz;
  const auto sample = [&](double eye_deg, int phase, double into) {
    const glm::dquat head = head_at(t);
    GazeSample s;
    s.t_ns = kT0 + static_cast<std::int64_t>(std::llround(t * 1e9));
    s.direction =
        aux::direction_from(aux::YawPitch{(eye_deg + noise(rng)) * aux::kRadPerDeg, noise(rng) * aux::kRadPerDeg});
    s.valid = true;
    s.confidence = 1.0f;
    c.push(s, head);
    reads.push_back(
        Read{phase, into, c.at(s.t_ns + static_cast<std::int64_t>(kLatencyS * 1e9), head_at(t + kLatencyS))});
    t += dt;
  };
  for (std::size_t i = 0; i < carried.size(); ++i) {
    const int k = static_cast<int>(i);
    if (i > 0) {
      const double from = eye_in_head_deg;
      for (double into = 0.0; into < kSaccadeS; into += dt) {
        const double f = 0.5 * (1.0 - std::cos(3.141592653589793 * into / kSaccadeS));
        sample(from + (k % 2 == 0 ? 1.0 : -1.0) * kSaccadeDeg * f, -1 - k, into);
      }
      eye_in_head_deg = from + (k % 2 == 0 ? 1.0 : -1.0) * kSaccadeDeg;
    }
    world_deg = eye_in_head_deg + kHeadDegS * t;
    const double start = t;
    while (t - start < kFixationS) {
      // Carried: still in the head. Held: still in the world, so the eye counter-rotates.
      const double eye = carried[i] ? eye_in_head_deg : world_deg - kHeadDegS * t;
      sample(eye, k, t - start);
    }
    eye_in_head_deg = carried[i] ? eye_in_head_deg : world_deg - kHeadDegS * t;
  }
  return reads;
}

// The first time into fixation k at which it is read as a fixation, and as a carried one
// (-1: never).
double first_fixation_s(const std::vector<Read>& reads, int k) {
  for (const Read& r : reads)
    if (r.fixation == k && r.out.motion == EyeMotion::fixation) return r.into_s;
  return -1.0;
}
double first_carried_s(const std::vector<Read>& reads, int k) {
  for (const Read& r : reads)
    if (r.fixation == k && r.out.motion == EyeMotion::fixation && r.out.carried) return r.into_s;
  return -1.0;
}
int carried_samples(const std::vector<Read>& reads, int k) {
  int n = 0;
  for (const Read& r : reads) n += r.fixation == k && r.out.carried ? 1 : 0;
  return n;
}

TEST(ConditionerHabit, AfterThreeCarriedFixationsTheNextStartsCarried) {
  ConditionerConfig off;
  off.carried_prior_fixations = 0.0;
  const std::vector<bool> all_carried(6, true);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto with = run(ConditionerConfig{}, all_carried, seed);
    const auto without = run(off, all_carried, seed);
    for (int k = 0; k < 6; ++k) {
      ASSERT_GE(first_fixation_s(without, k), 0.0) << "seed " << seed << " fixation " << k;
      ASSERT_GE(first_carried_s(without, k), 0.0) << "seed " << seed << " fixation " << k << ": earned on its own";
      // Without the habit a fixation needs a few samples' evidence (kMinPursuitSamples at
      // least) after its landing before it is read as carried (counted from the landing: the
      // saccade ends when its first samples there hold still, saccade_ends_at_landing).
      EXPECT_GE(first_carried_s(without, k), 3.5 / kRateHz) << "seed " << seed << " fixation " << k;
    }
    for (int k = 3; k < 6; ++k) {
      ASSERT_GE(first_fixation_s(with, k), 0.0) << "seed " << seed << " fixation " << k;
      EXPECT_EQ(first_carried_s(with, k), first_fixation_s(with, k))
          << "seed " << seed << " fixation " << k << ": carried from its landing";
      // The saccade before it too, with the head's rotation as the gaze's.
      int saccade_reads = 0;
      for (const Read& r : with) {
        if (r.fixation != -1 - k || r.out.motion != EyeMotion::saccade) continue;
        ++saccade_reads;
        EXPECT_TRUE(r.out.carried) << "seed " << seed << " saccade before fixation " << k;
        EXPECT_NEAR(glm::length(r.out.angular_velocity_world_rad_s) * aux::kDegPerRad, kHeadDegS, 1.0);
      }
      EXPECT_GT(saccade_reads, 0) << "seed " << seed << " saccade before fixation " << k;
    }
    // Fewer than three before it: no habit yet, nothing changes.
    for (int k = 0; k < 3; ++k) EXPECT_EQ(first_carried_s(with, k), first_carried_s(without, k)) << "seed " << seed;
  }
}

TEST(ConditionerHabit, AFixationHeldInTheWorldEndsTheHabit) {
  // Four carried fixations, then the reflex holds the world: the first held fixation starts
  // carried by habit, and its samples end that within a fraction of it; the run is then over,
  // so the next held fixation starts in the world.
  const std::vector<bool> phases{true, true, true, true, false, false, false};
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto reads = run(ConditionerConfig{}, phases, seed);
    const int held_first = carried_samples(reads, 4);
    EXPECT_GT(held_first, 0) << "seed " << seed << ": the habit starts it carried";
    EXPECT_LE(held_first, static_cast<int>(0.1 * kRateHz)) << "seed " << seed << ": read as held within 100 ms";
    EXPECT_EQ(carried_samples(reads, 5), 0) << "seed " << seed;
    EXPECT_EQ(carried_samples(reads, 6), 0) << "seed " << seed;
    for (const Read& r : reads) {
      if (r.fixation == -1 - 5 || r.fixation == -1 - 6) {
        EXPECT_FALSE(r.out.carried) << "seed " << seed;
      }
    }
  }
}

}  // namespace
}  // namespace gazelod::gaze
