// SPDX-License-Identifier: Apache-2.0
// The gaze silence timer on the simulated runtime: a runtime that advertises eye gaze but never
// delivers it is distrusted gaze_silence_timeout_s after the session became FOCUSED (the state
// forwarded through on_session_state), not after the first frame. The simulated session is
// focused from its first frame, so the application here holds FOCUSED back for 1.5 s, as if
// an overlay had the focus until then.
#include "run_test_util.hpp"

#include "apps/xr_host/xr_app.hpp"
#include "plugin/lod_plugin.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace gazelod::test {
namespace {

TEST(PluginFocus, SilenceTimerRunsFromFocused) {
  const auto dir = scratch_dir();
  const auto file = dir / "never.json";
  std::ofstream(file) << R"({"version": 1, "display": "questpro", "duration_s": 4,
    "scene": {"generators": [{"type": "random_field", "count": 20}]},
    "runtime": {"gaze_delivery": "never_delivers"}})";
  use_simulated_runtime(file.string());

  xr_host::XrApp app(true);
  ASSERT_TRUE(app.eye_gaze_enabled());
  PluginConfig cfg;
  cfg.gaze_silence_timeout_s = 1.0;
  auto plugin =
      LodPlugin::create(xrGetInstanceProcAddr, app.instance(), app.system(), app.session(), app.local_space(), cfg);
  XrTime focused = 0, first_frame = 0, distrusted = 0, frame_t = 0;
  plugin->on_source_changed([&](GazeSourceKind, const std::string& why) {
    if (why.find("delivered no usable eye gaze") != std::string::npos && distrusted == 0) distrusted = frame_t;
  });
  int frames = 0;
  bool focus_pending = false;
  while (frames < 300 && app.poll_events([&](XrSessionState s, XrTime t) {
    if (s == XR_SESSION_STATE_FOCUSED)
      focus_pending = true;
    else
      plugin->on_session_state(s, t);
  })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    frame_t = fs.predictedDisplayTime;
    if (first_frame == 0) first_frame = frame_t;
    if (focus_pending && focused == 0 && frame_t - first_frame >= 1'500'000'000) {
      focused = frame_t;
      plugin->on_session_state(XR_SESSION_STATE_FOCUSED, frame_t);
    }
    plugin->begin_frame(fs.predictedDisplayTime);
    app.end_frame(fs.predictedDisplayTime, {});
    plugin->end_frame(1.0);
    ++frames;
  }
  ASSERT_NE(focused, 0) << "the session never became focused";
  ASSERT_NE(distrusted, 0) << "the silent runtime was never distrusted";
  // 1.5 s of frames before FOCUSED: a timer from the first frame would have fired at 1 s.
  const double after_focus_s = static_cast<double>(distrusted - focused) * 1e-9;
  EXPECT_GT(after_focus_s, 1.0);
  EXPECT_LT(after_focus_s, 1.0 + 3.0 / 90.0) << "within a few frames of the timeout";
}

}  // namespace
}  // namespace gazelod::test
