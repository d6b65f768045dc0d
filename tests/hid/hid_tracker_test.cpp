// SPDX-License-Identifier: Apache-2.0
// The device thread against the fake hidapi: discovery by usage page, feature reports and the
// gaze-mode request, samples from recorded report bytes, bad reports counted and skipped,
// unplug / replug, the bounded queue, and the GazeSource on top. Waits are on conditions with
// a timeout (1 ms polls), never fixed sleeps.
#include "gaze/hid/enumerate.hpp"
#include "gaze/hid/hid_gaze_source.hpp"
#include "gaze/hid/hid_tracker.hpp"
#include "tests/hid/fake_hidapi.hpp"
#include "tests/hid/report_bytes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <mutex>
#include <thread>

namespace gazelod::gaze::hid {
namespace {

using testing::Bytes;
using testing::tracking_report;

bool wait_until(const std::function<bool()>& done, int timeout_ms = 3000) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// Thread-safe log capture.
struct Log {
  std::mutex m;
  std::vector<std::string> lines;
  std::function<void(const std::string&)> sink() {
    return [this](const std::string& l) {
      std::lock_guard lock(m);
      lines.push_back(l);
    };
  }
  int count(const std::string& needle) {
    std::lock_guard lock(m);
    return static_cast<int>(std::count_if(lines.begin(), lines.end(),
                                          [&](const std::string& l) { return l.find(needle) != std::string::npos; }));
  }
};

const std::string kPath = "/dev/hidraw-fake-et";

// A 527.04 x 296.46 mm screen in the Configuration report; both eyes 600 mm in front.
void plug_tracker(std::uint8_t status = 1) {
  fake_hid::plug({kPath});
  fake_hid::set_feature(
      kPath, Bytes{}.u8(kReportCapabilities).u8(1).u32(450000).u32(650000).u32(900000).u32(600000).u32(340000).b);
  fake_hid::set_feature(kPath, Bytes{}.u8(kReportConfiguration).u16(1).u16(2).u32(3).u16(4).i32(527040).i32(296460).b);
  fake_hid::set_feature(kPath, Bytes{}.u8(kReportStatus).u8(status).u16(250).b);
}

// Gaze at x (um from the left edge), vertical centre.
std::vector<std::uint8_t> gaze_at(std::uint64_t t_us, std::int32_t x_um) {
  return tracking_report(t_us, x_um, 148230, {-32000, 0, 600000}, {32000, 0, 600000});
}

HidTrackerConfig test_config(Log& log) {
  HidTrackerConfig c;
  c.read_timeout_ms = 2;
  c.reopen_interval_ms = 2;
  c.log = log.sink();
  return c;
}

class HidTrackerTest : public ::testing::Test {
 protected:
  void SetUp() override { fake_hid::reset(); }
  void TearDown() override { fake_hid::reset(); }
  Log log;
};

TEST_F(HidTrackerTest, FindsTheTrackerByUsagePageAndRequestsGazeMode) {
  fake_hid::plug({"/dev/hidraw-fake-kbd", 0x01, 0x06});     // a keyboard: not ours
  fake_hid::plug({"/dev/hidraw-fake-a-head", 0x12, 0x02});  // a head tracker, listed first: no gaze
  plug_tracker();
  const auto listed = list_trackers();
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0].path, "/dev/hidraw-fake-a-head");
  EXPECT_EQ(listed[1].path, kPath);
  EXPECT_EQ(listed[1].product, "Fake Eye Tracker");

  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  EXPECT_EQ(fake_hid::open_count("/dev/hidraw-fake-kbd"), 0);
  EXPECT_EQ(fake_hid::open_count("/dev/hidraw-fake-a-head"), 0);
  const auto sent = fake_hid::sent_features(kPath);
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0], (std::vector<std::uint8_t>{0x14, 0x07}));  // gaze | eye | head position
  const DeviceState st = t.device_state();
  ASSERT_TRUE(st.capabilities && st.configuration && st.status && st.screen);
  EXPECT_EQ(st.status->sampling_frequency_hz, 250);
  EXPECT_EQ(st.capabilities->optimum_tracking_distance_um, 650000u);
  // The calibrated size (Configuration) wins over the maximum plane (Capabilities).
  EXPECT_DOUBLE_EQ(st.screen->width_m, 0.52704);
  EXPECT_DOUBLE_EQ(st.screen->height_m, 0.29646);
  EXPECT_EQ(t.status(), "ok");
}

TEST_F(HidTrackerTest, RecordedReportsBecomeHeadSpaceSamples) {
  plug_tracker();
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  fake_hid::push_input(kPath, gaze_at(1000, 263520));  // screen centre
  fake_hid::push_input(kPath, gaze_at(5000, 527040));  // right edge
  ASSERT_TRUE(wait_until([&] { return t.counters().samples == 2; }));
  std::vector<GazeSample> got;
  ASSERT_TRUE(wait_until([&] { return t.drain(got) && got.size() == 2; }));
  ASSERT_TRUE(got[0].valid && got[1].valid);
  EXPECT_NEAR(got[0].direction.z, -1.0, 1e-12);
  // Right edge, 263.52 mm right of the centre at 600 mm: yaw = atan2(0.26352, 0.6) = 23.7111 deg.
  EXPECT_NEAR(std::atan2(got[1].direction.x, -got[1].direction.z) * 180.0 / 3.14159265358979, 23.7111, 1e-3);
  EXPECT_LE(got[0].t_ns, got[1].t_ns);
  EXPECT_EQ(t.counters().malformed + t.counters().unknown, 0u);
}

TEST_F(HidTrackerTest, ShortMalformedAndUnknownReportsAreCountedSkippedAndLogged) {
  plug_tracker();
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  auto good = gaze_at(1000, 263520);
  fake_hid::push_input(kPath, std::vector<std::uint8_t>(good.begin(), good.begin() + 20));  // short
  fake_hid::push_input(kPath, Bytes{}.u8(kReportStatus).u8(9).u16(250).b);                  // status 9: bad value
  fake_hid::push_input(kPath, Bytes{}.u8(0x42).pad(12).b);                                  // unknown report ID
  fake_hid::push_input(kPath, good);
  ASSERT_TRUE(wait_until([&] { return t.counters().reports == 4; }));
  const HidCounters c = t.counters();
  EXPECT_EQ(c.malformed, 2u);
  EXPECT_EQ(c.unknown, 1u);
  EXPECT_EQ(c.samples, 1u);
  EXPECT_EQ(log.count("tracking data report, byte 20"), 1);
  EXPECT_EQ(log.count("status report, byte 1"), 1);
  EXPECT_EQ(log.count("unknown ID 0x42"), 1);
  std::vector<GazeSample> got;
  ASSERT_TRUE(wait_until([&] { return t.drain(got) && !got.empty(); }));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_TRUE(got[0].valid);
}

TEST_F(HidTrackerTest, UnplugIsLoggedOnceAndTheDeviceIsReopenedWhenItReturns) {
  plug_tracker();
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  fake_hid::unplug(kPath);
  ASSERT_TRUE(wait_until([&] { return !t.connected(); }));
  EXPECT_EQ(t.status(), "unplugged");
  EXPECT_EQ(fake_hid::open_handles(), 0);  // closed
  // Let it look for the device several more times: still exactly one line for this absence.
  const int looked = fake_hid::enumerate_calls();
  ASSERT_TRUE(wait_until([&] { return fake_hid::enumerate_calls() >= looked + 5; }));
  EXPECT_EQ(log.count("lost " + kPath), 1);
  EXPECT_EQ(log.count("no eye tracker"), 0);
  EXPECT_EQ(t.counters().disconnects, 1u);

  plug_tracker();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  EXPECT_EQ(t.counters().opens, 2u);
  EXPECT_EQ(fake_hid::sent_features(kPath).size(), 2u);  // gaze mode requested again
  fake_hid::push_input(kPath, gaze_at(77, 263520));
  ASSERT_TRUE(wait_until([&] { return t.counters().samples == 1; }));
  EXPECT_EQ(log.count("opened " + kPath), 2);
}

TEST_F(HidTrackerTest, NoDeviceAtStartIsLoggedOnceThenFound) {
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return log.count("no eye tracker") == 1; }));
  EXPECT_EQ(t.status(), "no device");
  plug_tracker();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  EXPECT_EQ(log.count("no eye tracker"), 1);
}

TEST_F(HidTrackerTest, FullQueueDropsTheOldestSamples) {
  plug_tracker();
  HidTrackerConfig c = test_config(log);
  c.queue_capacity = 4;
  HidTracker t(c);
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  for (int i = 0; i < 10; ++i) fake_hid::push_input(kPath, gaze_at(1000 + 4000u * i, 50000 * i));
  ASSERT_TRUE(wait_until([&] { return t.counters().samples == 10; }));
  EXPECT_EQ(t.counters().dropped, 6u);
  std::vector<GazeSample> got;
  ASSERT_TRUE(wait_until([&] { return t.drain(got) && !got.empty(); }));
  ASSERT_EQ(got.size(), 4u);
  // The survivors are the newest four (gaze 300..450 mm from the left: moving right).
  for (std::size_t i = 1; i < got.size(); ++i) EXPECT_GT(got[i].direction.x, got[i - 1].direction.x);
  EXPECT_GT(got[0].direction.x, 0.0);  // 300 mm > the 263.5 mm centre
}

TEST_F(HidTrackerTest, NotReadyStatusMakesSamplesInvalidUntilReady) {
  plug_tracker(4);  // user calibration needed
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  fake_hid::push_input(kPath, gaze_at(1000, 263520));
  fake_hid::push_input(kPath, Bytes{}.u8(kReportStatus).u8(1).u16(250).b);  // now ready
  fake_hid::push_input(kPath, gaze_at(5000, 263520));
  ASSERT_TRUE(wait_until([&] { return t.counters().samples == 2; }));
  std::vector<GazeSample> got;
  ASSERT_TRUE(wait_until([&] { return t.drain(got) && got.size() == 2; }));
  EXPECT_FALSE(got[0].valid);
  EXPECT_TRUE(got[1].valid);
  EXPECT_EQ(log.count("tracker status: ready"), 1);
}

// The status says why gaze is missing: a tracker that needs calibration at open, and one that
// stays plugged in but stops streaming (its other reports do not count as gaze).
TEST_F(HidTrackerTest, StatusSaysNotReadyAndSilenceUntilGazeResumes) {
  plug_tracker(4);  // user calibration needed
  HidTrackerConfig c = test_config(log);
  c.silence_ms = 300;
  HidTracker t(c);
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  EXPECT_EQ(t.status(), "connected, tracker not ready (user calibration needed)");
  EXPECT_EQ(log.count("tracker not ready (user calibration needed), samples are invalid"), 1);
  fake_hid::push_input(kPath, Bytes{}.u8(kReportStatus).u8(1).u16(250).b);  // now ready
  ASSERT_TRUE(wait_until([&] { return log.count("tracker status: ready") == 1; }));
  ASSERT_TRUE(wait_until([&] { return t.status().find("no gaze reports for 300 ms") != std::string::npos; }));
  fake_hid::push_input(kPath, Bytes{}.u8(0x42).pad(12).b);  // an unknown report is no gaze
  ASSERT_TRUE(wait_until([&] { return t.counters().unknown == 1; }));
  EXPECT_NE(t.status().find("no gaze reports"), std::string::npos);
  fake_hid::push_input(kPath, gaze_at(1000, 263520));
  ASSERT_TRUE(wait_until([&] { return t.status() == "ok"; }));
  EXPECT_EQ(log.count("no gaze reports for 300 ms (device still open)"), 1);
  EXPECT_EQ(log.count("gaze reports resumed"), 1);
  EXPECT_TRUE(t.connected());
}

TEST_F(HidTrackerTest, WithoutAScreenSizeSamplesAreInvalidUnlessOneIsConfigured) {
  fake_hid::plug({kPath});
  fake_hid::fail_feature(kPath, kReportCapabilities);
  fake_hid::fail_feature(kPath, kReportConfiguration);
  fake_hid::fail_feature(kPath, kReportStatus);
  {
    HidTracker t(test_config(log));
    t.start();
    ASSERT_TRUE(wait_until([&] { return t.connected(); }));
    EXPECT_NE(t.status().find("no screen size"), std::string::npos);
    EXPECT_EQ(log.count("could not read the Configuration feature report"), 1);
    fake_hid::push_input(kPath, gaze_at(1000, 263520));
    ASSERT_TRUE(wait_until([&] { return t.counters().samples == 1; }));
    EXPECT_EQ(t.counters().invalid_samples, 1u);
  }
  HidTrackerConfig c = test_config(log);
  c.screen.width_m = 0.52704;
  c.screen.height_m = 0.29646;
  HidTracker t(c);
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  fake_hid::push_input(kPath, gaze_at(1000, 263520));
  ASSERT_TRUE(wait_until([&] { return t.counters().samples == 1; }));
  EXPECT_EQ(t.counters().invalid_samples, 0u);
}

TEST_F(HidTrackerTest, GazeSourceHoldsTheNewestSampleBrieflyAndFailsOnUnplug) {
  plug_tracker();
  HidTrackerConfig c = test_config(log);
  HidGazeSource source(c, 100'000'000);
  EXPECT_EQ(source.name(), "hid");
  ASSERT_TRUE(wait_until([&] { return source.tracker().connected(); }));
  fake_hid::push_input(kPath, gaze_at(1000, 263520));
  fake_hid::push_input(kPath, gaze_at(5000, 527040));
  ASSERT_TRUE(wait_until([&] { return source.tracker().counters().samples == 2; }));
  const std::int64_t now =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  std::optional<GazeSample> s;
  ASSERT_TRUE(wait_until([&] { return (s = source.sample_at(now)).has_value(); }));
  EXPECT_GT(s->direction.x, 0.1);                                     // the newest: right edge
  EXPECT_FALSE(source.sample_at(s->t_ns + 200'000'000).has_value());  // held 100 ms at most
  EXPECT_TRUE(source.sample_at(s->t_ns + 50'000'000).has_value());
  fake_hid::unplug(kPath);
  ASSERT_TRUE(wait_until([&] { return !source.tracker().connected(); }));
  EXPECT_FALSE(source.sample_at(now).has_value());
  EXPECT_EQ(source.status(), "hid: unplugged");
}

TEST_F(HidTrackerTest, DeviceTimestampsWrappingAt32BitsStayMonotonic) {
  plug_tracker();
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  const std::uint64_t wrap = std::uint64_t{1} << 32;
  for (int i = 0; i < 6; ++i)  // 32-bit counter: 8 ms before the wrap to 12 ms after
    fake_hid::push_input(kPath, gaze_at((wrap - 8000 + 4000u * i) % wrap, 263520));
  ASSERT_TRUE(wait_until([&] { return t.counters().samples == 6; }));
  std::vector<GazeSample> got;
  ASSERT_TRUE(wait_until([&] { return t.drain(got) && got.size() == 6; }));
  for (std::size_t i = 1; i < got.size(); ++i) EXPECT_GE(got[i].t_ns, got[i - 1].t_ns) << i;
  EXPECT_EQ(t.counters().clock_resets, 0u);  // the wrap is not mistaken for a device restart
}

TEST_F(HidTrackerTest, FeatureReportWithTheWrongIdIsLoggedAndNotUsed) {
  plug_tracker();
  // The device answers the Capabilities request with its Status report.
  fake_hid::set_feature(kPath, Bytes{}.u8(kReportStatus).u8(1).u16(250).b, kReportCapabilities);
  HidTracker t(test_config(log));
  t.start();
  ASSERT_TRUE(wait_until([&] { return t.connected(); }));
  EXPECT_FALSE(t.device_state().capabilities.has_value());
  EXPECT_TRUE(t.device_state().configuration.has_value());
  EXPECT_EQ(log.count("capabilities report, byte 0: report ID 0x13, expected 0x11"), 1);
}

}  // namespace
}  // namespace gazelod::gaze::hid
