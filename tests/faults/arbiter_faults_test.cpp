// SPDX-License-Identifier: Apache-2.0
// Faults through the gaze arbiter's state machine (plugin/gaze_arbiter.hpp) with scripted
// sources: NaN, zero-length and invalid samples, a frozen tracker, time jumping back, a source
// that disappears and comes back. Every change is reported once, with why; a sample that
// cannot be a gaze direction never reaches the LOD decision.
#include "plugin/gaze_arbiter.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

// Counts every allocation of this test program (g_allocations).
#include "tests/counting_new.hpp"

namespace gazelod::plugin {
namespace {

constexpr std::int64_t kMs = 1'000'000;

// A source whose next answer the test sets.
class ScriptedSource : public gaze::GazeSource {
 public:
  explicit ScriptedSource(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override {
    asked.push_back(t_ns);
    return next;
  }
  std::string status() const override { return status_text; }

  std::optional<gaze::GazeSample> next;
  std::string status_text = "ok";
  std::vector<std::int64_t> asked;

 private:
  std::string name_;
};

gaze::GazeSample sample(std::int64_t t_ns, glm::dvec3 dir, bool valid = true) {
  gaze::GazeSample s;
  s.t_ns = t_ns;
  s.direction = dir;
  s.valid = valid;
  s.confidence = valid ? 1.0f : 0.0f;
  return s;
}

struct Changes {
  std::vector<std::pair<GazeSourceKind, std::string>> seen;
  GazeArbiter::Changed sink() {
    return [this](GazeSourceKind s, const std::string& why) { seen.emplace_back(s, why); };
  }
};

const glm::dvec3 kAhead{0.0, 0.0, -1.0};
const double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ArbiterFaults, NanGazeFromTheRuntimeFallsBackInsteadOfReachingTheDecision) {
  ScriptedSource xr("openxr"), hid("hid");
  GazeArbiter a(&xr, &hid);
  Changes c;
  a.on_change(c.sink());
  xr.next = sample(0, kAhead);
  hid.next = sample(0, glm::normalize(glm::dvec3(0.1, 0.0, -1.0)));
  EXPECT_EQ(a.update(0).source, GazeSourceKind::openxr);
  for (const glm::dvec3 bad :
       {glm::dvec3(kNaN, 0.0, -1.0), glm::dvec3(0.0), glm::dvec3(std::numeric_limits<double>::infinity(), 0.0, 0.0)}) {
    xr.next = sample(10 * kMs, bad);
    const ArbiterResult r = a.update(10 * kMs);
    EXPECT_EQ(r.source, GazeSourceKind::external);
    EXPECT_TRUE(std::isfinite(r.sample.direction.x) && std::isfinite(r.sample.direction.z));
  }
  // Good gaze again: back to the runtime. Changes: primary, secondary, primary.
  xr.next = sample(20 * kMs, kAhead);
  EXPECT_EQ(a.update(20 * kMs).source, GazeSourceKind::openxr);
  ASSERT_EQ(c.seen.size(), 3u);
  EXPECT_EQ(c.seen[1].first, GazeSourceKind::external);
  EXPECT_NE(c.seen[1].second.find("openxr gaze unavailable"), std::string::npos) << c.seen[1].second;
}

TEST(ArbiterFaults, SamplesMarkedInvalidCountAsNoGaze) {
  ScriptedSource xr("openxr");
  GazeArbiter a(&xr, nullptr);
  xr.next = sample(0, kAhead, /*valid=*/false);
  EXPECT_EQ(a.update(0).source, GazeSourceKind::head_fixed);
  EXPECT_FALSE(a.primary_distrusted());
}

TEST(ArbiterFaults, ARuntimeDeliveringOnlyNanIsDistrustedAfterTheTimeout) {
  ScriptedSource xr("openxr");
  GazeArbiter a(&xr, nullptr, ArbiterConfig{500 * kMs});
  Changes c;
  a.on_change(c.sink());
  xr.next = sample(0, glm::dvec3(kNaN));
  for (std::int64_t t = 0; t <= 500 * kMs; t += 100 * kMs) a.update(t);
  EXPECT_FALSE(a.primary_distrusted());  // exactly the timeout: not yet
  a.update(600 * kMs);
  EXPECT_TRUE(a.primary_distrusted());
  xr.next = sample(700 * kMs, kAhead);  // good gaze after distrust is not taken any more
  EXPECT_EQ(a.update(700 * kMs).source, GazeSourceKind::head_fixed);
  ASSERT_EQ(c.seen.size(), 2u);  // head-fixed at start, then the distrust (reported again)
  EXPECT_NE(c.seen[1].second.find("delivered no usable eye gaze"), std::string::npos) << c.seen[1].second;
}

TEST(ArbiterFaults, FrozenTrackerKeepsItsSourceAndReportsNoChange) {
  // The source decides how long a sample may be held (HidGazeSource: 100 ms); the arbiter
  // takes what it is given and does not flap.
  ScriptedSource xr("openxr");
  GazeArbiter a(&xr, nullptr);
  Changes c;
  a.on_change(c.sink());
  xr.next = sample(5 * kMs, kAhead);
  for (int i = 0; i < 100; ++i) {
    const ArbiterResult r = a.update(5 * kMs + i * 11 * kMs);
    EXPECT_EQ(r.source, GazeSourceKind::openxr);
    EXPECT_EQ(r.sample.t_ns, 5 * kMs);
  }
  EXPECT_EQ(c.seen.size(), 1u);
}

TEST(ArbiterFaults, TimeJumpingBackNeitherDistrustsNorCrashes) {
  ScriptedSource xr("openxr");
  GazeArbiter a(&xr, nullptr, ArbiterConfig{1000 * kMs});
  a.update(5000 * kMs);  // nothing delivered yet
  a.update(100 * kMs);   // the clock jumps back 4.9 s
  a.update(5900 * kMs);
  EXPECT_FALSE(a.primary_distrusted());  // 0.9 s after the first frame, whatever came between
  EXPECT_EQ(xr.asked.back(), 5900 * kMs);
  a.update(6001 * kMs);
  EXPECT_TRUE(a.primary_distrusted());
}

TEST(ArbiterFaults, UnplugAndReplugOfTheExternalTrackerAreEachReportedOnce) {
  ScriptedSource xr("openxr"), hid("hid");
  GazeArbiter a(&xr, &hid, ArbiterConfig{100 * kMs});
  Changes c;
  a.on_change(c.sink());
  std::vector<GazeSourceKind> per_frame;
  for (int f = 0; f < 90; ++f) {
    const std::int64_t t = f * 11 * kMs;
    const bool plugged = f < 30 || f >= 60;  // unplugged for frames 30..59
    hid.next = plugged ? std::optional(sample(t, kAhead)) : std::nullopt;
    hid.status_text = plugged ? "ok" : "hid: unplugged";
    per_frame.push_back(a.update(t).source);
  }
  EXPECT_TRUE(a.primary_distrusted());  // the runtime never delivered
  EXPECT_EQ(per_frame[29], GazeSourceKind::external);
  EXPECT_EQ(per_frame[30], GazeSourceKind::head_fixed);
  EXPECT_EQ(per_frame[59], GazeSourceKind::head_fixed);
  EXPECT_EQ(per_frame[60], GazeSourceKind::external);
  // secondary (first frame), distrust of openxr (frame 10, re-reported), head-fixed, secondary.
  ASSERT_EQ(c.seen.size(), 4u);
  EXPECT_EQ(c.seen[2].first, GazeSourceKind::head_fixed);
  EXPECT_NE(c.seen[2].second.find("hid unavailable (hid: unplugged)"), std::string::npos) << c.seen[2].second;
  EXPECT_EQ(c.seen[3].first, GazeSourceKind::external);
}

// The plugin promises no allocation per frame after the first (plugin/gazelod.hpp): the
// arbiter spells out a reason only when it reports a change.
class FixedSource : public gaze::GazeSource {
 public:
  std::string name() const override { return "openxr"; }  // short: no allocation
  std::optional<gaze::GazeSample> sample_at(std::int64_t) override { return next; }
  std::optional<gaze::GazeSample> next;
};

TEST(ArbiterFaults, SteadyFramesAllocateNothingInAnyState) {
  FixedSource xr, hid;
  GazeArbiter a(&xr, &hid, ArbiterConfig{100 * kMs});
  Changes c;
  a.on_change(c.sink());
  c.seen.reserve(16);
  std::int64_t t = 0;
  auto steady = [&](GazeSourceKind expected) {
    a.update(t += 11 * kMs);  // may report (and allocate) a change
    const long before = g_allocations.load();
    for (int i = 0; i < 500; ++i) EXPECT_EQ(a.update(t += 11 * kMs).source, expected);
    return g_allocations.load() - before;
  };
  xr.next = sample(0, kAhead);
  EXPECT_EQ(steady(GazeSourceKind::openxr), 0);
  xr.next.reset();
  hid.next = sample(0, kAhead);
  EXPECT_EQ(steady(GazeSourceKind::external), 0);
  hid.next.reset();
  EXPECT_EQ(steady(GazeSourceKind::head_fixed), 0);
  EXPECT_EQ(c.seen.size(), 3u);
}

}  // namespace
}  // namespace gazelod::plugin
