// SPDX-License-Identifier: Apache-2.0
#include "plugin/gaze_arbiter.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace gazelod::plugin {
namespace {

// A scripted source: available on the listed frames only.
class ScriptedSource : public gaze::GazeSource {
 public:
  ScriptedSource(std::string name, std::function<bool(std::int64_t)> available)
      : name_(std::move(name)), available_(std::move(available)) {}
  std::string name() const override { return name_; }
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override {
    if (!available_(t_ns)) return std::nullopt;
    gaze::GazeSample s;
    s.t_ns = t_ns;
    s.valid = true;
    return s;
  }
  std::string status() const override { return "scripted gap"; }

 private:
  std::string name_;
  std::function<bool(std::int64_t)> available_;
};

constexpr std::int64_t kMs = 1'000'000;

struct Log {
  std::vector<GazeSourceKind> sources;
  std::vector<std::string> reasons;
};

GazeArbiter make(gaze::GazeSource* p, gaze::GazeSource* s, Log& log) {
  GazeArbiter a(p, s, {1000 * kMs});
  a.on_change([&log](GazeSourceKind now, const std::string& why) {
    log.sources.push_back(now);
    log.reasons.push_back(why);
  });
  return a;
}

TEST(GazeArbiter, UsesPrimaryWhenItDelivers) {
  ScriptedSource primary("openxr", [](std::int64_t) { return true; });
  Log log;
  auto a = make(&primary, nullptr, log);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(a.update(i * 11 * kMs).source, GazeSourceKind::openxr);
  ASSERT_EQ(log.sources.size(), 1u);  // reported once
}

TEST(GazeArbiter, DistrustsARuntimeThatAdvertisesButNeverDelivers) {
  ScriptedSource silent("openxr", [](std::int64_t) { return false; });
  ScriptedSource hid("hid", [](std::int64_t) { return true; });
  Log log;
  auto a = make(&silent, &hid, log);
  EXPECT_EQ(a.update(0).source, GazeSourceKind::external);
  EXPECT_FALSE(a.primary_distrusted());
  a.update(1500 * kMs);
  EXPECT_TRUE(a.primary_distrusted());
  ASSERT_GE(log.reasons.size(), 2u);
  EXPECT_NE(log.reasons.back().find("delivered no usable eye gaze in"), std::string::npos);
  EXPECT_EQ(log.sources.back(), GazeSourceKind::external);
}

// The silence timer starts when the session becomes focused, not at the first frame: an
// application that renders for 3 s before FOCUSED does not lose the runtime's gaze for it.
TEST(GazeArbiter, SilenceTimerStartsAtFocused) {
  ScriptedSource silent("openxr", [](std::int64_t) { return false; });
  Log log;
  auto a = make(&silent, nullptr, log);
  a.session_state(false, 0);  // READY: the application reports states
  for (std::int64_t t = 0; t <= 3000 * kMs; t += 11 * kMs) a.update(t);
  EXPECT_FALSE(a.primary_distrusted()) << "not focused yet";
  a.session_state(true, 3000 * kMs);  // FOCUSED
  a.update(3900 * kMs);
  EXPECT_FALSE(a.primary_distrusted()) << "0.9 s after FOCUSED";
  a.update(4001 * kMs);
  EXPECT_TRUE(a.primary_distrusted()) << "1.001 s after FOCUSED";
}

// Without any reported state the timer runs from the first update (applications that do
// not forward their events).
TEST(GazeArbiter, SilenceTimerFromFirstFrameWithoutStates) {
  ScriptedSource silent("openxr", [](std::int64_t) { return false; });
  Log log;
  auto a = make(&silent, nullptr, log);
  a.update(500 * kMs);
  a.update(1400 * kMs);
  EXPECT_FALSE(a.primary_distrusted());
  a.update(1501 * kMs);
  EXPECT_TRUE(a.primary_distrusted());
}

TEST(GazeArbiter, FallsBackDuringGapsAndReturns) {
  // Delivers except between 100 and 200 ms.
  ScriptedSource primary("openxr", [](std::int64_t t) { return t < 100 * kMs || t >= 200 * kMs; });
  Log log;
  auto a = make(&primary, nullptr, log);
  EXPECT_EQ(a.update(0).source, GazeSourceKind::openxr);
  EXPECT_EQ(a.update(150 * kMs).source, GazeSourceKind::head_fixed);
  EXPECT_EQ(a.update(160 * kMs).source, GazeSourceKind::head_fixed);
  EXPECT_EQ(a.update(250 * kMs).source, GazeSourceKind::openxr);
  ASSERT_EQ(log.sources.size(), 3u);  // primary, head-fixed, primary: one report per change
  EXPECT_NE(log.reasons[1].find("scripted gap"), std::string::npos);
  EXPECT_FALSE(a.primary_distrusted());  // it had delivered: a gap is not distrust
}

// A source that reports blinks as invalid samples (as the OpenXR and pushed sources do once
// they have delivered): invalid inside [from, to).
class BlinkingSource : public gaze::GazeSource {
 public:
  BlinkingSource(std::int64_t from_ns, std::int64_t to_ns) : from_(from_ns), to_(to_ns) {}
  std::string name() const override { return "openxr"; }
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override {
    gaze::GazeSample s;
    s.t_ns = t_ns;
    s.valid = t_ns < from_ || t_ns >= to_;
    return s;
  }
  std::string status() const override { return "gaze not tracked (blink or lost)"; }

 private:
  std::int64_t from_, to_;
};

TEST(GazeArbiter, BlinkIsBridgedWithItsInvalidSamplesThenLossFallsBack) {
  Log log;
  BlinkingSource blink(100 * kMs, 250 * kMs);  // a 150 ms blink
  auto a = make(&blink, nullptr, log);
  for (std::int64_t t = 0; t < 400 * kMs; t += 10 * kMs) {
    const ArbiterResult r = a.update(t);
    EXPECT_EQ(r.source, GazeSourceKind::openxr) << "t " << t / kMs << " ms: the blink stays on the source";
    EXPECT_EQ(r.sample.valid, t < 100 * kMs || t >= 250 * kMs) << "t " << t / kMs << " ms";
  }
  EXPECT_EQ(log.sources.size(), 1u) << "no source change to report";

  Log lost_log;
  BlinkingSource lost(100 * kMs, 2000 * kMs);  // lost for longer than the bridge (300 ms)
  auto b = make(&lost, nullptr, lost_log);
  for (std::int64_t t = 0; t < 1000 * kMs; t += 10 * kMs) {
    const ArbiterResult r = b.update(t);
    const bool bridged = t - 90 * kMs <= 300 * kMs;  // the last usable sample at 90 ms
    EXPECT_EQ(r.source, bridged ? GazeSourceKind::openxr : GazeSourceKind::head_fixed) << "t " << t / kMs << " ms";
  }
  ASSERT_EQ(lost_log.sources.size(), 2u);
  EXPECT_EQ(lost_log.sources.back(), GazeSourceKind::head_fixed);
}

TEST(GazeArbiter, HeadFixedWithoutAnySource) {
  Log log;
  auto a = make(nullptr, nullptr, log);
  EXPECT_EQ(a.update(0).source, GazeSourceKind::head_fixed);
  ASSERT_EQ(log.sources.size(), 1u);
  EXPECT_NE(log.reasons[0].find("head-fixed"), std::string::npos);
}

TEST(GazeArbiter, SecondaryUnpluggedMidRunFallsToHeadFixed) {
  ScriptedSource hid("hid", [](std::int64_t t) { return t < 50 * kMs; });
  Log log;
  auto a = make(nullptr, &hid, log);
  EXPECT_EQ(a.update(0).source, GazeSourceKind::external);
  EXPECT_EQ(a.update(60 * kMs).source, GazeSourceKind::head_fixed);
  EXPECT_NE(log.reasons.back().find("hid unavailable"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::plugin
