// SPDX-License-Identifier: Apache-2.0
// Faults of the external HID tracker (fake hidapi, tests/hid/fake_hidapi.hpp) seen through the
// gaze arbiter, as the plugin sees them: unplugged and replugged mid-run, a device clock that
// jumps back (tracker restart), a frozen tracker repeating one report.
#include "gaze/hid/hid_gaze_source.hpp"
#include "plugin/gaze_arbiter.hpp"
#include "tests/hid/fake_hidapi.hpp"
#include "tests/hid/report_bytes.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <mutex>
#include <thread>

namespace gazelod {
namespace {

using gaze::hid::testing::Bytes;
namespace hid = gaze::hid;

const std::string kPath = "/dev/hidraw-fault-et";

bool wait_until(const std::function<bool()>& done, int timeout_ms = 5000) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void plug_tracker() {
  fake_hid::plug({kPath});
  fake_hid::set_feature(kPath,
                        Bytes{}.u8(hid::kReportConfiguration).u16(1).u16(2).u32(3).u16(4).i32(527040).i32(296460).b);
  fake_hid::set_feature(kPath, Bytes{}.u8(hid::kReportStatus).u8(1).u16(250).b);
}

std::vector<std::uint8_t> gaze_at(std::uint64_t t_us) {  // screen centre, eyes 600 mm away
  return hid::testing::tracking_report(t_us, 263520, 148230, {-32000, 0, 600000}, {32000, 0, 600000});
}

hid::HidTrackerConfig config(std::vector<std::string>& log, std::mutex& m) {
  hid::HidTrackerConfig c;
  c.read_timeout_ms = 2;
  c.reopen_interval_ms = 2;
  c.log = [&log, &m](const std::string& l) {
    std::lock_guard lock(m);
    log.push_back(l);
  };
  return c;
}

class HidFaults : public ::testing::Test {
 protected:
  void SetUp() override { fake_hid::reset(); }
  void TearDown() override { fake_hid::reset(); }
  std::vector<std::string> log;
  std::mutex log_mutex;
};

TEST_F(HidFaults, UnpluggedAndReplugedMidRunFallsBackAndReturns) {
  plug_tracker();
  hid::HidGazeSource source(config(log, log_mutex));
  plugin::GazeArbiter arbiter(nullptr, &source);
  std::vector<std::pair<GazeSourceKind, std::string>> changes;
  arbiter.on_change([&](GazeSourceKind s, const std::string& why) { changes.emplace_back(s, why); });
  ASSERT_TRUE(wait_until([&] { return source.tracker().connected(); }));

  std::uint64_t t_us = 1000;
  auto frame_with_fresh_sample = [&] {
    const auto before = source.tracker().counters().samples;  // before the push: no race
    fake_hid::push_input(kPath, gaze_at(t_us += 4000));
    EXPECT_TRUE(wait_until([&] { return source.tracker().counters().samples > before; }));
    return arbiter.update(now_ns());
  };
  EXPECT_EQ(frame_with_fresh_sample().source, GazeSourceKind::external);

  fake_hid::unplug(kPath);
  ASSERT_TRUE(wait_until([&] { return !source.tracker().connected(); }));
  EXPECT_EQ(arbiter.update(now_ns()).source, GazeSourceKind::head_fixed);
  for (int i = 0; i < 20; ++i) arbiter.update(now_ns());  // frames go on while unplugged

  plug_tracker();
  ASSERT_TRUE(wait_until([&] { return source.tracker().connected(); }));
  EXPECT_EQ(frame_with_fresh_sample().source, GazeSourceKind::external);
  ASSERT_EQ(changes.size(), 3u);
  EXPECT_NE(changes[1].second.find("unplugged"), std::string::npos) << changes[1].second;
  EXPECT_EQ(source.tracker().counters().disconnects, 1u);
  EXPECT_EQ(source.tracker().counters().opens, 2u);
}

TEST_F(HidFaults, DeviceClockJumpingBackIsAResetAndHostTimesStayMonotonic) {
  plug_tracker();
  hid::HidTracker tracker(config(log, log_mutex));
  tracker.start();
  ASSERT_TRUE(wait_until([&] { return tracker.connected(); }));
  // 5 s of device time, then the tracker restarts its clock at 1 ms.
  const std::uint64_t device_us[] = {5'000'000, 5'004'000, 5'008'000, 1'000, 5'000, 9'000};
  for (std::uint64_t t : device_us) fake_hid::push_input(kPath, gaze_at(t));
  ASSERT_TRUE(wait_until([&] { return tracker.counters().samples == 6; }));
  std::vector<gaze::GazeSample> got;
  ASSERT_TRUE(wait_until([&] {
    tracker.drain(got);
    return got.size() == 6;
  }));
  EXPECT_EQ(tracker.counters().clock_resets, 1u);
  const std::int64_t host_now = now_ns();
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_LE(got[i].t_ns, host_now) << i;  // never in the future
    if (i > 0) {
      EXPECT_GE(got[i].t_ns, got[i - 1].t_ns) << i;
    }
  }
}

TEST_F(HidFaults, FrozenTrackerRepeatingOneReportGoesStaleAfterTheHoldTime) {
  plug_tracker();
  const std::int64_t hold_ns = 50'000'000;
  hid::HidGazeSource source(config(log, log_mutex), hold_ns);
  ASSERT_TRUE(wait_until([&] { return source.tracker().connected(); }));
  for (int i = 0; i < 10; ++i) fake_hid::push_input(kPath, gaze_at(777'000));  // same timestamp
  ASSERT_TRUE(wait_until([&] { return source.tracker().counters().samples == 10; }));
  std::optional<gaze::GazeSample> s;
  ASSERT_TRUE(wait_until([&] { return (s = source.sample_at(now_ns())).has_value(); }));
  EXPECT_TRUE(source.sample_at(s->t_ns + hold_ns / 2).has_value());
  // Still "connected" and still sending, but nothing new: no gaze past the hold time.
  for (int i = 0; i < 5; ++i) fake_hid::push_input(kPath, gaze_at(777'000));
  EXPECT_FALSE(source.sample_at(s->t_ns + 3 * hold_ns).has_value());
  EXPECT_TRUE(source.tracker().connected());
}

}  // namespace
}  // namespace gazelod
