// SPDX-License-Identifier: Apache-2.0
// A saccade ends at its landing (ConditionerConfig::saccade_ends_at_landing) and the
// post-saccadic window counts from there (post_saccade_from_landing). The velocity fit alone
// ends a saccade only once most of the flight has left its window, tens of ms after the
// landing, and the window counted from that last saccade-labelled sample closed 90-115 ms
// after the landing, so coarsenings made after the true ~50 ms of suppression were taken for
// hidden (docs/evaluation.md, "Scenario family", item 11).
#include "gaze/gaze_conditioner.hpp"

#include "tests/gaze/noisy_saccade.hpp"

#include <gtest/gtest.h>

#include <string>

namespace gazelod::gaze {
namespace {

// After 4 s of fixation: the long-run noise level is learnt over seconds (from a guess), as in
// any session but its first seconds; with less, the landing is put later, towards the old
// answer.
constexpr double kOnsetS = 4.0;
constexpr double kLatencyS = 0.02;  // each sample shown this much later

struct Ends {
  bool found = false;
  double last_saccade_s = -1.0;     // the newest sample time read as saccade, after the true end
  double last_suppressed_s = -1.0;  // the last display time with suppressed, after the true end
  int fixation_frames_off = 0;      // frames after the window read as anything but a fixation
};

// A main-sequence saccade of `amplitude_deg` (yaw) at kOnsetS, then a fixation for 0.7 s;
// samples at rate_hz with noise_deg of noise (RMS over both axes).
Ends run(const ConditionerConfig& config, double amplitude_deg, double rate_hz, double noise_deg, unsigned seed) {
  GazeConditioner c(config);
  test::NoisySaccade saccade(amplitude_deg, kOnsetS, noise_deg, seed);
  const double end = saccade.end_s();
  const glm::dquat still{1.0, 0.0, 0.0, 0.0};
  Ends e;
  for (int i = 0; i < static_cast<int>((kOnsetS + 0.7) * rate_hz); ++i) {
    const double t = i / rate_hz;
    c.push(saccade.sample(t), still);
    const double shown = t + kLatencyS;
    const ConditionedGaze out = c.at(test::NoisySaccade::at_ns(shown), still);
    if (out.motion == EyeMotion::saccade && t >= kOnsetS - 0.02) {  // not noise read as one before
      e.found = true;
      e.last_saccade_s = t - end;
    }
    if (out.suppressed && t > kOnsetS) e.last_suppressed_s = shown - end;
    if (shown > end + 0.25) e.fixation_frames_off += out.motion != EyeMotion::fixation ? 1 : 0;
  }
  return e;
}

TEST(ConditionerLanding, SaccadeEndsAndItsWindowCountsFromTheLanding) {
  ConditionerConfig old;
  old.saccade_ends_at_landing = false;
  old.post_saccade_from_landing = false;
  const ConditionerConfig now;
  const double post_s = static_cast<double>(now.post_saccade_suppression_ns) * 1e-9;
  double lag_now = 0.0, lag_old = 0.0;
  int cases = 0;
  for (const double amplitude : {4.0, 10.0, 20.0})
    for (const double rate : {120.0, 250.0})
      for (const double noise : {0.2, 0.5, 1.0, 1.5})
        for (unsigned seed = 1; seed <= 5; ++seed) {
          const std::string what = std::to_string(amplitude) + " deg, " + std::to_string(rate) + " Hz, " +
                                   std::to_string(noise) + " deg noise, seed " + std::to_string(seed);
          const Ends a = run(now, amplitude, rate, noise, seed);
          const Ends b = run(old, amplitude, rate, noise, seed);
          // A small saccade under much noise is below the velocity test's threshold either way
          // (4 deg at 120 Hz and 1.5 deg of noise).
          ASSERT_EQ(a.found, b.found) << what;
          if (!a.found) {
            EXPECT_TRUE(amplitude < 5.0 && noise > 1.0) << what;
            continue;
          }
          // Read as a saccade until at most the landing's own samples (25 ms) and a sample
          // interval after the landing.
          EXPECT_LE(a.last_saccade_s, 0.025 + 1.0 / rate) << what;
          // ... and not in flight: at most a sample interval before the end (the flight's
          // last, slow, part within the noise). A slope limit from the landing's own few
          // samples let a noisy tracker's flight through at its peak speed, 6-8 deg short.
          EXPECT_GE(a.last_saccade_s, -1.0 / rate - 0.003) << what;
          EXPECT_LE(a.last_saccade_s, b.last_saccade_s) << what;
          // Vision is taken as suppressed until about post_s after the landing: not past it by
          // more than the landing estimate's sample, and not long before the true ~50 ms (the
          // estimate may fall on the flight's last, slow, part within the noise). At 1.5 deg of
          // noise the estimate errs by up to 15 ms more either way.
          const double tol = noise > 1.0 ? 0.015 : 0.0;
          EXPECT_LE(a.last_suppressed_s, post_s + 1.0 / rate + tol) << what;
          EXPECT_GE(a.last_suppressed_s, 0.04 - tol) << what;
          EXPECT_EQ(a.fixation_frames_off, 0) << what;
          lag_now += a.last_saccade_s;
          lag_old += b.last_saccade_s;
          ++cases;
        }
  // The velocity fit's lag, which the landing test removes most of (here 24 -> 9 ms on average).
  EXPECT_GT((lag_old - lag_now) / cases, 0.010) << "old " << lag_old / cases << " s, now " << lag_now / cases << " s";
}

}  // namespace
}  // namespace gazelod::gaze
