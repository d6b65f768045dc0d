// SPDX-License-Identifier: Apache-2.0
// The C++ plugin (plugin/lod_plugin.hpp) over the fake OpenXR runtime (tests/plugin/fake_xr.hpp):
// begin_frame follows the runtime's eye gaze, refines at once and holds a coarsening (not inside
// a saccade); creation failures throw XrCallError with the runtime's result and release what was
// made; bad handles and arguments throw; shutdown releases everything and stops calling the
// runtime.
#include "plugin/lod_core.hpp"
#include "plugin/lod_plugin.hpp"
#include "plugin/xr_check.hpp"
#include "tests/plugin/fake_xr.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace gazelod::test {
namespace {

constexpr XrTime kFrameNs = 11'111'111;  // 90 Hz

// An object 2 m away at yaw_deg (left positive), 0.1 m in radius, with levels that remove
// detail of 0.5, 2 and 8 mm.
ObjectDesc object_at_yaw(double yaw_deg) {
  const double y = glm::radians(yaw_deg);
  ObjectDesc d;
  d.center_m = {-std::sin(y) * 2.0, 0.0, -std::cos(y) * 2.0};
  d.radius_m = 0.1;
  d.lods.resize(4);
  const double detail_m[4] = {0.0, 0.0005, 0.002, 0.008};
  for (int k = 0; k < 4; ++k) {
    d.lods[k].detail_kind = lod::DetailKind::geometric_error_m;
    d.lods[k].detail = detail_m[k];
    d.lods[k].triangles = 4000u >> (2 * k);
  }
  return d;
}

class LodPluginFakeXr : public ::testing::Test {
 protected:
  void SetUp() override { FakeXr::get().reset(); }
  void TearDown() override {
    plugin_.reset();
    EXPECT_EQ(log().live_spaces, 0);
    EXPECT_EQ(log().live_action_sets, 0);
    EXPECT_TRUE(log().misuse.empty()) << FakeXr::get().misuse_text();
  }

  static FakeXrLog& log() { return FakeXr::get().log; }
  static std::unique_ptr<LodPlugin> create(PluginConfig config = {}, OpenXrOptions options = {}) {
    const FakeXr& xr = FakeXr::get();
    return LodPlugin::create(xr.get_instance_proc_addr(), xr.instance(), xr.system(), xr.session(), xr.local_space(),
                             std::move(config), options);
  }
  const FrameDecisions& frames(int n) {
    const FrameDecisions* d = nullptr;
    for (int i = 0; i < n; ++i) d = &plugin_->begin_frame(t_ += kFrameNs);
    return *d;
  }
  std::vector<std::uint8_t> look(double yaw_deg, int n) {
    FakeXr::get().script.gaze = pose_looking_at(yaw_deg);
    const FrameDecisions& d = frames(n);
    return {d.lod.begin(), d.lod.end()};
  }

  std::unique_ptr<LodPlugin> plugin_;
  XrTime t_ = 1'000'000'000;
};

TEST_F(LodPluginFakeXr, FinerAtTheGazeThanThirtyDegreesAway) {
  plugin_ = create();  // the default configuration: our own eye-gaze action set
  ASSERT_EQ(plugin_->add_object(object_at_yaw(0)), 0u);
  ASSERT_EQ(plugin_->add_object(object_at_yaw(30)), 1u);
  EXPECT_EQ(plugin_->view_count(), 2u);
  EXPECT_EQ(plugin_->max_view_height_px(), 1800);
  std::vector<std::uint8_t> lod = look(30, 60);
  EXPECT_LT(lod[1], lod[0]) << "looking 30 deg left: the object there is finer";
  const FrameDecisions& d = plugin_->begin_frame(t_ += kFrameNs);
  EXPECT_EQ(d.gaze_source, GazeSourceKind::openxr);
  EXPECT_TRUE(d.gaze_valid);
  EXPECT_EQ(plugin_->active_source(), GazeSourceKind::openxr);
  const FrameDiagnostics& diag = plugin_->diagnostics();
  EXPECT_TRUE(diag.head_valid);
  EXPECT_NEAR(diag.gaze_direction_world.x, -0.5, 0.01);
  EXPECT_GT(diag.gaze_error_deg, 1.4) << "at least the source's accuracy (1.5 deg)";
  EXPECT_LT(diag.gaze_error_deg, 5.0);
  EXPECT_EQ(plugin_->core().view_count(), 2u);
  EXPECT_FLOAT_EQ(static_cast<float>(plugin_->core().views()[0].fov.angle_left_rad), -0.785398f);

  lod = look(0, 120);
  EXPECT_LT(lod[0], lod[1]) << "looking ahead: the object ahead is finer";
  EXPECT_EQ(log().count(XrFn::sync_actions), 181) << "our own set, synced once a frame";
  EXPECT_EQ(log().head_locate_times.end()[-2], t_) << "the head at the display time";
}

TEST_F(LodPluginFakeXr, RefinesAtOnceAndHoldsACoarsening) {
  plugin_ = create();
  plugin_->add_object(object_at_yaw(0));
  const std::uint8_t near = look(0, 60)[0];
  // The object moves from 2 m to 8 m ahead while the eye holds still: a coarser level is
  // allowed at once, but drawn only after the hold (200 ms) and the wait for a saccade or blink
  // (at most 600 ms more); never a level coarser than the perceptual one.
  plugin_->set_object_motion(0, {0.0, 0.0, -8.0}, glm::dvec3(0.0));
  int held_frames = 0;
  std::uint8_t drawn = near;
  for (int f = 0; f < 90 && drawn == near; ++f) {
    const FrameDecisions& d = frames(1);
    drawn = d.lod[0];
    ASSERT_LE(drawn, plugin_->diagnostics().lod_perceptual[0]) << "frame " << f;
    if (drawn == near) {
      ++held_frames;
      EXPECT_NE(d.held[0], 0) << "a finer level than the perceptual one is drawn only with a reason";
    }
  }
  EXPECT_GT(drawn, near) << "coarsened in the end";
  EXPECT_GE(held_frames, 18) << "after at least the 200 ms hold (18 frames at 90 Hz)";
  EXPECT_LE(held_frames, 74) << "and at most the hold plus the 600 ms deferral (72 frames, and rounding)";
  // Back at 2 m: refined in the very next frame.
  plugin_->set_object_motion(0, {0.0, 0.0, -2.0}, glm::dvec3(0.0));
  EXPECT_EQ(frames(1).lod[0], near);

  // A coarsening inside a saccade is not held: vision is suppressed, nobody sees the switch.
  plugin_->add_object(object_at_yaw(30));
  const std::vector<std::uint8_t> at_30 = look(30, 120);
  FakeXr::get().script.gaze = pose_looking_at(0);
  int frames_to_coarsen = 0;
  while (frames(1).lod[1] == at_30[1] && frames_to_coarsen < 90) ++frames_to_coarsen;
  EXPECT_LE(frames_to_coarsen, 2) << "a 30 deg gaze jump is a saccade";
  EXPECT_TRUE(plugin_->diagnostics().gaze_suppressed);
}

// The release by regret (SwitchPolicyConfig::release_regret_s) on the plugin's own path: two
// objects move from 2 m to 8 m ahead while the eye holds still, no saccade to wait for. The one
// whose coarsening saves 100 times the triangles is drawn coarser right after the hold; the
// small one waits for the deadline (hold + deferral). With the rule off, both wait.
TEST_F(LodPluginFakeXr, ABigSavingIsNotHeldForASaccade) {
  for (const double regret_s : {lod::SwitchPolicyConfig{}.release_regret_s, 0.0}) {
    PluginConfig config;
    config.switching.release_regret_s = regret_s;
    plugin_ = create(config);
    ObjectDesc big = object_at_yaw(0), small = object_at_yaw(-3);
    for (lod::LodLevel& level : big.lods) level.triangles *= 100;
    plugin_->add_object(big);
    plugin_->add_object(small);
    // More small objects, so that the mean object (the rule's unit, 0.15 s of its full detail)
    // is small beside the big one's saving.
    for (int k = 0; k < 8; ++k) plugin_->add_object(object_at_yaw(20.0 + 3.0 * k));
    const std::vector<std::uint8_t> near = look(0, 60);
    plugin_->set_object_motion(0, {0.0, 0.0, -8.0}, glm::dvec3(0.0));
    plugin_->set_object_motion(1, {-std::sin(glm::radians(-3.0)) * 8.0, 0.0, -std::cos(glm::radians(-3.0)) * 8.0},
                               glm::dvec3(0.0));
    std::vector<int> frames_held(2, -1);
    for (int f = 0; f < 90; ++f) {
      const FrameDecisions& d = frames(1);
      for (std::size_t i = 0; i < 2; ++i)
        if (frames_held[i] < 0 && d.lod[i] > near[i]) frames_held[i] = f;
    }
    ASSERT_GE(frames_held[0], 0) << "regret " << regret_s;
    ASSERT_GE(frames_held[1], 0) << "regret " << regret_s;
    EXPECT_GE(frames_held[0], 18) << "never before the hold (200 ms, 18 frames)";
    if (regret_s > 0.0)
      EXPECT_LE(frames_held[0], 20) << "the big saving: at the end of the hold";
    else
      EXPECT_GE(frames_held[0], 70) << "without the rule: the deadline (72 frames)";
    EXPECT_GE(frames_held[1], 70) << "the small saving waits for the deadline, regret " << regret_s;
    EXPECT_FALSE(plugin_->diagnostics().gaze_suppressed);
    plugin_.reset();
    FakeXr::get().reset();
  }
}

TEST_F(LodPluginFakeXr, CreationFailureThrowsTheResultAndReleasesWhatWasMade) {
  // plugin_actions creates two spaces and an action set before the views are enumerated.
  for (XrFn call : {XrFn::create_action_set, XrFn::attach_session_action_sets, XrFn::create_action_space,
                    XrFn::enumerate_view_configuration_views}) {
    SCOPED_TRACE(xr_fn_name(call));
    FakeXr::get().reset();
    FakeXr::get().script.fail_call(call, XR_ERROR_RUNTIME_FAILURE);
    try {
      plugin_ = create();
      ADD_FAILURE() << "created";
    } catch (const XrCallError& e) {
      EXPECT_EQ(e.result, XR_ERROR_RUNTIME_FAILURE);
      EXPECT_NE(std::string(e.what()).find(xr_fn_name(call)), std::string::npos) << e.what();
    }
    EXPECT_EQ(log().live_spaces, 0);
    EXPECT_EQ(log().live_action_sets, 0);
  }
  // xrGetSystemProperties failing is not fatal: eye gaze is then taken as absent.
  FakeXr::get().reset();
  FakeXr::get().script.fail_call(XrFn::get_system_properties, XR_ERROR_RUNTIME_FAILURE);
  plugin_ = create();
  EXPECT_EQ(plugin_->action_set(), XR_NULL_HANDLE);
  EXPECT_EQ(frames(2).gaze_source, GazeSourceKind::head_fixed);
}

TEST_F(LodPluginFakeXr, BadHandlesAndMissingFunctions) {
  const FakeXr& xr = FakeXr::get();
  EXPECT_THROW(
      LodPlugin::create(xr.get_instance_proc_addr(), XR_NULL_HANDLE, xr.system(), xr.session(), xr.local_space(), {}),
      std::invalid_argument);
  EXPECT_THROW(
      LodPlugin::create(xr.get_instance_proc_addr(), xr.instance(), xr.system(), xr.session(), XR_NULL_HANDLE, {}),
      std::invalid_argument);
  try {
    LodPlugin::create(nullptr, xr.instance(), xr.system(), xr.session(), xr.local_space(), {});
    ADD_FAILURE() << "created without xrGetInstanceProcAddr";
  } catch (const XrCallError& e) {
    EXPECT_EQ(e.result, XR_ERROR_VALIDATION_FAILURE);
  }
  FakeXr::get().script.withhold(XrFn::locate_space);
  try {
    create();
    ADD_FAILURE() << "created without xrLocateSpace";
  } catch (const XrCallError& e) {
    EXPECT_EQ(e.result, XR_ERROR_FUNCTION_UNSUPPORTED);
    EXPECT_NE(std::string(e.what()).find("xrLocateSpace"), std::string::npos) << e.what();
  }
  EXPECT_EQ(log().live_spaces, 0);

  FakeXr::get().reset();
  OpenXrOptions none;
  none.gaze_input = OpenXrGazeInput::none;
  plugin_ = create({}, none);
  EXPECT_THROW(plugin_->set_base_space(XR_NULL_HANDLE), std::invalid_argument);
  EXPECT_THROW(plugin_->set_view_resolution(2, 100, 100), std::out_of_range);
  EXPECT_THROW(plugin_->set_view_resolution(0, 0, 100), std::invalid_argument);
  EXPECT_THROW(plugin_->set_gaze_space(xr.app_gaze_space(), XR_NULL_HANDLE), std::invalid_argument);
  std::string why;
  EXPECT_EQ(plugin_->push_gaze({}, why), plugin::PushResult::invalid);
  EXPECT_NE(why.find("GZL_GAZE_INPUT_PUSHED"), std::string::npos) << why;
  // No objects: a frame is still decided, with empty spans.
  const FrameDecisions& d = frames(2);
  EXPECT_TRUE(d.lod.empty());
  EXPECT_EQ(d.gaze_source, GazeSourceKind::head_fixed);
  EXPECT_EQ(log().count(XrFn::get_action_state_pose), 0) << "no gaze asked for: no action read";
}

TEST_F(LodPluginFakeXr, ShutdownReleasesEverythingAndStopsCallingTheRuntime) {
  OpenXrOptions app;
  app.gaze_input = OpenXrGazeInput::app_space;  // the application's space, given after creation
  plugin_ = create({}, app);
  plugin_->add_object(object_at_yaw(30));
  FakeXr::get().script.gaze = pose_looking_at(30);
  EXPECT_EQ(frames(3).gaze_source, GazeSourceKind::head_fixed) << "no gaze space yet";
  EXPECT_EQ(log().count(XrFn::locate_space), 3) << "the head only";
  plugin_->set_gaze_space(FakeXr::get().app_gaze_space(), FakeXr::get().app_gaze_action());
  const std::uint8_t level = frames(60).lod[0];
  EXPECT_EQ(plugin_->begin_frame(t_ += kFrameNs).gaze_source, GazeSourceKind::openxr);
  EXPECT_EQ(log().live_spaces, 2) << "two VIEW spaces: the head's and the gaze's";

  plugin_->shutdown();
  EXPECT_TRUE(plugin_->is_shut_down());
  EXPECT_EQ(log().live_spaces, 0);
  const FakeXrLog before = log();
  const FrameDecisions& d = frames(5);
  EXPECT_EQ(d.lod[0], level) << "later frames keep the last decisions";
  EXPECT_EQ(log().calls, before.calls) << "no OpenXR call after shutdown";
  plugin_->shutdown();  // safe twice
  EXPECT_TRUE(log().misuse.empty()) << FakeXr::get().misuse_text();
}

}  // namespace
}  // namespace gazelod::test
