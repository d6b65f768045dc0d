// SPDX-License-Identifier: Apache-2.0
// The switch policy: refinement at once, coarsening after the hold to the finest level allowed
// in the window, suppression preferred with a bounded deferral, the flicker case, reset,
// validation, non-finite time, and a seeded randomized check of the invariants.
#include "lod/switch_policy.hpp"

#include "lod/motion_bound.hpp"
#include "lod/object_set.hpp"
#include "lod/select.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// n objects' caller-owned state, reset to level 0.
struct Objects {
  explicit Objects(std::size_t n, std::uint8_t level = 0) : drawn(n), finest(n), start(n), held(n, 0xff) {
    EXPECT_EQ(reset_switch_state(state(), level), "");
  }
  SwitchState state() { return {drawn, finest, start}; }
  // One frame with every object's perceptual level `p`.
  void frame(const SwitchPolicyConfig& c, double t, bool suppressed, std::uint8_t p) {
    const std::vector<std::uint8_t> lod(drawn.size(), p);
    ASSERT_EQ(apply_switch_policy(c, t, suppressed, lod, state(), held), "");
  }
  HoldReason why(std::size_t i = 0) const { return static_cast<HoldReason>(held[i]); }
  std::vector<std::uint8_t> drawn, finest;
  std::vector<double> start;
  std::vector<std::uint8_t> held;
};

SwitchPolicyConfig no_suppression(double hold = 0.2) {
  return {hold, 1.0, false};
}

TEST(SwitchPolicy, DefaultsAreValid) {
  const SwitchPolicyConfig c;
  EXPECT_EQ(validate_switch_config(c), "");
  EXPECT_EQ(c.coarsen_hold_s, 0.2);
  EXPECT_EQ(c.max_deferral_s, 0.6);
  EXPECT_TRUE(c.prefer_suppression);
}

TEST(SwitchPolicy, RefinementIsImmediate) {
  const SwitchPolicyConfig c;
  Objects o(1, 3);
  o.frame(c, 0.0, false, 1);  // finer than drawn: at once, not suppressed, no hold
  EXPECT_EQ(o.drawn[0], 1);
  EXPECT_EQ(o.why(), HoldReason::none);
  // During an open window, and while awaiting suppression, a finer level still comes at once.
  o.frame(c, 0.1, false, 3);
  EXPECT_EQ(o.why(), HoldReason::hold_time);
  o.frame(c, 0.5, false, 3);
  EXPECT_EQ(o.why(), HoldReason::awaiting_suppression);
  EXPECT_EQ(o.drawn[0], 1);
  o.frame(c, 0.51, false, 0);
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.why(), HoldReason::none);
  EXPECT_FALSE(std::isfinite(o.start[0]));  // the window closed
  // Without a valid time too.
  Objects q(1, 2);
  q.frame(c, kNaN, false, 0);
  EXPECT_EQ(q.drawn[0], 0);
}

TEST(SwitchPolicy, SteadyCoarserLevelReachedAfterHold) {
  const SwitchPolicyConfig c = no_suppression(0.25);
  Objects o(3);
  const double dt = 1.0 / 128;  // exact in binary: the frame at 0.25 s is exactly the hold
  for (int k = 0; k <= 64; ++k) {
    const double t = 1.0 + k * dt;  // window opens at t = 1
    o.frame(c, t, false, 2);
    if (k < 32) {
      ASSERT_EQ(o.drawn[0], 0) << k;
      ASSERT_EQ(o.why(), HoldReason::hold_time) << k;
    } else {
      ASSERT_EQ(o.drawn[0], 2) << k;
      ASSERT_EQ(o.why(), HoldReason::none) << k;
    }
  }
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 2, 2}));
  // Hold 0: the perceptual level at once.
  Objects z(1);
  z.frame(no_suppression(0.0), 0.0, false, 3);
  EXPECT_EQ(z.drawn[0], 3);
}

TEST(SwitchPolicy, CoarsensToFinestLevelAllowedDuringWindow) {
  const SwitchPolicyConfig c = no_suppression(0.25);
  Objects o(1);
  const double dt = 1.0 / 16;                  // exact in binary
  const std::uint8_t seq[] = {3, 1, 2, 3, 2};  // all coarser than 0: the window stays open
  for (int k = 0; k < 5; ++k) {
    o.frame(c, k * dt, false, seq[k]);
    ASSERT_EQ(o.drawn[0], k < 4 ? 0 : 1) << k;
  }
  // At t = 0.25 it went to 1, the finest level allowed in [0, 0.25], not to this frame's 2.
  // 2 is still allowed: a new window opened at this frame, towards 2.
  EXPECT_EQ(o.why(), HoldReason::hold_time);
  EXPECT_EQ(o.finest[0], 2);
  EXPECT_EQ(o.start[0], 0.25);
  for (int k = 5; k <= 8; ++k) {
    o.frame(c, k * dt, false, 3);
    ASSERT_EQ(o.drawn[0], k < 8 ? 1 : 2) << k;  // the second window's finest, at t = 0.5
  }
}

// The default: a suppressed frame coarsens at once (no hold), to the finest level allowed
// since the window opened; outside suppression the hold and the deferral still apply.
TEST(SwitchPolicy, SuppressedFrameCoarsensAtOnceByDefault) {
  const SwitchPolicyConfig c;
  EXPECT_EQ(c.suppressed_hold_s, 0.0);
  Objects o(1);
  o.frame(c, 0.0, false, 2);
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.why(), HoldReason::hold_time);
  o.frame(c, 0.01, false, 1);  // the window's finest is now 1
  o.frame(c, 0.02, true, 3);   // suppressed: at once, to the window's finest
  EXPECT_EQ(o.drawn[0], 1);
  EXPECT_EQ(o.why(), HoldReason::hold_time);  // 3 is still allowed: a new window from now
  o.frame(c, 0.03, true, 3);
  EXPECT_EQ(o.drawn[0], 3);
  EXPECT_EQ(o.why(), HoldReason::none);
  // Flicker between L and L+1 switches only on suppressed frames (where it goes unseen) and
  // on the refinement right after: at most 2 per suppressed frame, none otherwise.
  Objects f(1, 1);
  int switches_outside = 0, suppressed_frames = 0, total = 0;
  for (int k = 0; k < 900; ++k) {
    const bool s = k % 20 == 0;
    const std::uint8_t before = f.drawn[0];
    f.frame(c, k / 90.0, s, static_cast<std::uint8_t>(1 + k % 2));
    total += f.drawn[0] != before;
    suppressed_frames += s;
    if (!s && f.drawn[0] > before) ++switches_outside;  // a coarsening outside suppression
  }
  EXPECT_EQ(switches_outside, 0);
  EXPECT_LE(total, 2 * suppressed_frames);
}

TEST(SwitchPolicy, SuppressedFrameReleasesCoarseningOnceHoldHasPassed) {
  SwitchPolicyConfig c;                    // hold 0.2, deferral 1.0, prefer suppression
  c.suppressed_hold_s = c.coarsen_hold_s;  // the full hold in suppression too
  Objects o(1);
  o.frame(c, 0.0, false, 2);
  o.frame(c, 0.1, true, 2);  // suppressed, but within the hold: nothing
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.why(), HoldReason::hold_time);
  for (double t = 0.2; t < 0.6; t += 0.05) {
    o.frame(c, t, false, 2);
    ASSERT_EQ(o.drawn[0], 0);
    ASSERT_EQ(o.why(), HoldReason::awaiting_suppression);
  }
  o.frame(c, 0.61, true, 2);  // the next suppressed frame
  EXPECT_EQ(o.drawn[0], 2);
  EXPECT_EQ(o.why(), HoldReason::none);
}

TEST(SwitchPolicy, DeferralIsBoundedWithoutSuppression) {
  // Dyadic times: the deadline 0.25 + 0.5 after the window opens is hit exactly.
  const SwitchPolicyConfig c{0.25, 0.5, true};
  Objects o(1);
  const double dt = 1.0 / 128;
  int coarsenings = 0;
  for (int k = 0; k <= 200; ++k) {
    const double t = 3.0 + k * dt;
    const std::uint8_t before = o.drawn[0];
    o.frame(c, t, false, 1);
    coarsenings += o.drawn[0] > before;
    if (k < 32) {
      ASSERT_EQ(o.why(), HoldReason::hold_time) << k;
    } else if (k < 96) {
      ASSERT_EQ(o.why(), HoldReason::awaiting_suppression) << k;
    }
    ASSERT_EQ(o.drawn[0], k < 96 ? 0 : 1) << k;
  }
  EXPECT_EQ(coarsenings, 1);
  // Defaults at 90 Hz: the coarsening frame is the first at or after hold + deferral (0.2 + 0.6 s).
  Objects d(1);
  const SwitchPolicyConfig def;
  int k = 0;
  for (; d.drawn[0] == 0 && k < 1000; ++k) d.frame(def, k / 90.0, false, 2);
  const double t_switch = (k - 1) / 90.0;
  const double due = def.coarsen_hold_s + def.max_deferral_s;
  EXPECT_GE(t_switch, due - 1e-9);
  EXPECT_LT(t_switch - 1.0 / 90.0, due);
}

// Switches (changes of the drawn level) of one object fed `seq` at 90 Hz.
int switches(const SwitchPolicyConfig& c, const std::vector<std::uint8_t>& seq, std::uint8_t start) {
  Objects o(1, start);
  int count = 0;
  for (std::size_t k = 0; k < seq.size(); ++k) {
    const std::uint8_t before = o.drawn[0];
    o.frame(c, static_cast<double>(k) / 90.0, k % 20 == 0, seq[k]);  // frequent suppression: no help to flicker
    count += o.drawn[0] != before;
  }
  return count;
}

TEST(SwitchPolicy, FlickerBetweenAdjacentLevelsNeverSwitches) {
  const std::uint8_t L = 1;
  std::vector<std::uint8_t> alternating(900), runs;  // 10 s at 90 Hz
  for (std::size_t k = 0; k < alternating.size(); ++k) alternating[k] = static_cast<std::uint8_t>(L + k % 2);
  // Random runs of L + 1 shorter than the hold (18 frames at 90 Hz), separated by L.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> run(1, 17), gap(1, 3);
  while (runs.size() < 900) {
    runs.insert(runs.end(), run(rng), std::uint8_t{L + 1});
    runs.insert(runs.end(), gap(rng), L);
  }
  for (const auto* seq : {&alternating, &runs}) {
    SwitchPolicyConfig full_hold;
    full_hold.suppressed_hold_s = full_hold.coarsen_hold_s;
    EXPECT_EQ(switches(full_hold, *seq, L), 0);
    EXPECT_EQ(switches(no_suppression(), *seq, L), 0);
    // Without the policy (hold 0, no suppression) the same noise switches on every flip.
    EXPECT_GT(switches(no_suppression(0.0), *seq, L), 100);
  }
}

TEST(SwitchPolicy, ResetDrawsLevelWithNoWindowOpen) {
  Objects o(4);
  o.frame(SwitchPolicyConfig{}, 0.0, false, 3);
  EXPECT_TRUE(std::isfinite(o.start[2]));
  ASSERT_EQ(reset_switch_state(o.state(), 2), "");
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(o.drawn[i], 2);
    EXPECT_EQ(o.finest[i], 2);
    EXPECT_FALSE(std::isfinite(o.start[i]));
  }
  // One object: a state of one-entry subspans.
  const SwitchState s = o.state();
  ASSERT_EQ(reset_switch_state({s.drawn.subspan(1, 1), s.finest_allowed.subspan(1, 1), s.window_start_s.subspan(1, 1)}),
            "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 0, 2, 2}));
  // A caller-written inconsistent entry (window "open" but finest not coarser than drawn)
  // counts as no window: it opens afresh, nothing coarsens early.
  o.start[0] = -100.0, o.finest[0] = 2;
  o.frame(no_suppression(), 0.0, false, 3);
  EXPECT_EQ(o.drawn[0], 2);
  EXPECT_EQ(o.start[0], 0.0);
  EXPECT_EQ(o.finest[0], 3);
}

TEST(SwitchPolicy, EmptySetAndEmptyHeld) {
  SwitchState empty{};
  EXPECT_EQ(apply_switch_policy(SwitchPolicyConfig{}, 0.0, false, {}, empty, {}), "");
  EXPECT_EQ(reset_switch_state(empty), "");
  Objects o(2);
  const std::vector<std::uint8_t> lod{1, 0};
  EXPECT_EQ(apply_switch_policy(no_suppression(0.0), 0.0, false, lod, o.state(), {}), "");
  EXPECT_EQ(o.drawn, lod);
}

TEST(SwitchPolicy, SizeMismatchRefusedAndNothingWritten) {
  Objects o(3, 1);
  const auto drawn = o.drawn, finest = o.finest;
  const std::vector<std::uint8_t> lod4(4, 0), lod3(3, 0);
  std::vector<std::uint8_t> held2(2, 0xff);
  const SwitchPolicyConfig c = no_suppression(0.0);
  EXPECT_NE(apply_switch_policy(c, 0.0, false, lod4, o.state(), o.held).find("state.drawn"), std::string::npos);
  EXPECT_NE(apply_switch_policy(c, 0.0, false, lod3, o.state(), held2).find("held"), std::string::npos);
  SwitchState s = o.state();
  s.window_start_s = s.window_start_s.first(2);
  EXPECT_NE(apply_switch_policy(c, 0.0, false, lod3, s, o.held).find("window_start_s"), std::string::npos);
  s = o.state(), s.finest_allowed = s.finest_allowed.first(1);
  EXPECT_NE(apply_switch_policy(c, 0.0, false, lod3, s, o.held).find("finest_allowed"), std::string::npos);
  EXPECT_NE(reset_switch_state(s, 3), "");
  EXPECT_EQ(o.drawn, drawn);
  EXPECT_EQ(o.finest, finest);
  EXPECT_EQ(held2, std::vector<std::uint8_t>(2, 0xff));
  EXPECT_EQ(o.held, std::vector<std::uint8_t>(3, 0xff));
}

TEST(SwitchPolicy, InvalidConfigRefused) {
  Objects o(1);
  const std::vector<std::uint8_t> lod{2};
  for (const SwitchPolicyConfig& c : {SwitchPolicyConfig{-0.1, 1.0, true}, SwitchPolicyConfig{kNaN, 1.0, true},
                                      SwitchPolicyConfig{0.2, kInf, true}, SwitchPolicyConfig{0.2, -1.0, false}}) {
    EXPECT_NE(validate_switch_config(c), "");
    EXPECT_NE(apply_switch_policy(c, 0.0, false, lod, o.state(), o.held), "");
  }
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.held[0], 0xff);
}

TEST(SwitchPolicy, NonFiniteTimeIsNoTimePassed) {
  const SwitchPolicyConfig c;
  for (double bad : {kNaN, kInf, -kInf}) {
    Objects o(1);
    // No window opens at an unknown time, even over many frames and suppressed ones.
    for (int k = 0; k < 200; ++k) o.frame(c, bad, true, 2);
    EXPECT_EQ(o.drawn[0], 0);
    EXPECT_EQ(o.why(), HoldReason::no_time);
    EXPECT_FALSE(std::isfinite(o.start[0]));
    // An open window keeps its start and takes the frame's level into its finest.
    o.frame(c, 1.0, false, 3);
    EXPECT_EQ(o.start[0], 1.0);
    o.frame(c, bad, true, 1);
    EXPECT_EQ(o.start[0], 1.0);
    EXPECT_EQ(o.finest[0], 1);
    EXPECT_EQ(o.drawn[0], 0);
    o.frame(c, 1.3, true, 3);  // hold passed, suppressed: to the finest seen, 1
    EXPECT_EQ(o.drawn[0], 1);
    EXPECT_TRUE(std::isfinite(o.start[0]));  // 3 still allowed: new window at 1.3
    EXPECT_EQ(o.start[0], 1.3);
  }
}

TEST(SwitchPolicy, ClockGoingBackRestartsWindow) {
  const SwitchPolicyConfig c = no_suppression(0.2);
  Objects o(1);
  o.frame(c, 10.0, false, 2);
  o.frame(c, 5.0, false, 2);  // back in time: the window restarts at 5, nothing coarsens
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.start[0], 5.0);
  o.frame(c, 5.1, false, 2);
  EXPECT_EQ(o.drawn[0], 0);
  o.frame(c, 5.2, false, 2);
  EXPECT_EQ(o.drawn[0], 2);
}

TEST(SwitchPolicy, HoldReasonNames) {
  EXPECT_STREQ(to_string(HoldReason::none), "none");
  EXPECT_STREQ(to_string(HoldReason::hold_time), "hold_time");
  EXPECT_STREQ(to_string(HoldReason::awaiting_suppression), "awaiting_suppression");
  EXPECT_STREQ(to_string(HoldReason::no_time), "no_time");
  EXPECT_STREQ(to_string(static_cast<HoldReason>(9)), "unknown");
}

// Randomized (seeded): objects with noisy perceptual levels (a slowly changing base, frame
// noise of +-1, occasional jumps), jittered frame times with some non-finite, saccade-like
// suppression bursts, random configurations. Checked against the history of each object:
//   - drawn never coarser than this frame's perceptual level;
//   - a coarsening to D from d: every frame from the last finite one at or before t - hold to
//     now allowed a level > d and >= D (never coarser than the minimum over the window);
//   - it coarsens exactly when due: when a coarser level has been allowed without a break for
//     at least the hold and (suppressed, or no preference, or for hold + max deferral);
//   - coarsenings of one object are at least the hold apart (<= 1 / hold per object-second).
TEST(SwitchPolicyProperty, NeverCoarserThanWindowMinimumAndRateBounded) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  constexpr std::size_t n = 48;
  constexpr int frames = 1800;  // ~20 s at 90 Hz
  for (int trial = 0; trial < 12; ++trial) {
    // The full hold in suppressed frames too (suppressed_hold_s = coarsen_hold_s): the model
    // below; the default's shorter hold there has its own test.
    const double hold = trial == 0 ? 0.0 : 0.5 * u(rng);
    const SwitchPolicyConfig c{hold, 2.0 * u(rng), u(rng) < 0.7, hold};
    Objects o(n);
    std::vector<double> base(n, 0.0);
    std::vector<std::vector<std::uint8_t>> p_hist(n);
    std::vector<double> t_hist;
    std::vector<double> run_start(n, kNaN), last_coarsen(n, -kInf);
    std::vector<int> coarsenings(n, 0);
    double t = 100.0 * u(rng), last_finite = t, first_t = t;
    int suppress_left = 0;
    std::vector<std::uint8_t> lod(n);
    for (int k = 0; k < frames; ++k) {
      t += (1.0 / 90.0) * (0.5 + u(rng));
      const double tf = u(rng) < 0.02 ? kNaN : t;  // a few frames without a valid time
      if (suppress_left > 0)
        --suppress_left;
      else if (u(rng) < 0.03)
        suppress_left = 3 + static_cast<int>(u(rng) * 6);
      const bool suppressed = suppress_left > 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (u(rng) < 0.01) base[i] = std::floor(u(rng) * 5.0);
        const double noise = u(rng) < 0.4 ? std::round(2.0 * u(rng) - 1.0) : 0.0;
        lod[i] = static_cast<std::uint8_t>(std::clamp(base[i] + noise, 0.0, 4.0));
      }
      const std::vector<std::uint8_t> before = o.drawn;
      ASSERT_EQ(apply_switch_policy(c, tf, suppressed, lod, o.state(), o.held), "");
      t_hist.push_back(tf);
      for (std::size_t i = 0; i < n; ++i) {
        p_hist[i].push_back(lod[i]);
        const std::uint8_t d = before[i], p = lod[i], now = o.drawn[i];
        ASSERT_LE(now, p) << trial << " " << k << " " << i;
        if (p <= d) {
          ASSERT_EQ(now, p);
          ASSERT_EQ(o.why(i), HoldReason::none);
          run_start[i] = kNaN;
          continue;
        }
        // The reference: the run of frames allowing a coarser level than d, timed from its
        // first finite frame.
        if (std::isnan(run_start[i]) && std::isfinite(tf)) run_start[i] = tf;
        const bool timed = std::isfinite(tf) && std::isfinite(run_start[i]);
        const double elapsed = timed ? tf - run_start[i] : -1.0;
        const bool due = timed && elapsed >= c.coarsen_hold_s &&
                         (suppressed || !c.prefer_suppression || elapsed >= c.coarsen_hold_s + c.max_deferral_s);
        ASSERT_EQ(now > d, due) << trial << " " << k << " " << i << " " << elapsed;
        if (!due) {
          ASSERT_EQ(now, d);
          ASSERT_NE(o.why(i), HoldReason::none);
          continue;
        }
        ++coarsenings[i];
        ASSERT_GE(tf - last_coarsen[i], c.coarsen_hold_s);
        last_coarsen[i] = tf;
        // Every frame of the window [run_start, tf] allowed > d and >= now; the window covers
        // at least the last hold seconds.
        std::uint8_t window_min = 255;
        for (int j = k; j >= 0; --j) {
          window_min = std::min(window_min, p_hist[i][j]);
          if (t_hist[j] == run_start[i]) break;  // the window's first frame
        }
        ASSERT_GT(window_min, d);
        ASSERT_EQ(now, window_min);
        run_start[i] = p > now ? tf : kNaN;  // a new run towards this frame's level
      }
      if (std::isfinite(tf)) last_finite = tf;
    }
    const double seconds = last_finite - first_t;
    if (c.coarsen_hold_s > 0.0) {
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_LE(coarsenings[i], 1.0 + seconds / c.coarsen_hold_s) << trial << " " << i;
    }
  }
}

// release_by_motion: the part of a coarsening that size and motion alone allow is drawn at once,
// the rest keeps the hold; off (the default) or without motion levels nothing changes.
TEST(SwitchPolicy, ReleaseByMotionDrawsTheMotionPartAtOnce) {
  SwitchPolicyConfig c;  // hold 0.2 s, deferral 0.6 s, suppression preferred
  EXPECT_FALSE(c.release_by_motion);
  c.release_by_motion = true;
  Objects o(3, 0);
  const std::vector<std::uint8_t> lod{3, 3, 3}, motion{3, 1, 0};
  ASSERT_EQ(apply_switch_policy(c, 0.0, false, lod, motion, o.state(), o.held), "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{3, 1, 0}));
  EXPECT_EQ(o.why(0), HoldReason::none);
  EXPECT_EQ(o.why(1), HoldReason::hold_time);  // 1 -> 3 still waits
  EXPECT_EQ(o.why(2), HoldReason::hold_time);
  // The rest of the coarsening follows the ordinary rule: after the hold, in suppression.
  ASSERT_EQ(apply_switch_policy(c, 0.25, true, lod, motion, o.state(), o.held), "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{3, 3, 3}));
  // Refinement stays immediate whatever the motion level says.
  const std::vector<std::uint8_t> fine{0, 0, 0};
  ASSERT_EQ(apply_switch_policy(c, 0.3, false, fine, motion, o.state(), o.held), "");
  EXPECT_EQ(o.drawn, fine);

  // Off, or no motion levels: the ordinary policy.
  for (bool on : {false, true}) {
    SwitchPolicyConfig off = c;
    off.release_by_motion = on;
    Objects p(3, 0);
    ASSERT_EQ(
        apply_switch_policy(off, 0.0, false, lod, on ? std::span<const std::uint8_t>() : motion, p.state(), p.held),
        "");
    EXPECT_EQ(p.drawn, fine);
  }
  // A frame without time releases nothing.
  Objects q(3, 0);
  ASSERT_EQ(apply_switch_policy(c, kNaN, false, lod, motion, q.state(), q.held), "");
  EXPECT_EQ(q.drawn, fine);
  // A motion level of the wrong length is refused, writing nothing.
  const std::vector<std::uint8_t> short_motion{3, 3};
  EXPECT_NE(apply_switch_policy(c, 1.0, false, lod, short_motion, q.state(), q.held).find("motion_level"),
            std::string::npos);
  EXPECT_EQ(q.drawn, fine);
}

// A field of moving and static objects under a head sweep with the eye carried by the head.
struct MotionField {
  MotionField() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<LodLevel> chain{{4000, 0, DetailKind::removed_cycles_per_diameter, 0.0},
                                      {1000, 0, DetailKind::removed_cycles_per_diameter, 30.0},
                                      {250, 0, DetailKind::removed_cycles_per_diameter, 15.0},
                                      {60, 0, DetailKind::removed_cycles_per_diameter, 7.0}};
    for (int i = 0; i < 300; ++i) {
      const glm::dvec3 c(20.0 * u(rng), 5.0 * u(rng), -12.0 - 10.0 * u(rng));
      const glm::dvec3 vel = i % 3 == 0 ? glm::dvec3(3.0 * u(rng), 0.0, 3.0 * u(rng)) : glm::dvec3(0.0);
      store.add(c, 0.2 + 0.15 * (u(rng) + 1.0), vel, chain);
    }
    viewer.xi_cpd = 20.0;
    viewer.head_angular_velocity_rad_s = glm::dvec3(0.0, 0.7, 0.0);  // a 40 deg/s yaw sweep
    viewer.gaze_angular_velocity_in_head_rad_s = glm::dvec3(0.0);    // carried: no VOR
    viewer.tracker_error_deg = 1.0;
  }
  std::vector<std::uint8_t> select(const Viewer& v) {
    const std::size_t n = store.size();
    std::vector<std::uint8_t> lod(n), a(n), b(n), c(n), d(n);
    EXPECT_EQ(select_lods(v, store.view(), {lod, a, b, c, d, {}, {}, {}}), "");
    return lod;
  }
  ObjectStore store;
  Viewer viewer;
};

// The size-and-motion level is select_lods with eccentricity off, for the candidates only, and
// no gaze direction or tracker error changes it (what makes it safe to release without the hold).
TEST(MotionBound, GazeIndependentAndCandidatesOnly) {
  MotionField f;
  const std::size_t n = f.store.size();
  Viewer sv = f.viewer;
  sv.use_eccentricity = false;
  const std::vector<std::uint8_t> reference = f.select(sv);
  std::uint8_t coarsest = 0;
  for (std::uint8_t l : reference) coarsest = std::max(coarsest, l);
  ASSERT_GE(coarsest, 2);  // the sweep does coarsen something by motion
  const std::vector<std::uint8_t> perceptual(n, 3);
  std::vector<std::uint8_t> drawn(n, 0);
  for (std::size_t i = 0; i < n; i += 4) drawn[i] = 3;  // not candidates
  MotionBoundScratch scratch;
  std::vector<std::uint8_t> out(n, 0xff);
  ASSERT_EQ(motion_bound_levels(f.viewer, f.store.view(), perceptual, drawn, scratch, out), "");
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(out[i], i % 4 == 0 ? 0 : reference[i]) << i;

  // Any gaze direction and error cone: the same levels.
  const std::vector<glm::dvec3> gazes{{0, 0, -1}, {0.5, 0.1, -1}, {-0.7, -0.3, -0.4}, {1, 0, 0}, {0, 0, 1}};
  for (const glm::dvec3& g : gazes)
    for (double err : {0.0, 2.0, 20.0}) {
      Viewer v = f.viewer;
      v.gaze_direction = g;
      v.tracker_error_deg = err;
      std::vector<std::uint8_t> o2(n, 0xff);
      ASSERT_EQ(motion_bound_levels(v, f.store.view(), perceptual, drawn, scratch, o2), "");
      ASSERT_EQ(o2, out);
    }
  // Whereas the eye's rotation does change it: an eye holding the world still (VOR) sees the
  // static objects without head-sweep blur. The bound trusts the conditioner's motion class.
  Viewer vor = f.viewer;
  vor.gaze_angular_velocity_in_head_rad_s = -vor.head_angular_velocity_rad_s;
  std::vector<std::uint8_t> o3(n, 0xff);
  ASSERT_EQ(motion_bound_levels(vor, f.store.view(), perceptual, drawn, scratch, o3), "");
  EXPECT_NE(o3, out);

  // Over the eye rotations the tracker may not yet have told apart: the finest of the levels at
  // the estimate, at rest in the head and at rest in the world (here the VOR viewer's).
  Viewer at_rest = f.viewer;
  at_rest.gaze_angular_velocity_in_head_rad_s = glm::dvec3(0.3, 0.0, 0.1);  // some estimate
  Viewer at_rest_sv = at_rest;
  at_rest_sv.use_eccentricity = false;
  const std::vector<std::uint8_t> est = f.select(at_rest_sv);
  Viewer carried_sv = sv;  // eye-in-head 0
  Viewer world_sv = sv;
  world_sv.gaze_angular_velocity_in_head_rad_s = -f.viewer.head_angular_velocity_rad_s;
  const std::vector<std::uint8_t> carried = f.select(carried_sv), world = f.select(world_sv);
  std::vector<std::uint8_t> o5(n, 0xff);
  ASSERT_EQ(motion_bound_levels(at_rest, f.store.view(), perceptual, drawn, scratch, o5, {true, true}), "");
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(o5[i], i % 4 == 0 ? 0 : std::min({est[i], carried[i], world[i]})) << i;

  // Refusals write nothing.
  std::vector<std::uint8_t> wrong(n - 1, 0xff);
  EXPECT_NE(motion_bound_levels(f.viewer, f.store.view(), perceptual, drawn, scratch, wrong), "");
  EXPECT_EQ(wrong, std::vector<std::uint8_t>(n - 1, 0xff));
  Viewer bad = f.viewer;
  bad.xi_cpd = -1.0;
  std::vector<std::uint8_t> o4(n, 0xff);
  EXPECT_NE(motion_bound_levels(bad, f.store.view(), perceptual, drawn, scratch, o4), "");
  EXPECT_EQ(o4, std::vector<std::uint8_t>(n, 0xff));
}

}  // namespace
}  // namespace gazelod::lod
