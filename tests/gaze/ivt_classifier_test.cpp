// SPDX-License-Identifier: Apache-2.0
// I-VT classification: robust to tracker noise, finds every saccade >= 3 deg.
#include "gaze/gaze_events.hpp"
#include "gaze/ivt_classifier.hpp"
#include "tests/gaze/synth.hpp"

#include <gtest/gtest.h>

namespace gazelod::gaze {
namespace {

struct Counts {
  std::vector<SaccadeEvent> saccades;
  int fixations = 0;
};

Counts events_of(const std::vector<GazeSample>& samples) {
  Counts c;
  EventTracker tracker;
  auto take = [&](const EventTracker::Finished& f) {
    if (f.saccade) c.saccades.push_back(*f.saccade);
    if (f.fixation) ++c.fixations;
  };
  for (const auto& ls : classify_ivt(samples)) take(tracker.push(ls));
  take(tracker.finish());
  return c;
}

TEST(Ivt, NoFalseSaccadeInTenSecondFixationWithNoise) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    testing::Synth s;
    s.rng.seed(seed);
    s.noise_deg = 0.1;
    s.fixate(10.0);
    ASSERT_EQ(s.out.size(), 2500u);
    const auto labels = classify_ivt(s.out);
    ASSERT_EQ(labels.size(), s.out.size());
    int sacc = 0;
    for (const auto& l : labels) sacc += l.label == GazeLabel::saccade;
    EXPECT_EQ(sacc, 0) << "seed " << seed;
    const Counts c = events_of(s.out);
    EXPECT_EQ(c.saccades.size(), 0u);
    EXPECT_EQ(c.fixations, 1);
  }
}

TEST(Ivt, FindsEverySaccadeOfThreeDegreesOrMore) {
  for (double slow : {1.0, 2.0}) {  // also saccades twice as slow as the main sequence
    testing::Synth s;
    s.rng.seed(static_cast<unsigned>(slow * 10));
    std::vector<double> amps;
    s.fixate(0.3);
    int k = 0;
    for (double amp : {3.0, 3.5, 4.0, 5.0, 8.0, 12.0, 20.0, 30.0}) {
      for (double angle : {0.0, 45.0, 90.0, 160.0, 200.0, 270.0, 315.0}) {
        // Stay within +-35 deg: alternate direction.
        s.saccade(amp, (k++ % 2) ? angle + 180.0 : angle, slow);
        amps.push_back(amp);
        s.fixate(0.25);
      }
    }
    const Counts c = events_of(s.out);
    ASSERT_EQ(c.saccades.size(), amps.size()) << "slow " << slow;
    for (std::size_t i = 0; i < amps.size(); ++i) {
      // The smoothing window widens the labelled run, so amplitude >= ~true - noise.
      EXPECT_NEAR(c.saccades[i].amplitude_deg, amps[i], 0.25 * amps[i] + 0.5) << i;
      EXPECT_GT(c.saccades[i].peak_velocity_deg_s, 30.0);
    }
    EXPECT_EQ(c.fixations, static_cast<int>(amps.size()) + 1);
  }
}

TEST(Ivt, InvalidSamplesAndGapsAreNotSaccades) {
  testing::Synth s;
  s.fixate(0.5);
  s.blink(0.15);
  s.pitch_deg = 2.0;  // eye moved during the blink: no valid samples show it
  s.fixate(0.5);
  const auto labels = classify_ivt(s.out);
  int sacc = 0, invalid = 0;
  for (const auto& l : labels) {
    sacc += l.label == GazeLabel::saccade;
    invalid += l.label == GazeLabel::invalid;
  }
  EXPECT_EQ(sacc, 0);
  EXPECT_EQ(invalid, 38);  // 0.15 s at 250 Hz, rounded
  // Indices are the input positions, in order.
  for (std::size_t i = 0; i < labels.size(); ++i) ASSERT_EQ(labels[i].index, i);
}

TEST(Ivt, VelocityOfConstantRotationIsExact) {
  // Smooth pursuit at 20 deg/s: least-squares slope of a linear ramp is exact.
  testing::Synth s;
  s.noise_deg = 0.0;
  for (int i = 0; i < 100; ++i) s.emit(20.0 * i / 250.0, 0.0);
  const auto labels = classify_ivt(s.out);
  EXPECT_NEAR(labels[50].velocity_deg_s, 20.0, 0.02);
  EXPECT_EQ(labels[50].label, GazeLabel::fixation);
}

}  // namespace
}  // namespace gazelod::gaze
