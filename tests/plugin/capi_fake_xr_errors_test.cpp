// SPDX-License-Identifier: Apache-2.0
// The C ABI in OpenXR mode when things go wrong, over the fake runtime (tests/plugin/fake_xr.hpp):
// a failing OpenXR call at creation is GZL_ERROR_OPENXR_CALL naming the call and its XrResult,
// with nothing left behind; a function the loader does not give is GZL_ERROR_OPENXR_FUNCTION;
// failures and non-finite poses inside a frame are reported in its output, never crashed on;
// bad arguments get the documented result codes; zero objects is a valid scene.
#include "tests/plugin/capi_fake_xr_util.hpp"

#include <gtest/gtest.h>
#include <openxr/openxr.h>

#include <limits>

namespace gazelod::test {
namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();

// The result code, and a "gazelod:" message (the plugin's, or the thread's for a create) that
// mentions `part`.
::testing::AssertionResult refused(gzl_plugin p, gzl_result got, gzl_result want, const char* part) {
  const std::string m = last_error(p);
  if (got != want)
    return ::testing::AssertionFailure() << gzl_result_to_string(got) << " instead of " << gzl_result_to_string(want)
                                         << " (" << m << ")";
  if (m.rfind("gazelod:", 0) != 0 || !contains(m, part))
    return ::testing::AssertionFailure() << "message \"" << m << "\" lacks \"" << part << "\"";
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult nothing_left_behind() {
  const FakeXrLog& log = FakeXr::get().log;
  if (log.live_spaces != 0 || log.live_action_sets != 0 || !log.misuse.empty())
    return ::testing::AssertionFailure() << log.live_spaces << " spaces and " << log.live_action_sets
                                         << " action sets left; misuse:\n"
                                         << FakeXr::get().misuse_text();
  return ::testing::AssertionSuccess();
}

// A plugin on a fresh fake runtime, with one object 2 m away at yaw_deg.
gzl_plugin plugin_with_object(gzl_gaze_input input, double yaw_deg, gzl_object& o) {
  FakeXr::get().reset();
  gzl_plugin p = create_on_fake(input);
  gzl_object_desc d = object_at(yaw_deg, 0, 2.0);
  if (p != nullptr) {
    EXPECT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS) << last_error(p);
  }
  return p;
}

gzl_result create(const gzl_openxr_create_info& info, gzl_plugin& p) {
  p = reinterpret_cast<gzl_plugin>(0x1);  // must be cleared on failure
  return gzl_create_openxr(&info, &p);
}

TEST(CApiFakeXrErrors, FailedCallAtCreationNamesTheCallAndItsResult) {
  // Each call creation makes, in PLUGIN_ACTIONS (the mode that makes the most).
  const XrFn calls[] = {XrFn::create_reference_space,
                        XrFn::enumerate_view_configuration_views,
                        XrFn::create_action_set,
                        XrFn::create_action,
                        XrFn::string_to_path,
                        XrFn::suggest_interaction_profile_bindings,
                        XrFn::attach_session_action_sets,
                        XrFn::create_action_space};
  for (XrFn call : calls) {
    SCOPED_TRACE(xr_fn_name(call));
    FakeXr::get().reset();
    FakeXr::get().script.fail_call(call, XR_ERROR_SESSION_LOST);
    gzl_plugin p = nullptr;
    EXPECT_TRUE(refused(nullptr, create(fake_openxr_info(GZL_GAZE_INPUT_PLUGIN_ACTIONS), p), GZL_ERROR_OPENXR_CALL,
                        "XR_ERROR_SESSION_LOST"));
    EXPECT_TRUE(contains(last_error(nullptr), xr_fn_name(call))) << last_error(nullptr);
    EXPECT_EQ(p, nullptr);
    EXPECT_EQ(FakeXr::get().log.count(call), 1);
    EXPECT_TRUE(nothing_left_behind());
  }
  // The session's action sets are attached already: the message gives the two modes that work.
  FakeXr::get().reset();
  FakeXr::get().script.app_attached_action_sets = true;
  gzl_plugin p = nullptr;
  EXPECT_TRUE(refused(nullptr, create(fake_openxr_info(GZL_GAZE_INPUT_PLUGIN_ACTIONS), p), GZL_ERROR_OPENXR_CALL,
                      "GZL_GAZE_INPUT_APP_SPACE"));
  EXPECT_TRUE(nothing_left_behind());
  // A system without the view configuration asked for.
  FakeXr::get().reset();
  gzl_openxr_create_info info = fake_openxr_info(GZL_GAZE_INPUT_NONE);
  info.view_configuration_type = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_QUAD_VARJO;
  EXPECT_TRUE(refused(nullptr, create(info, p), GZL_ERROR_OPENXR_CALL, "does not support view configuration"));
  EXPECT_TRUE(nothing_left_behind());
}

TEST(CApiFakeXrErrors, FunctionTheLoaderDoesNotGive) {
  for (XrResult answer : {XR_ERROR_FUNCTION_UNSUPPORTED, XR_SUCCESS}) {  // XR_SUCCESS: a hook with no pointer
    FakeXr::get().reset();
    FakeXr::get().script.withhold(XrFn::locate_views);
    FakeXr::get().script.missing_result = answer;
    gzl_plugin p = nullptr;
    EXPECT_TRUE(refused(nullptr, create(fake_openxr_info(GZL_GAZE_INPUT_NONE), p), GZL_ERROR_OPENXR_FUNCTION,
                        "xrGetInstanceProcAddr(\"xrLocateViews\") gave no function"));
    EXPECT_TRUE(contains(last_error(nullptr), "XR_ERROR_FUNCTION_UNSUPPORTED") || answer == XR_SUCCESS);
    EXPECT_EQ(p, nullptr);
    EXPECT_TRUE(nothing_left_behind());
  }
}

TEST(CApiFakeXrErrors, FailuresInAFrameAreReportedNotCrashedOn) {
  gzl_object o = 0;
  gzl_plugin p = plugin_with_object(GZL_GAZE_INPUT_PLUGIN_ACTIONS, 30, o);
  ASSERT_NE(p, nullptr);
  FakeXr::get().script.gaze = pose_looking_at(30);
  int64_t t = run_xr_frames(p, kXrStartNs, 30);
  const gzl_frame_info good = frame_info_of(p);
  ASSERT_EQ(good.gaze_source, GZL_GAZE_SOURCE_OPENXR);
  uint8_t level_good = 0xEE;
  ASSERT_EQ(gzl_get_levels(p, 1, &o, &level_good), GZL_SUCCESS);

  // The session is lost: every locate fails. The frame is still decided (from the last head
  // pose, with head-fixed gaze), and its output says the head was not located and why the gaze
  // fell back.
  FakeXrScript& script = FakeXr::get().script;
  script.fail_call(XrFn::locate_space, XR_ERROR_SESSION_LOST);
  script.fail_call(XrFn::locate_views, XR_ERROR_SESSION_LOST);
  script.fov = {-0.5f, 0.5f, 0.5f, -0.5f};  // narrower views, not seen while xrLocateViews fails
  t = run_xr_frames(p, t, 3);
  gzl_frame_info info = frame_info_of(p);
  EXPECT_EQ(info.frame_index, 33u);
  EXPECT_EQ(info.head_valid, 0u);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  EXPECT_DOUBLE_EQ(info.xi_cpd, good.xi_cpd) << "the last located views are kept";
  EXPECT_TRUE(contains(gaze_status_of(p), "xrLocateSpace(gaze) failed")) << gaze_status_of(p);
  uint8_t level = 0xEE;
  ASSERT_EQ(gzl_get_levels(p, 1, &o, &level), GZL_SUCCESS);
  EXPECT_EQ(level, level_good) << "a coarsening waits out the switch policy's hold (200 ms)";
  // Back: head and gaze again.
  script.fail = {};
  t = run_xr_frames(p, t, 2);
  info = frame_info_of(p);
  EXPECT_EQ(info.head_valid, 1u);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_OPENXR);
  EXPECT_GT(info.xi_cpd, good.xi_cpd) << "the narrower views, located again: more pixels per degree";
  // A failing xrSyncActions (the plugin syncs its own set in this mode) is named too.
  script.fail_call(XrFn::sync_actions, XR_ERROR_SESSION_LOST);
  t = run_xr_frames(p, t, 2);
  info = frame_info_of(p);
  EXPECT_EQ(info.head_valid, 1u);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  EXPECT_TRUE(contains(gaze_status_of(p), "xrSyncActions failed")) << gaze_status_of(p);
  gzl_destroy(p);
  EXPECT_TRUE(nothing_left_behind());
}

TEST(CApiFakeXrErrors, NonFinitePosesFromTheRuntimeAreNotUsed) {
  gzl_object o = 0;
  gzl_plugin p = plugin_with_object(GZL_GAZE_INPUT_APP_SPACE, 0, o);
  ASSERT_NE(p, nullptr);
  int64_t t = run_xr_frames(p, kXrStartNs, 5);
  uint8_t foveal = 0xEE;  // gaze and head straight at it
  ASSERT_EQ(gzl_get_levels(p, 1, &o, &foveal), GZL_SUCCESS);
  FakeXrScript& script = FakeXr::get().script;
  script.head.position.y = kNaNf;
  script.gaze.orientation = {kNaNf, 0, 0, 1};
  t = run_xr_frames(p, t, 40);
  const gzl_frame_info info = frame_info_of(p);
  EXPECT_EQ(info.head_valid, 0u);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  EXPECT_TRUE(std::isfinite(info.eye_position_base_m.y));
  EXPECT_TRUE(std::isfinite(info.gaze_direction_base.x));
  EXPECT_TRUE(contains(gaze_status_of(p), "degenerate gaze orientation")) << gaze_status_of(p);
  uint8_t level = 0xEE;
  ASSERT_EQ(gzl_get_levels(p, 1, &o, &level), GZL_SUCCESS);
  EXPECT_EQ(level, foveal) << "the object ahead, in the widened cone, keeps foveal detail";
  gzl_destroy(p);
  EXPECT_TRUE(nothing_left_behind());
}

TEST(CApiFakeXrErrors, BadArgumentsGetTheirResultCodes) {
  FakeXr::get().reset();
  gzl_openxr_create_info info = fake_openxr_info(GZL_GAZE_INPUT_APP_SPACE);
  gzl_plugin p = nullptr;
  EXPECT_TRUE(refused(nullptr, gzl_create_openxr(nullptr, &p), GZL_ERROR_NULL_POINTER, "info"));
  EXPECT_TRUE(refused(nullptr, gzl_create_openxr(&info, nullptr), GZL_ERROR_NULL_POINTER, "plugin"));
  info.type = GZL_TYPE_DATA_CREATE_INFO;
  EXPECT_TRUE(refused(nullptr, create(info, p), GZL_ERROR_STRUCT_TYPE, "info->type"));
  info = fake_openxr_info(GZL_GAZE_INPUT_APP_SPACE);
  info.get_instance_proc_addr = nullptr;
  EXPECT_TRUE(refused(nullptr, create(info, p), GZL_ERROR_NULL_POINTER, "get_instance_proc_addr"));
  for (uint64_t gzl_openxr_create_info::*handle :
       {&gzl_openxr_create_info::instance, &gzl_openxr_create_info::session, &gzl_openxr_create_info::base_space}) {
    info = fake_openxr_info(GZL_GAZE_INPUT_APP_SPACE);
    info.*handle = 0;
    EXPECT_TRUE(refused(nullptr, create(info, p), GZL_ERROR_INVALID_ARGUMENT, "must be live handles"));
    EXPECT_EQ(p, nullptr);
  }
  info = fake_openxr_info(GZL_GAZE_INPUT_APP_SPACE);
  info.view_configuration_type = 7;
  EXPECT_TRUE(refused(nullptr, create(info, p), GZL_ERROR_INVALID_ARGUMENT, "view_configuration_type 7"));
  info = fake_openxr_info(static_cast<gzl_gaze_input>(99));
  EXPECT_TRUE(refused(nullptr, create(info, p), GZL_ERROR_INVALID_ARGUMENT, "gaze_input 99"));
  EXPECT_EQ(FakeXr::get().log.count(XrFn::create_reference_space), 0) << "refused before any OpenXR call";

  p = create_on_fake(GZL_GAZE_INPUT_PLUGIN_ACTIONS);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(gzl_begin_frame_openxr(nullptr, kXrStartNs), GZL_ERROR_NULL_HANDLE);
  ASSERT_EQ(gzl_begin_frame_openxr(p, kXrStartNs), GZL_SUCCESS);
  EXPECT_TRUE(refused(p, gzl_begin_frame_openxr(p, kXrStartNs), GZL_ERROR_TIME_OUT_OF_ORDER, "predictedDisplayTime"));
  EXPECT_TRUE(refused(p, gzl_begin_frame_openxr(p, (int64_t{1} << 62) + 1), GZL_ERROR_INVALID_ARGUMENT, "2^62"));
  EXPECT_TRUE(refused(p, gzl_set_base_space(p, 0), GZL_ERROR_INVALID_ARGUMENT, "base space"));
  EXPECT_TRUE(refused(p, gzl_set_gaze_space(p, 5, 0), GZL_ERROR_INVALID_ARGUMENT, "GZL_GAZE_INPUT_APP_SPACE"));
  EXPECT_TRUE(refused(p, gzl_set_view_resolution(p, 2, 100, 100), GZL_ERROR_INVALID_ARGUMENT, "view 2"));
  gzl_frame_input in = still_head(kXrStartNs + kXrFrameNs);
  EXPECT_TRUE(refused(p, gzl_begin_frame_data(p, &in), GZL_ERROR_WRONG_MODE, "gzl_begin_frame_openxr"));
  gzl_gaze_sample s = gaze_at(kXrStartNs, 0);
  EXPECT_TRUE(refused(p, gzl_push_gaze_sample(p, &s), GZL_ERROR_INVALID_ARGUMENT, "GZL_GAZE_INPUT_PUSHED"));
  gzl_object o = 0;
  gzl_object_desc d = object_at(0, 0, 2.0);
  d.center_m.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(refused(p, gzl_add_object(p, &d, &o), GZL_ERROR_INVALID_ARGUMENT, "desc->center_m"));
  EXPECT_EQ(o, GZL_NULL_OBJECT);
  // Still usable; a recentred base space is taken.
  ASSERT_EQ(gzl_set_base_space(p, GZL_XR_HANDLE(FakeXr::get().stage_space())), GZL_SUCCESS) << last_error(p);
  EXPECT_EQ(gzl_begin_frame_openxr(p, kXrStartNs + kXrFrameNs), GZL_SUCCESS) << last_error(p);
  EXPECT_EQ(frame_info_of(p).head_valid, 1u);
  ASSERT_EQ(gzl_shutdown(p), GZL_SUCCESS);
  EXPECT_TRUE(nothing_left_behind()) << "gzl_shutdown releases what the plugin made";
  const int locates = FakeXr::get().log.count(XrFn::locate_space);
  EXPECT_TRUE(refused(p, gzl_begin_frame_openxr(p, kXrStartNs + 2 * kXrFrameNs), GZL_ERROR_SHUT_DOWN, "gzl_destroy"));
  EXPECT_EQ(FakeXr::get().log.count(XrFn::locate_space), locates);
  gzl_destroy(p);
}

TEST(CApiFakeXrErrors, ZeroObjectsIsAValidScene) {
  FakeXr::get().reset();
  gzl_plugin p = create_on_fake(GZL_GAZE_INPUT_APP_SPACE);
  ASSERT_NE(p, nullptr);
  run_xr_frames(p, kXrStartNs, 3);
  const gzl_frame_info info = frame_info_of(p);
  EXPECT_EQ(info.frame_index, 3u);
  EXPECT_EQ(info.object_count, 0u);
  EXPECT_EQ(info.triangles_drawn, 0u);
  EXPECT_EQ(info.triangles_full, 0u);
  EXPECT_EQ(info.gaze_source, GZL_GAZE_SOURCE_OPENXR);
  EXPECT_EQ(gzl_get_levels(p, 0, nullptr, nullptr), GZL_SUCCESS);
  gzl_foveal_cone cone{};
  cone.type = GZL_TYPE_FOVEAL_CONE;
  ASSERT_EQ(gzl_get_foveal_cone(p, 0, &cone), GZL_SUCCESS);
  EXPECT_EQ(cone.in_view, 1u);
  EXPECT_NEAR(cone.center_v, 0.5, 1e-6) << "gaze straight ahead: the image's vertical centre";
  EXPECT_TRUE(refused(p, gzl_get_foveal_cone(p, 2, &cone), GZL_ERROR_INVALID_ARGUMENT, "view 2"));
  gzl_destroy(p);
  EXPECT_TRUE(nothing_left_behind());
}

}  // namespace
}  // namespace gazelod::test
