// SPDX-License-Identifier: Apache-2.0
// The C ABI in OpenXR mode over the Khronos loader and the simulated runtime: every OpenXR call
// through the application's xrGetInstanceProcAddr; an OpenXR-mode run recorded frame by frame
// (gzl_get_frame_record) and replayed through data mode gives the same levels in every frame;
// an eye-gaze binding the application's own suggestion replaced is detected and named.
#include "apps/xr_host/xr_app.hpp"
#include "tests/capi/capi_test_util.hpp"
#include "tests/run/run_test_util.hpp"

#include <gtest/gtest.h>
#include <openxr/openxr.h>

#include <cstring>

namespace gazelod::test {
namespace {

struct StateEvent {
  std::size_t before_frame;
  XrSessionState state;
  XrTime time;
};

std::vector<gzl_object> add_grid(gzl_plugin p) {
  std::vector<gzl_object> out;
  for (int yaw = -30; yaw <= 30; yaw += 10)
    for (int pitch = -20; pitch <= 20; pitch += 10) {
      gzl_object o = 0;
      gzl_object_desc d = object_at(yaw, pitch, 2.0 + (yaw + 30) / 20.0);
      EXPECT_EQ(gzl_add_object(p, &d, &o), GZL_SUCCESS) << last_error(p);
      out.push_back(o);
    }
  return out;
}

TEST(CApiOpenXr, RecordedRunReplaysThroughDataModeIdentically) {
  use_simulated_runtime("");  // the default scenario: head sweeps and turns, saccades, pursuit, blinks
  xr_host::XrApp app(true);
  ASSERT_TRUE(app.eye_gaze_enabled());
  gzl_config cfg{};
  cfg.type = GZL_TYPE_CONFIG;
  cfg.max_gaze_sample_age_s = 1.0;
  gzl_openxr_create_info info{};
  info.type = GZL_TYPE_OPENXR_CREATE_INFO;
  info.get_instance_proc_addr = reinterpret_cast<gzl_void_function>(xrGetInstanceProcAddr);
  info.instance = GZL_XR_HANDLE(app.instance());
  info.system_id = app.system();
  info.session = GZL_XR_HANDLE(app.session());
  info.base_space = GZL_XR_HANDLE(app.local_space());
  info.gaze_input = GZL_GAZE_INPUT_PLUGIN_ACTIONS;  // this host has no actions of its own
  info.config = &cfg;
  gzl_plugin xr = nullptr;
  ASSERT_EQ(gzl_create_openxr(&info, &xr), GZL_SUCCESS) << last_error(nullptr);
  const std::vector<gzl_object> objects = add_grid(xr);

  std::vector<gzl_frame_record> records;
  std::vector<std::vector<uint8_t>> levels;
  std::vector<StateEvent> events;
  int gaze_frames = 0;
  while (records.size() < 600 && app.poll_events([&](XrSessionState s, XrTime t) {
    events.push_back({records.size(), s, t});
    ASSERT_EQ(gzl_on_session_state(xr, s, t), GZL_SUCCESS);
  })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    ASSERT_EQ(gzl_begin_frame_openxr(xr, fs.predictedDisplayTime), GZL_SUCCESS) << last_error(xr);
    std::vector<uint8_t> l(objects.size());
    ASSERT_EQ(gzl_get_levels(xr, static_cast<uint32_t>(objects.size()), objects.data(), l.data()), GZL_SUCCESS);
    levels.push_back(l);
    gzl_frame_record r{};
    r.type = GZL_TYPE_FRAME_RECORD;
    ASSERT_EQ(gzl_get_frame_record(xr, &r), GZL_SUCCESS);
    records.push_back(r);
    gzl_frame_info fi{};
    fi.type = GZL_TYPE_FRAME_INFO;
    ASSERT_EQ(gzl_get_frame_info(xr, &fi), GZL_SUCCESS);
    gaze_frames += fi.gaze_source == GZL_GAZE_SOURCE_OPENXR;
    app.end_frame(fs.predictedDisplayTime, {});
  }
  ASSERT_EQ(records.size(), 600u);
  EXPECT_GT(gaze_frames, 500) << "eye gaze through the application's xrGetInstanceProcAddr";
  EXPECT_EQ(gzl_shutdown(xr), GZL_SUCCESS);  // before the session and instance go
  gzl_destroy(xr);

  // Replay: the same display, objects, session states, gaze samples and head poses.
  gzl_data_create_info di{};
  di.type = GZL_TYPE_DATA_CREATE_INFO;
  di.view_count = records[0].view_count;
  di.views = records[0].views;
  di.config = &cfg;
  gzl_plugin data = nullptr;
  ASSERT_EQ(gzl_create_data(&di, &data), GZL_SUCCESS) << last_error(nullptr);
  const std::vector<gzl_object> replayed = add_grid(data);
  std::size_t next_event = 0, differing = 0, varied = 0;
  for (std::size_t k = 0; k < records.size(); ++k) {
    for (; next_event < events.size() && events[next_event].before_frame <= k; ++next_event)
      ASSERT_EQ(gzl_on_session_state(data, events[next_event].state, events[next_event].time), GZL_SUCCESS);
    const gzl_frame_record& r = records[k];
    if (r.has_gaze_sample) {
      ASSERT_EQ(gzl_push_gaze_sample(data, &r.gaze_sample), GZL_SUCCESS) << last_error(data);
    }
    gzl_frame_input in{};
    in.type = GZL_TYPE_FRAME_INPUT;
    in.display_time_ns = r.display_time_ns;
    in.head = r.head;
    in.view_count = r.view_count;
    in.views = r.views;
    ASSERT_EQ(gzl_begin_frame_data(data, &in), GZL_SUCCESS) << last_error(data);
    std::vector<uint8_t> l(replayed.size());
    ASSERT_EQ(gzl_get_levels(data, static_cast<uint32_t>(replayed.size()), replayed.data(), l.data()), GZL_SUCCESS);
    differing += l != levels[k];
    varied += *std::max_element(l.begin(), l.end()) != *std::min_element(l.begin(), l.end());
  }
  EXPECT_EQ(differing, 0u) << "frames whose levels differ between OpenXR mode and its data-mode replay";
  // 256 of the 600 frames when written: the fovea and the head's motion decide.
  EXPECT_GT(varied, 200u) << "frames where the grid's levels differ";
  gzl_destroy(data);
}

XrPath path(XrInstance i, const char* s) {
  XrPath p = XR_NULL_PATH;
  EXPECT_EQ(xrStringToPath(i, s, &p), XR_SUCCESS);
  return p;
}

TEST(CApiOpenXr, BindingReplacedByTheApplicationIsNamed) {
  use_simulated_runtime("");
  xr_host::XrApp app(true);
  ASSERT_TRUE(app.eye_gaze_enabled());
  gzl_openxr_create_info info{};
  info.type = GZL_TYPE_OPENXR_CREATE_INFO;
  info.get_instance_proc_addr = reinterpret_cast<gzl_void_function>(xrGetInstanceProcAddr);
  info.instance = GZL_XR_HANDLE(app.instance());
  info.system_id = app.system();
  info.session = GZL_XR_HANDLE(app.session());
  info.base_space = GZL_XR_HANDLE(app.local_space());
  info.gaze_input = GZL_GAZE_INPUT_MERGE_BINDING;
  gzl_plugin p = nullptr;
  ASSERT_EQ(gzl_create_openxr(&info, &p), GZL_SUCCESS) << last_error(nullptr);
  gzl_gaze_binding b{};
  b.type = GZL_TYPE_GAZE_BINDING;
  ASSERT_EQ(gzl_get_gaze_binding(p, &b), GZL_SUCCESS) << last_error(p);
  EXPECT_STREQ(b.interaction_profile, "/interaction_profiles/ext/eye_gaze_interaction");

  // The application's own eye-gaze action, suggested alone: gazelod's binding is not merged.
  XrActionSetCreateInfo si{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(si.actionSetName, "app");
  std::strcpy(si.localizedActionSetName, "app");
  XrActionSet app_set = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSet(app.instance(), &si, &app_set), XR_SUCCESS);
  XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
  ai.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(ai.actionName, "gaze");
  std::strcpy(ai.localizedActionName, "gaze");
  XrAction app_gaze = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateAction(app_set, &ai, &app_gaze), XR_SUCCESS);
  XrActionSuggestedBinding sb{app_gaze, path(app.instance(), b.binding_path)};
  XrInteractionProfileSuggestedBinding sug{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sug.interactionProfile = path(app.instance(), b.interaction_profile);
  sug.countSuggestedBindings = 1;
  sug.suggestedBindings = &sb;
  ASSERT_EQ(xrSuggestInteractionProfileBindings(app.instance(), &sug), XR_SUCCESS);
  XrActionSet sets[2] = {app_set, reinterpret_cast<XrActionSet>(static_cast<uintptr_t>(b.action_set))};
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 2;
  attach.actionSets = sets;
  ASSERT_EQ(xrAttachSessionActionSets(app.session(), &attach), XR_SUCCESS);
  ASSERT_EQ(gzl_action_sets_attached(p), GZL_SUCCESS) << last_error(p);

  int frames = 0;
  while (frames < 200 && app.poll_events([&](XrSessionState s, XrTime t) { gzl_on_session_state(p, s, t); })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    XrActiveActionSet active[2] = {{sets[0], XR_NULL_PATH}, {sets[1], XR_NULL_PATH}};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 2;
    sync.activeActionSets = active;
    xrSyncActions(app.session(), &sync);
    ASSERT_EQ(gzl_begin_frame_openxr(p, fs.predictedDisplayTime), GZL_SUCCESS) << last_error(p);
    app.end_frame(fs.predictedDisplayTime, {});
    ++frames;
  }
  gzl_frame_info fi{};
  fi.type = GZL_TYPE_FRAME_INFO;
  ASSERT_EQ(gzl_get_frame_info(p, &fi), GZL_SUCCESS);
  EXPECT_EQ(fi.gaze_source, GZL_GAZE_SOURCE_HEAD_FIXED);
  char why[1024];
  ASSERT_EQ(gzl_get_gaze_status(p, why, sizeof why, nullptr), GZL_SUCCESS);
  EXPECT_NE(std::string(why).find("replaced by the application's own suggestion"), std::string::npos) << why;
  EXPECT_NE(std::string(why).find("GZL_GAZE_INPUT_MERGE_BINDING"), std::string::npos) << why;
  gzl_shutdown(p);
  gzl_destroy(p);
  xrDestroyActionSet(app_set);
}

// Recentring (a new base space) and a new render resolution between frames: the eye's position
// follows the new space from the next frame, and the display's limit the resolution rendered.
TEST(CApiOpenXr, BaseSpaceAndResolutionChangeBetweenFrames) {
  use_simulated_runtime("");
  xr_host::XrApp app(true);
  gzl_openxr_create_info info{};
  info.type = GZL_TYPE_OPENXR_CREATE_INFO;
  info.get_instance_proc_addr = reinterpret_cast<gzl_void_function>(xrGetInstanceProcAddr);
  info.instance = GZL_XR_HANDLE(app.instance());
  info.system_id = app.system();
  info.session = GZL_XR_HANDLE(app.session());
  info.base_space = GZL_XR_HANDLE(app.local_space());
  info.gaze_input = GZL_GAZE_INPUT_NONE;
  gzl_plugin p = nullptr;
  ASSERT_EQ(gzl_create_openxr(&info, &p), GZL_SUCCESS) << last_error(nullptr);
  XrReferenceSpaceCreateInfo ri{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  ri.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  ri.poseInReferenceSpace.orientation.w = 1.0f;
  ri.poseInReferenceSpace.position.y = -2.0f;  // the new origin 2 m lower
  XrSpace lower = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateReferenceSpace(app.session(), &ri, &lower), XR_SUCCESS);
  std::vector<gzl_frame_info> infos;
  while (infos.size() < 20 && app.poll_events([&](XrSessionState s, XrTime t) { gzl_on_session_state(p, s, t); })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    if (infos.size() == 10) {
      ASSERT_EQ(gzl_set_base_space(p, GZL_XR_HANDLE(lower)), GZL_SUCCESS) << last_error(p);
      for (uint32_t v = 0; v < 2; ++v) {
        ASSERT_EQ(gzl_set_view_resolution(p, v, 500, 500), GZL_SUCCESS) << last_error(p);
      }
    }
    ASSERT_EQ(gzl_begin_frame_openxr(p, fs.predictedDisplayTime), GZL_SUCCESS) << last_error(p);
    gzl_frame_info fi{};
    fi.type = GZL_TYPE_FRAME_INFO;
    ASSERT_EQ(gzl_get_frame_info(p, &fi), GZL_SUCCESS);
    infos.push_back(fi);
    app.end_frame(fs.predictedDisplayTime, {});
  }
  ASSERT_EQ(infos.size(), 20u);
  EXPECT_NEAR(infos[10].eye_position_base_m.y - infos[9].eye_position_base_m.y, 2.0, 0.05)
      << "the head 2 m higher in the new space";
  EXPECT_LT(infos[10].xi_cpd, 0.6 * infos[9].xi_cpd) << "500 px rendered: a lower display limit";
  EXPECT_EQ(gzl_set_view_resolution(p, 2, 500, 500), GZL_ERROR_INVALID_ARGUMENT)
      << "a stereo configuration has 2 views";
  gzl_shutdown(p);
  gzl_destroy(p);
  xrDestroySpace(lower);
}

// An engine whose eye-gaze action exists only after it attached its sets: gazelod is created
// without a gaze space (APP_SPACE), distrusts the empty input after its timeout, and trusts
// the space given later afresh.
TEST(CApiOpenXr, GazeSpaceGivenLateIsTrustedAfresh) {
  use_simulated_runtime("");
  xr_host::XrApp app(true);
  ASSERT_TRUE(app.eye_gaze_enabled());
  gzl_openxr_create_info info{};
  info.type = GZL_TYPE_OPENXR_CREATE_INFO;
  info.get_instance_proc_addr = reinterpret_cast<gzl_void_function>(xrGetInstanceProcAddr);
  info.instance = GZL_XR_HANDLE(app.instance());
  info.system_id = app.system();
  info.session = GZL_XR_HANDLE(app.session());
  info.base_space = GZL_XR_HANDLE(app.local_space());
  info.gaze_input = GZL_GAZE_INPUT_APP_SPACE;  // zero-initialised create info: the engine's space comes later
  gzl_plugin p = nullptr;
  ASSERT_EQ(gzl_create_openxr(&info, &p), GZL_SUCCESS) << last_error(nullptr);

  XrActionSetCreateInfo si{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(si.actionSetName, "engine");
  std::strcpy(si.localizedActionSetName, "engine");
  XrActionSet set = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSet(app.instance(), &si, &set), XR_SUCCESS);
  XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
  ai.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(ai.actionName, "eyes");
  std::strcpy(ai.localizedActionName, "eyes");
  XrAction eyes = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateAction(set, &ai, &eyes), XR_SUCCESS);
  XrActionSuggestedBinding sb{eyes, path(app.instance(), "/user/eyes_ext/input/gaze_ext/pose")};
  XrInteractionProfileSuggestedBinding sug{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sug.interactionProfile = path(app.instance(), "/interaction_profiles/ext/eye_gaze_interaction");
  sug.countSuggestedBindings = 1;
  sug.suggestedBindings = &sb;
  ASSERT_EQ(xrSuggestInteractionProfileBindings(app.instance(), &sug), XR_SUCCESS);
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &set;
  ASSERT_EQ(xrAttachSessionActionSets(app.session(), &attach), XR_SUCCESS);

  XrSpace eye_space = XR_NULL_HANDLE;
  int frames = 0;
  gzl_gaze_source before = GZL_GAZE_SOURCE_OPENXR, after = GZL_GAZE_SOURCE_HEAD_FIXED;
  while (frames < 300 && app.poll_events([&](XrSessionState s, XrTime t) { gzl_on_session_state(p, s, t); })) {
    if (!app.session_running()) continue;
    const XrFrameState fs = app.wait_frame();
    app.begin_frame();
    XrActiveActionSet active{set, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    xrSyncActions(app.session(), &sync);
    if (frames == 150) {  // past the 1 s silence timeout
      XrActionSpaceCreateInfo ci{XR_TYPE_ACTION_SPACE_CREATE_INFO};
      ci.action = eyes;
      ci.poseInActionSpace.orientation.w = 1.0f;
      ASSERT_EQ(xrCreateActionSpace(app.session(), &ci, &eye_space), XR_SUCCESS);
      ASSERT_EQ(gzl_set_gaze_space(p, GZL_XR_HANDLE(eye_space), GZL_XR_HANDLE(eyes)), GZL_SUCCESS) << last_error(p);
    }
    ASSERT_EQ(gzl_begin_frame_openxr(p, fs.predictedDisplayTime), GZL_SUCCESS) << last_error(p);
    gzl_frame_info fi{};
    fi.type = GZL_TYPE_FRAME_INFO;
    ASSERT_EQ(gzl_get_frame_info(p, &fi), GZL_SUCCESS);
    if (frames == 149) before = fi.gaze_source;
    if (fi.gaze_source == GZL_GAZE_SOURCE_OPENXR) after = fi.gaze_source;
    app.end_frame(fs.predictedDisplayTime, {});
    ++frames;
  }
  EXPECT_EQ(before, GZL_GAZE_SOURCE_HEAD_FIXED) << "no gaze space yet";
  EXPECT_EQ(after, GZL_GAZE_SOURCE_OPENXR) << "the space given late delivers";
  gzl_shutdown(p);
  gzl_destroy(p);
  xrDestroySpace(eye_space);
  xrDestroyActionSet(set);
}

}  // namespace
}  // namespace gazelod::test
