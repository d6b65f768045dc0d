// SPDX-License-Identifier: Apache-2.0
// The C ABI in OpenXR mode as an engine drives it, over the fake runtime (tests/plugin/fake_xr.hpp):
// the fovea follows the runtime's eye gaze; lost gaze, a runtime that never delivers and a
// missing eye-gaze extension fall back to head-fixed gaze and say why; the merge-binding flow;
// a static scene under a noisy tracker does not flicker.
#include "tests/plugin/capi_fake_xr_util.hpp"

#include <gtest/gtest.h>
#include <openxr/openxr.h>

#include <cmath>

namespace gazelod::test {
namespace {

class CApiFakeXr : public ::testing::Test {
 protected:
  void SetUp() override { FakeXr::get().reset(); }
  void TearDown() override {
    gzl_destroy(p_);
    // Destroyed: every space and action set the plugin made is gone, and nothing it was lent
    // was destroyed or misused.
    const FakeXrLog& log = FakeXr::get().log;
    EXPECT_EQ(log.live_spaces, 0);
    EXPECT_EQ(log.live_action_sets, 0);
    EXPECT_TRUE(log.misuse.empty()) << FakeXr::get().misuse_text();
  }

  // Objects 2 m away, 0.1 m in radius, at these yaws (deg, left positive).
  void add_objects(std::initializer_list<double> yaws) {
    for (double yaw : yaws) {
      gzl_object o = 0;
      gzl_object_desc d = object_at(yaw, 0, 2.0);
      ASSERT_EQ(gzl_add_object(p_, &d, &o), GZL_SUCCESS) << last_error(p_);
      objects_.push_back(o);
    }
  }
  // An engine's start: the plugin, objects ahead and 30 deg left, the session focused.
  void start(gzl_gaze_input input) {
    p_ = create_on_fake(input);
    ASSERT_NE(p_, nullptr);
    add_objects({0.0, 30.0});
    ASSERT_EQ(gzl_on_session_state(p_, XR_SESSION_STATE_FOCUSED, t_), GZL_SUCCESS);
  }
  void look(double yaw_deg, int frames) {
    FakeXr::get().script.gaze = pose_looking_at(yaw_deg);
    t_ = run_xr_frames(p_, t_, frames);
  }
  std::vector<uint8_t> levels() { return levels_of(p_, objects_); }

  gzl_plugin p_ = nullptr;
  std::vector<gzl_object> objects_;
  int64_t t_ = kXrStartNs;
};

TEST_F(CApiFakeXr, FinerAtTheGazeThanThirtyDegreesAway) {
  ASSERT_NO_FATAL_FAILURE(start(GZL_GAZE_INPUT_APP_SPACE));
  look(30, 60);
  std::vector<uint8_t> l = levels();
  EXPECT_LT(l[1], l[0]) << "looking 30 deg left: the object there is finer than the one ahead";
  gzl_frame_info info = frame_info_of(p_);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_OPENXR);
  EXPECT_EQ(info.eye_motion, GZL_EYE_FIXATION);
  EXPECT_EQ(info.head_valid, 1u);
  EXPECT_EQ(info.frame_index, 60u);
  EXPECT_EQ(info.object_count, 2u);
  EXPECT_NEAR(info.gaze_direction_base.x, -std::sin(M_PI / 6), 0.01);
  EXPECT_NEAR(info.gaze_direction_base.z, -std::cos(M_PI / 6), 0.01);
  EXPECT_LT(info.triangles_drawn, info.triangles_full);
  EXPECT_EQ(gaze_status_of(p_), "openxr eye gaze delivered");
  gzl_frame_record record{};
  record.type = GZL_TYPE_FRAME_RECORD;
  ASSERT_EQ(gzl_get_frame_record(p_, &record), GZL_SUCCESS);
  EXPECT_EQ(record.has_gaze_sample, 1u);
  EXPECT_EQ(record.gaze_sample.time_ns, t_ - FakeXr::get().script.gaze_latency_ns) << "the runtime's sample time";
  EXPECT_EQ(record.view_count, 2u);

  look(0, 120);
  l = levels();
  EXPECT_LT(l[0], l[1]) << "looking ahead: the object ahead is finer";
  // The application owns the actions: the plugin only located its space.
  const FakeXrLog& log = FakeXr::get().log;
  EXPECT_EQ(log.count(XrFn::suggest_interaction_profile_bindings), 0);
  EXPECT_EQ(log.count(XrFn::attach_session_action_sets), 0);
  EXPECT_EQ(log.count(XrFn::sync_actions), 0);
  EXPECT_EQ(log.count(XrFn::get_action_state_pose), 180) << "isActive of the application's action, once a frame";
  // The head is located at the predicted display time, then at the gaze sample's time (the eye
  // in the world is the head then).
  ASSERT_GE(log.head_locate_times.size(), 2u);
  EXPECT_EQ(log.head_locate_times.end()[-2], t_);
  EXPECT_EQ(log.head_locate_times.end()[-1], t_ - FakeXr::get().script.gaze_latency_ns);
}

TEST_F(CApiFakeXr, LostGazeFallsBackToHeadFixedAndSaysSo) {
  ASSERT_NO_FATAL_FAILURE(start(GZL_GAZE_INPUT_APP_SPACE));
  look(0, 120);
  const std::vector<uint8_t> at_0 = levels();
  look(30, 120);
  const std::vector<uint8_t> at_30 = levels();
  ASSERT_LT(at_0[0], at_30[0]);
  // Tracking lost: the runtime marks the gaze pose invalid. A blink's length is bridged (the
  // estimate held, vision counted as suppressed) ...
  FakeXr::get().script.gaze_flags = 0;
  t_ = run_xr_frames(p_, t_, 3);
  gzl_frame_info info = frame_info_of(p_);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_OPENXR);
  EXPECT_EQ(info.gaze_suppressed, 1u);
  // ... then the head-fixed fallback: straight ahead with the widened cone (20 deg).
  t_ = run_xr_frames(p_, t_, 40);
  info = frame_info_of(p_);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  EXPECT_EQ(info.eye_motion, GZL_EYE_LOSS);
  EXPECT_EQ(info.head_valid, 1u);
  EXPECT_DOUBLE_EQ(info.gaze_uncertainty_deg, 20.0);
  EXPECT_NEAR(info.gaze_direction_base.z, -1.0, 1e-9);
  const std::string why = gaze_status_of(p_);
  EXPECT_TRUE(contains(why, "gaze not tracked (blink or lost)")) << why;
  EXPECT_TRUE(contains(why, "head-fixed gaze with a widened cone")) << why;
  const std::vector<uint8_t> lost = levels();
  EXPECT_EQ(lost[0], at_0[0]) << "the object ahead is inside the widened cone: foveal detail";

  // Tracking back: the runtime's gaze is used again at once.
  FakeXr::get().script.gaze_flags = kPoseTracked;
  t_ = run_xr_frames(p_, t_, 2);
  info = frame_info_of(p_);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_OPENXR);
  EXPECT_EQ(gaze_status_of(p_), "openxr eye gaze delivered");
}

TEST_F(CApiFakeXr, RuntimeThatNeverDeliversGazeIsDistrustedForTheSession) {
  FakeXr::get().script.gaze_flags = 0;
  ASSERT_NO_FATAL_FAILURE(start(GZL_GAZE_INPUT_PLUGIN_ACTIONS));
  t_ = run_xr_frames(p_, t_, 10);
  EXPECT_EQ(frame_info_of(p_).gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  EXPECT_TRUE(contains(gaze_status_of(p_), "runtime has not delivered gaze")) << gaze_status_of(p_);
  t_ = run_xr_frames(p_, t_, 90);  // past the 1 s silence timeout
  const std::string why = gaze_status_of(p_);
  EXPECT_TRUE(contains(why, "openxr delivered no usable eye gaze in 1.000 s (runtime has not delivered gaze)")) << why;
  // Distrusted for the rest of the session: a late gaze pose does not bring it back.
  FakeXr::get().script.gaze_flags = kPoseTracked;
  t_ = run_xr_frames(p_, t_, 10);
  EXPECT_EQ(frame_info_of(p_).gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  // The plugin's own set: suggested for the eye-gaze profile, attached once, synced every frame.
  const FakeXrLog& log = FakeXr::get().log;
  ASSERT_EQ(log.suggested_bindings.size(), 1u);
  EXPECT_EQ(log.suggested_bindings[0],
            "/interaction_profiles/ext/eye_gaze_interaction /user/eyes_ext/input/gaze_ext/pose");
  EXPECT_EQ(log.count(XrFn::attach_session_action_sets), 1);
  EXPECT_EQ(log.count(XrFn::sync_actions), 91) << "synced each frame until distrusted (past 1 s), then left alone";
}

TEST_F(CApiFakeXr, EyeGazeExtensionNotEnabledFallsBackAtCreation) {
  for (gzl_gaze_input input : {GZL_GAZE_INPUT_PLUGIN_ACTIONS, GZL_GAZE_INPUT_MERGE_BINDING}) {
    SCOPED_TRACE(input);
    FakeXr::get().reset();
    FakeXr::get().script.system_eye_gaze = false;
    gzl_plugin p = create_on_fake(input);
    ASSERT_NE(p, nullptr);
    // Nothing created for a gaze the system does not have, and no binding to merge.
    EXPECT_EQ(FakeXr::get().log.live_action_sets, 0);
    EXPECT_EQ(FakeXr::get().log.count(XrFn::suggest_interaction_profile_bindings), 0);
    gzl_gaze_binding binding{};
    binding.type = GZL_TYPE_GAZE_BINDING;
    EXPECT_EQ(gzl_get_gaze_binding(p, &binding), GZL_ERROR_WRONG_MODE);
    run_xr_frames(p, kXrStartNs, 3);
    EXPECT_EQ(frame_info_of(p).gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
    const std::string why = gaze_status_of(p);
    EXPECT_TRUE(contains(why, "enable XR_EXT_eye_gaze_interaction")) << why;
    gzl_destroy(p);
    EXPECT_EQ(FakeXr::get().log.live_spaces, 0);
  }
}

TEST_F(CApiFakeXr, MergedBindingIsUsedOnceTheApplicationAttached) {
  ASSERT_NO_FATAL_FAILURE(start(GZL_GAZE_INPUT_MERGE_BINDING));
  gzl_gaze_binding binding{};
  binding.type = GZL_TYPE_GAZE_BINDING;
  ASSERT_EQ(gzl_get_gaze_binding(p_, &binding), GZL_SUCCESS) << last_error(p_);
  EXPECT_NE(binding.action_set, 0u);
  EXPECT_NE(binding.action, 0u);
  EXPECT_STREQ(binding.interaction_profile, "/interaction_profiles/ext/eye_gaze_interaction");
  EXPECT_STREQ(binding.binding_path, "/user/eyes_ext/input/gaze_ext/pose");
  look(30, 5);  // not attached yet: no gaze space to locate
  EXPECT_EQ(frame_info_of(p_).gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  EXPECT_EQ(FakeXr::get().log.count(XrFn::create_action_space), 0);
  ASSERT_EQ(gzl_action_sets_attached(p_), GZL_SUCCESS) << last_error(p_);
  look(30, 120);  // the object ahead coarsens after the switch policy's hold
  EXPECT_EQ(frame_info_of(p_).gaze_source, GZL_GAZE_SOURCE_OPENXR);
  const std::vector<uint8_t> l = levels();
  EXPECT_LT(l[1], l[0]);
  // The application suggests, attaches and syncs; the plugin made only its set, action and space.
  const FakeXrLog& log = FakeXr::get().log;
  EXPECT_EQ(log.count(XrFn::suggest_interaction_profile_bindings), 0);
  EXPECT_EQ(log.count(XrFn::attach_session_action_sets), 0);
  EXPECT_EQ(log.count(XrFn::sync_actions), 0);
  EXPECT_EQ(log.count(XrFn::create_action_space), 1);
  EXPECT_EQ(log.live_action_sets, 1);
}

// A static scene under a noisy tracker: the levels settle and then hold; drawing each frame's
// perceptual choice instead (the switch policy off) flips levels with the noise, which shows
// the noise is enough to matter.
int level_changes_under_noise(const gzl_config* config) {
  FakeXr::get().reset();
  gzl_plugin p = create_on_fake(GZL_GAZE_INPUT_APP_SPACE, config);
  if (p == nullptr) return -1;
  std::vector<gzl_object> objects;
  for (int yaw = -40; yaw <= 40; yaw += 4)
    for (int pitch = -20; pitch <= 20; pitch += 10) {
      gzl_object o = 0;
      gzl_object_desc d = object_at(yaw, pitch, 1.5 + 0.05 * (yaw + 40));
      EXPECT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS);
      objects.push_back(o);
    }
  EXPECT_EQ(gzl_on_session_state(p, XR_SESSION_STATE_FOCUSED, kXrStartNs), GZL_SUCCESS);
  int64_t t = kXrStartNs;
  std::vector<uint8_t> before;
  int changes = 0;
  for (int f = 0; f < 360; ++f) {
    // A noisy tracker: deterministic jitter of up to +-4 deg from frame to frame around (5, 2)
    // deg, which the conditioner's fixation filter does not fully absorb.
    const double jitter = 4.0 * std::sin(f * 2.3) * std::cos(f * 0.7);
    FakeXr::get().script.gaze = pose_looking_at(5.0 + jitter, 2.0 - jitter);
    t = run_xr_frames(p, t, 1);
    const std::vector<uint8_t> now = levels_of(p, objects);
    if (f >= 60)  // after the warm-up
      for (std::size_t i = 0; i < now.size(); ++i) changes += now[i] != before[i];
    before = now;
  }
  EXPECT_EQ(frame_info_of(p).gaze_source, GZL_GAZE_SOURCE_OPENXR);
  gzl_destroy(p);
  return changes;
}

TEST_F(CApiFakeXr, StaticSceneDoesNotFlicker) {
  EXPECT_EQ(level_changes_under_noise(nullptr), 0) << "level changes in 300 frames of a static scene";
  gzl_config no_policy{};
  no_policy.type = GZL_TYPE_CONFIG;
  no_policy.disable_switch_policy = 1;
  EXPECT_GT(level_changes_under_noise(&no_policy), 0) << "the noise is enough to flip perceptual levels";
}

}  // namespace
}  // namespace gazelod::test
