// SPDX-License-Identifier: Apache-2.0
// The switch policy's release by regret (SwitchPolicyConfig::release_regret_s): a coarsening
// that saves many triangles goes after the hold, one that saves few waits for suppression; the
// seam of the rule; never before the hold and never coarser than the window allowed; off
// without costs; the costs' validation; and a seeded randomized check of the invariants.
#include "lod/switch_policy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <limits>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Object 0 saves 18 750 triangles going from level 0 to 2, object 1 saves 200.
const std::vector<std::uint32_t> kTriangles{20000, 5000, 1250, 313, 400, 300, 200, 100};
const std::vector<std::uint32_t> kFirst{0, 4};

struct Objects {
  explicit Objects(std::size_t n) : drawn(n), finest(n), start(n), held(n, 0xff) {
    EXPECT_EQ(reset_switch_state(state()), "");
  }
  SwitchState state() { return {drawn, finest, start}; }
  std::string frame(const SwitchPolicyConfig& c, double t, bool suppressed, const std::vector<std::uint8_t>& lod,
                    const SwitchCosts& costs) {
    return apply_switch_policy(c, t, suppressed, lod, {}, costs, state(), held);
  }
  HoldReason why(std::size_t i) const { return static_cast<HoldReason>(held[i]); }
  std::vector<std::uint8_t> drawn, finest;
  std::vector<double> start;
  std::vector<std::uint8_t> held;
};

SwitchPolicyConfig regret(double s) {
  SwitchPolicyConfig c;  // hold 0.2 s, deferral 0.6 s, suppression preferred
  c.release_regret_s = s;
  return c;
}

TEST(SwitchRegret, BigSavingGoesAfterTheHoldSmallOneWaitsForSuppression) {
  const SwitchCosts costs{kTriangles, kFirst, 1000.0};  // a switch is worth 0.8 * 1000 triangle-seconds
  Objects o(2);
  const std::vector<std::uint8_t> coarser{2, 2};
  ASSERT_EQ(o.frame(regret(0.8), 0.0, false, coarser, costs), "");
  ASSERT_EQ(o.frame(regret(0.8), 0.1, false, coarser, costs), "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{0, 0}));  // within the hold: both wait
  EXPECT_EQ(o.why(0), HoldReason::hold_time);
  ASSERT_EQ(o.frame(regret(0.8), 0.2, false, coarser, costs), "");
  // 18 750 * 0.2 s = 3 750 >= 800: released without suppression; 200 * 0.2 = 40 is not.
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 0}));
  EXPECT_EQ(o.why(0), HoldReason::none);
  EXPECT_EQ(o.why(1), HoldReason::awaiting_suppression);
  ASSERT_EQ(o.frame(regret(0.8), 0.5, true, coarser, costs), "");  // a saccade: the small one goes now
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 2}));
}

TEST(SwitchRegret, SmallSavingWithoutSuppressionGoesAtTheDeadline) {
  const SwitchCosts costs{kTriangles, kFirst, 1000.0};
  Objects o(2);
  const std::vector<std::uint8_t> coarser{0, 2};
  for (double t : {0.0, 0.2, 0.5, 0.79}) ASSERT_EQ(o.frame(regret(0.8), t, false, coarser, costs), "");
  EXPECT_EQ(o.drawn[1], 0);  // 200 * 0.79 = 158 < 800
  ASSERT_EQ(o.frame(regret(0.8), 0.8, false, coarser, costs), "");
  EXPECT_EQ(o.drawn[1], 2);  // hold + deferral
}

// The seam: saved * elapsed == worth releases, just below does not (exact in binary).
TEST(SwitchRegret, ReleasedExactlyWhenTheKeptTrianglesReachTheWorth) {
  const std::vector<std::uint32_t> tri{3000, 2000};
  const std::vector<std::uint32_t> first{0};
  const SwitchCosts costs{tri, first, 1000.0};  // worth 0.5 * 1000 = 500 = (3000 - 2000) * 0.5 s
  SwitchPolicyConfig c = regret(0.5);
  c.max_deferral_s = 1.0;
  Objects o(1);
  for (double t : {0.0, 0.25, 0.375}) ASSERT_EQ(o.frame(c, t, false, {1}, costs), "");
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.why(0), HoldReason::awaiting_suppression);
  ASSERT_EQ(o.frame(c, 0.5, false, {1}, costs), "");
  EXPECT_EQ(o.drawn[0], 1);
}

// Released to the finest level allowed since the window opened, never coarser.
TEST(SwitchRegret, ReleasesTheWindowsFinestLevel) {
  Objects o(1);
  const std::vector<std::uint32_t> first{0};
  const SwitchCosts one{std::span<const std::uint32_t>(kTriangles).first(4), first, 100.0};
  ASSERT_EQ(o.frame(regret(0.8), 0.0, false, {3}, one), "");
  ASSERT_EQ(o.frame(regret(0.8), 0.1, false, {1}, one), "");
  ASSERT_EQ(o.frame(regret(0.8), 0.2, false, {3}, one), "");
  EXPECT_EQ(o.drawn[0], 1);
}

// Off at 0, without costs, or with a unit of 0 triangles: the policy as without the rule.
TEST(SwitchRegret, OffItChangesNothing) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> level(0, 3);
  std::bernoulli_distribution suppressed(0.05);
  const std::vector<SwitchCosts> off_costs{SwitchCosts{}, SwitchCosts{kTriangles, kFirst, 0.0}};
  for (const SwitchCosts& costs : off_costs) {
    Objects a(2), b(2);
    for (int f = 0; f < 400; ++f) {
      const double t = f / 90.0;
      const bool s = suppressed(rng);
      const std::vector<std::uint8_t> lod{static_cast<std::uint8_t>(level(rng) / 2 + 1),
                                          static_cast<std::uint8_t>(level(rng))};
      ASSERT_EQ(apply_switch_policy(regret(0.8), t, s, lod, a.state(), a.held), "");
      ASSERT_EQ(b.frame(regret(0.8), t, s, lod, costs), "");
      ASSERT_EQ(a.drawn, b.drawn) << "frame " << f;
      ASSERT_EQ(a.held, b.held) << "frame " << f;
    }
  }
  Objects a(2), b(2);
  const SwitchCosts costs{kTriangles, kFirst, 1000.0};
  const std::vector<std::uint8_t> coarser{2, 2};
  for (double t : {0.0, 0.2, 0.4}) {
    ASSERT_EQ(apply_switch_policy(regret(0.8), t, false, coarser, a.state(), a.held), "");
    ASSERT_EQ(b.frame(regret(0.0), t, false, {2, 2}, costs), "");
  }
  EXPECT_EQ(a.drawn, b.drawn);
}

TEST(SwitchRegret, BadCostsOrSettingRefusedWritingNothing) {
  Objects o(2);
  const std::vector<std::uint8_t> lod{2, 3};
  const std::vector<std::uint32_t> one_first{0};
  const std::vector<std::uint32_t> short_tri{20000, 5000, 1250, 313, 400, 300};  // object 1 has no level 3
  const std::string wrong_length = o.frame(regret(0.8), 0.0, false, lod, SwitchCosts{kTriangles, one_first, 1.0});
  EXPECT_NE(wrong_length.find("costs.level_first has 1 entries, expected 2"), std::string::npos) << wrong_length;
  const std::string past = o.frame(regret(0.8), 0.0, false, lod, SwitchCosts{short_tri, kFirst, 1.0});
  EXPECT_NE(past.find("no entry for object 1's level 3"), std::string::npos) << past;
  // A drawn level past the costs is refused as well (a caller's state, not this frame's level).
  Objects drawn_past(2);
  drawn_past.drawn[1] = 3;
  const std::string drawn_err = drawn_past.frame(regret(0.8), 0.0, false, {0, 0}, SwitchCosts{short_tri, kFirst, 1.0});
  EXPECT_NE(drawn_err.find("no entry for object 1's level 3"), std::string::npos) << drawn_err;
  EXPECT_EQ(drawn_past.drawn, (std::vector<std::uint8_t>{0, 3}));
  for (double bad : {-0.1, kNaN, std::numeric_limits<double>::infinity()}) {
    EXPECT_NE(validate_switch_config(regret(bad)), "");
    EXPECT_NE(o.frame(regret(bad), 0.0, false, lod, SwitchCosts{kTriangles, kFirst, 1.0}), "");
    const std::string unit = o.frame(regret(0.8), 0.0, false, lod, SwitchCosts{kTriangles, kFirst, bad});
    EXPECT_NE(unit.find("costs.unit_triangles must be finite and >= 0"), std::string::npos) << unit;
  }
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{0, 0}));
  EXPECT_EQ(o.held, (std::vector<std::uint8_t>(2, 0xff)));
  EXPECT_TRUE(std::isnan(o.start[0]));
}

// Time as for the other rules: a frame without a finite time releases nothing by regret, and a
// clock that goes back restarts the window (the regret starts again from zero).
TEST(SwitchRegret, NoReleaseWithoutTimeAndAClockGoingBackStartsAgain) {
  const SwitchCosts costs{kTriangles, kFirst, 1000.0};  // object 0 at 0.2 s: 3 750 >= 800
  Objects o(2);
  const std::vector<std::uint8_t> coarser{2, 0};
  ASSERT_EQ(o.frame(regret(0.8), 10.0, false, coarser, costs), "");
  ASSERT_EQ(o.frame(regret(0.8), kNaN, false, coarser, costs), "");
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.why(0), HoldReason::no_time);
  ASSERT_EQ(o.frame(regret(0.8), 8.0, false, coarser, costs), "");  // back: the window restarts
  ASSERT_EQ(o.frame(regret(0.8), 8.125, false, coarser, costs), "");
  EXPECT_EQ(o.drawn[0], 0);
  EXPECT_EQ(o.why(0), HoldReason::hold_time);
  ASSERT_EQ(o.frame(regret(0.8), 8.25, false, coarser, costs), "");  // 18 750 * 0.25 >= 800
  EXPECT_EQ(o.drawn[0], 2);
}

// With release_by_motion the motion's share goes at once; the regret then counts what the rest
// of the coarsening saves, from the same window.
TEST(SwitchRegret, AfterAReleaseByMotionTheRestWaitsForItsOwnRegret) {
  SwitchPolicyConfig c = regret(0.8);
  c.release_by_motion = true;
  c.max_deferral_s = 2.0;  // no deadline in the way
  const SwitchCosts costs{kTriangles, kFirst, 1000.0};
  Objects o(2);
  const std::vector<std::uint8_t> lod{3, 3}, motion{2, 2};
  for (double t : {0.0, 0.1}) ASSERT_EQ(apply_switch_policy(c, t, false, lod, motion, costs, o.state(), o.held), "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 2}));  // motion's share: no hold
  ASSERT_EQ(apply_switch_policy(c, 0.2, false, lod, motion, costs, o.state(), o.held), "");
  // From 2 to 3: object 0 saves 937 * 0.2 s = 187 < 800, object 1 saves 100 * 0.2 = 20: both wait.
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 2}));
  EXPECT_EQ(o.why(0), HoldReason::awaiting_suppression);
  for (double t : {0.5, 0.85}) ASSERT_EQ(apply_switch_policy(c, t, false, lod, motion, costs, o.state(), o.held), "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{2, 2}));  // 937 * 0.85 = 796 < 800
  ASSERT_EQ(apply_switch_policy(c, 0.86, false, lod, motion, costs, o.state(), o.held), "");
  EXPECT_EQ(o.drawn, (std::vector<std::uint8_t>{3, 2}));  // 937 * 0.86 = 806: the window counts from 0
}

// Randomized (seeded): against a reference of the rule. Per object, the run of frames allowing
// a coarser level than the drawn one and the finest level in it; the policy coarsens exactly
// when the run has lasted the hold and (suppressed, or hold + deferral, or the saving times the
// run's length reaches the worth), to the run's finest level; never coarser than this frame's
// perceptual level, and one object's coarsenings at least the hold apart.
TEST(SwitchRegret, MatchesTheReferenceOnNoisyLevels) {
  std::mt19937 rng(2026);
  const std::size_t n = 2;
  std::uniform_int_distribution<int> jitter(-1, 1);
  std::bernoulli_distribution suppressed(0.03);
  const SwitchCosts costs{kTriangles, kFirst, 200.0};
  SwitchPolicyConfig c = regret(0.3);
  c.suppressed_hold_s = c.coarsen_hold_s;  // the full hold in suppression too: the spacing below
  Objects o(n);
  std::vector<double> run_start(n, kNaN), last_coarsening(n, -1e9);
  std::vector<std::uint8_t> run_finest(n, 0);
  std::vector<int> base{1, 2};
  int released_by_regret = 0;
  for (int f = 0; f < 3000; ++f) {
    const double t = f / 90.0;
    const bool s = suppressed(rng);
    std::vector<std::uint8_t> lod(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (f % 70 == 0) base[i] = std::uniform_int_distribution<int>(0, 3)(rng);
      lod[i] = static_cast<std::uint8_t>(std::clamp(base[i] + jitter(rng), 0, 3));
    }
    const std::vector<std::uint8_t> before = o.drawn;
    ASSERT_EQ(o.frame(c, t, s, lod, costs), "");
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t d = before[i], p = lod[i];
      ASSERT_LE(o.drawn[i], p) << "frame " << f << " object " << i;
      if (p <= d) {
        ASSERT_EQ(o.drawn[i], p);
        run_start[i] = kNaN;
        continue;
      }
      if (std::isnan(run_start[i])) run_start[i] = t, run_finest[i] = p;
      run_finest[i] = std::min(run_finest[i], p);
      const double elapsed = t - run_start[i];
      const double saved = double(kTriangles[kFirst[i] + d]) - double(kTriangles[kFirst[i] + run_finest[i]]);
      const bool by_regret = saved * elapsed >= c.release_regret_s * costs.unit_triangles;
      const bool due =
          elapsed >= c.coarsen_hold_s && (s || elapsed >= c.coarsen_hold_s + c.max_deferral_s || by_regret);
      ASSERT_EQ(o.drawn[i] > d, due) << "frame " << f << " object " << i << " elapsed " << elapsed;
      if (!due) continue;
      ASSERT_EQ(o.drawn[i], run_finest[i]);
      EXPECT_GE(t - last_coarsening[i], c.coarsen_hold_s - 1e-9) << "frame " << f << " object " << i;
      last_coarsening[i] = t;
      if (!s && elapsed < c.coarsen_hold_s + c.max_deferral_s) ++released_by_regret;
      if (p > o.drawn[i])
        run_start[i] = t, run_finest[i] = p;
      else
        run_start[i] = kNaN;
    }
  }
  EXPECT_GE(released_by_regret, 10);  // the rule was exercised, not only the old ones
}

}  // namespace
}  // namespace gazelod::lod
