// SPDX-License-Identifier: Apache-2.0
// The layer with its HID source, built against the fake hidapi (tests/hid/fake_hidapi.cpp,
// linked into this program and exported to the layer library, which is built with hid_* left
// for the loader's process to provide): gaze from a plugged tracker makes the eye-gaze action
// active and locatable; unplugging makes it inactive, replugging brings it back; a session
// that starts with no tracker logs one line and picks the tracker up once it is plugged in.
// The runtime is paced, so its clock (XR_KHR_convert_timespec_time) and the frames move with
// the tracker's real time.
#include "tests/hid/fake_hidapi.hpp"
#include "tests/hid/report_bytes.hpp"
#include "tests/layer/layer_test_util.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

namespace gazelod::layer_test {
namespace {

using gaze::hid::testing::Bytes;
namespace hid = gaze::hid;

const std::string kPath = "/dev/hidraw-fake-layer";

// A 527.04 x 296.46 mm screen in the Configuration report (as tests/hid/hid_tracker_test.cpp).
void plug_tracker() {
  fake_hid::plug({kPath});
  fake_hid::set_feature(
      kPath, Bytes{}.u8(hid::kReportCapabilities).u8(1).u32(450000).u32(650000).u32(900000).u32(600000).u32(340000).b);
  fake_hid::set_feature(kPath,
                        Bytes{}.u8(hid::kReportConfiguration).u16(1).u16(2).u32(3).u16(4).i32(527040).i32(296460).b);
  fake_hid::set_feature(kPath, Bytes{}.u8(hid::kReportStatus).u8(1).u16(250).b);
}

// Pushes tracking reports at ~250 Hz (gaze right of centre, eyes 600 mm away) while running.
class Feeder {
 public:
  void start() {
    stop_ = false;
    thread_ = std::thread([this] {
      while (!stop_) {
        const auto us =
            std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
                .count();
        fake_hid::push_input(kPath, hid::testing::tracking_report(static_cast<std::uint64_t>(us), 400000, 148230,
                                                                  {-32000, 0, 600000}, {32000, 0, 600000}));
        std::this_thread::sleep_for(std::chrono::milliseconds(4));
      }
    });
  }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  ~Feeder() { stop(); }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Frames until `want(active, located)` holds, at most ~4 s of paced frames.
bool frames_until(GazeRig& rig, const std::function<bool(bool, bool)>& want) {
  for (int f = 0; f < 360; ++f) {
    const XrTime t = rig.frame();
    if (rig.sync() != XR_SUCCESS) return false;
    const bool active = rig.active();
    const auto loc = rig.locate(rig.gaze_space, rig.view, t);
    const bool located = loc.flags != 0;
    if (located && direction_of(loc.pose).x <= 0.05) return false;  // the tracker looks right
    if (want(active, located)) return true;
  }
  return false;
}

class LayerHid : public ::testing::Test {
 protected:
  void SetUp() override {
    fake_hid::reset();
    LayerSetup setup;
    setup.paced = true;
    setup.duration_s = 60.0;
    apply(setup);  // no GAZELOD_LAYER_TRACE: the HID tracker
  }
  void TearDown() override { fake_hid::reset(); }
};

TEST_F(LayerHid, UnplugMakesTheActionInactiveAndReplugBringsItBack) {
  plug_tracker();
  Feeder feeder;
  feeder.start();
  GazeRig rig;
  std::string err = capture_stderr([&] { rig.create(); });
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(rig.supported, XR_TRUE);
  EXPECT_EQ(count_lines_with(err, "no HID eye tracker"), 0) << err;
  ASSERT_TRUE(frames_until(rig, [](bool active, bool located) { return active && located; }));
  EXPECT_EQ(rig.current_profile(), rig.profile);

  feeder.stop();
  fake_hid::unplug(kPath);
  ASSERT_TRUE(frames_until(rig, [](bool active, bool located) { return !active && !located; }));

  plug_tracker();
  feeder.start();
  ASSERT_TRUE(frames_until(rig, [](bool active, bool located) { return active && located; }));
  feeder.stop();
  rig.destroy();
}

TEST_F(LayerHid, NoTrackerAtStartIsOneLineAndAPluggedTrackerIsPickedUp) {
  GazeRig rig;
  const std::string err = capture_stderr([&] {
    rig.create();
    for (int f = 0; f < 20; ++f) {
      rig.frame();
      EXPECT_EQ(rig.sync(), XR_SUCCESS);
      EXPECT_FALSE(rig.active());
    }
  });
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(count_lines_with(err, "gazelod layer:"), 1) << err;
  EXPECT_EQ(count_lines_with(err, "gazelod layer: no HID eye tracker (usage page 0x12) found"), 1) << err;
  EXPECT_EQ(rig.supported, XR_TRUE);  // hot-plug: gaze comes when a tracker does

  plug_tracker();
  Feeder feeder;
  feeder.start();
  EXPECT_TRUE(frames_until(rig, [](bool active, bool located) { return active && located; }));
  feeder.stop();
  rig.destroy();
}

}  // namespace
}  // namespace gazelod::layer_test
