// SPDX-License-Identifier: Apache-2.0
// XR_EXT_conformance_automation through the loader: a test switches a controller on, presses
// a button, places its grip pose and overrides the gaze pose; the action system reports them
// after the next xrSyncActions, and the interaction profile changes are announced there.
#include "tests/runtime/xr_client.hpp"

#include <cmath>
#include <cstring>

namespace gazelod::xrrt_test {
namespace {

TEST(RuntimeAutomation, DrivesControllerButtonsPosesAndGaze) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(
      hs.create({XR_EXT_CONFORMANCE_AUTOMATION_EXTENSION_NAME, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME}));
  const XrInstance inst = hs.instance;
  auto set_active = proc<PFN_xrSetInputDeviceActiveEXT>(inst, "xrSetInputDeviceActiveEXT");
  auto set_bool = proc<PFN_xrSetInputDeviceStateBoolEXT>(inst, "xrSetInputDeviceStateBoolEXT");
  auto set_location = proc<PFN_xrSetInputDeviceLocationEXT>(inst, "xrSetInputDeviceLocationEXT");
  ASSERT_TRUE(set_active && set_bool && set_location);

  XrActionSetCreateInfo asi{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(asi.actionSetName, "test");
  std::strcpy(asi.localizedActionSetName, "Test");
  XrActionSet set = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSet(inst, &asi, &set), XR_SUCCESS);
  const XrPath left = path(inst, "/user/hand/left");
  auto make_action = [&](const char* name, XrActionType type, bool with_hand) {
    XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
    ai.actionType = type;
    std::strcpy(ai.actionName, name);
    std::strcpy(ai.localizedActionName, name);
    ai.countSubactionPaths = with_hand ? 1 : 0;
    ai.subactionPaths = with_hand ? &left : nullptr;
    XrAction a = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateAction(set, &ai, &a), XR_SUCCESS);
    return a;
  };
  const XrAction select = make_action("select", XR_ACTION_TYPE_BOOLEAN_INPUT, true);
  const XrAction grip = make_action("grip", XR_ACTION_TYPE_POSE_INPUT, true);
  const XrAction gaze = make_action("gaze", XR_ACTION_TYPE_POSE_INPUT, false);
  const XrPath simple = path(inst, "/interaction_profiles/khr/simple_controller");
  const XrPath select_path = path(inst, "/user/hand/left/input/select/click");
  const XrPath grip_path = path(inst, "/user/hand/left/input/grip/pose");
  const XrActionSuggestedBinding hand_bindings[] = {{select, select_path}, {grip, grip_path}};
  XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sb.interactionProfile = simple;
  sb.countSuggestedBindings = 2;
  sb.suggestedBindings = hand_bindings;
  ASSERT_EQ(xrSuggestInteractionProfileBindings(inst, &sb), XR_SUCCESS);
  const XrPath eyes = path(inst, "/user/eyes_ext");
  const XrPath gaze_path = path(inst, "/user/eyes_ext/input/gaze_ext/pose");
  const XrActionSuggestedBinding gaze_binding{gaze, gaze_path};
  sb.interactionProfile = path(inst, "/interaction_profiles/ext/eye_gaze_interaction");
  sb.countSuggestedBindings = 1;
  sb.suggestedBindings = &gaze_binding;
  ASSERT_EQ(xrSuggestInteractionProfileBindings(inst, &sb), XR_SUCCESS);
  XrSessionActionSetsAttachInfo at{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  at.countActionSets = 1;
  at.actionSets = &set;
  ASSERT_EQ(xrAttachSessionActionSets(hs.session, &at), XR_SUCCESS);
  XrActionSpaceCreateInfo asci{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  asci.action = grip;
  asci.subactionPath = left;
  asci.poseInActionSpace.orientation.w = 1.0f;
  XrSpace grip_space = XR_NULL_HANDLE, gaze_space = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSpace(hs.session, &asci, &grip_space), XR_SUCCESS);
  asci.action = gaze;
  asci.subactionPath = XR_NULL_PATH;
  ASSERT_EQ(xrCreateActionSpace(hs.session, &asci, &gaze_space), XR_SUCCESS);
  const XrSpace local = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSpace view = hs.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  ASSERT_NO_FATAL_FAILURE(hs.begin());

  const XrActiveActionSet active{set, XR_NULL_PATH};
  XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = select;
  XrActionStateBoolean b{XR_TYPE_ACTION_STATE_BOOLEAN};
  ASSERT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
  ASSERT_EQ(xrGetActionStateBoolean(hs.session, &get, &b), XR_SUCCESS);
  EXPECT_EQ(b.isActive, XR_FALSE) << "no controller until automation turns one on";
  XrInteractionProfileState ips{XR_TYPE_INTERACTION_PROFILE_STATE};
  ASSERT_EQ(xrGetCurrentInteractionProfile(hs.session, eyes, &ips), XR_SUCCESS);
  EXPECT_EQ(ips.interactionProfile, path(inst, "/interaction_profiles/ext/eye_gaze_interaction"));

  // The profile changes, with its event, at the next xrSyncActions only (section 11.4).
  ASSERT_EQ(set_active(hs.session, simple, left, XR_TRUE), XR_SUCCESS);
  ASSERT_EQ(xrGetCurrentInteractionProfile(hs.session, left, &ips), XR_SUCCESS);
  EXPECT_EQ(ips.interactionProfile, XR_NULL_PATH);
  int profile_events = 0;
  XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
  const auto count_profile_events = [&] {
    while (xrPollEvent(inst, &e) == XR_SUCCESS) {
      profile_events += e.type == XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED;
      e = {XR_TYPE_EVENT_DATA_BUFFER};
    }
  };
  count_profile_events();
  EXPECT_EQ(profile_events, 1) << "only the eyes' change, from the first xrSyncActions";
  ASSERT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
  ASSERT_EQ(xrGetCurrentInteractionProfile(hs.session, left, &ips), XR_SUCCESS);
  EXPECT_EQ(ips.interactionProfile, simple);
  ASSERT_EQ(xrGetActionStateBoolean(hs.session, &get, &b), XR_SUCCESS);
  EXPECT_EQ(b.isActive, XR_TRUE);
  EXPECT_EQ(b.currentState, XR_FALSE);
  ASSERT_EQ(set_bool(hs.session, left, select_path, XR_TRUE), XR_SUCCESS);
  ASSERT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
  get.subactionPath = left;
  ASSERT_EQ(xrGetActionStateBoolean(hs.session, &get, &b), XR_SUCCESS);
  EXPECT_EQ(b.currentState, XR_TRUE);
  EXPECT_EQ(b.changedSinceLastSync, XR_TRUE);
  ASSERT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
  ASSERT_EQ(xrGetActionStateBoolean(hs.session, &get, &b), XR_SUCCESS);
  EXPECT_EQ(b.changedSinceLastSync, XR_FALSE);

  // Grip pose set in LOCAL comes back in LOCAL.
  XrPosef pose{};
  pose.orientation = {0.0f, std::sin(0.25f), 0.0f, std::cos(0.25f)};
  pose.position = {0.2f, -0.3f, -0.4f};
  ASSERT_EQ(set_location(hs.session, left, grip_path, local, pose), XR_SUCCESS);
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  ASSERT_EQ(xrLocateSpace(grip_space, local, 2'000'000'000, &loc), XR_SUCCESS);
  EXPECT_TRUE(loc.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT);
  EXPECT_NEAR(loc.pose.position.x, 0.2f, 1e-6);
  EXPECT_NEAR(loc.pose.position.z, -0.4f, 1e-6);
  EXPECT_NEAR(loc.pose.orientation.y, std::sin(0.25f), 1e-6);

  // A gaze pose set in VIEW replaces the simulated gaze.
  XrPosef gaze_pose{};
  gaze_pose.orientation = {std::sin(0.1f), 0.0f, 0.0f, std::cos(0.1f)};  // 0.2 rad up
  ASSERT_EQ(set_location(hs.session, eyes, gaze_path, view, gaze_pose), XR_SUCCESS);
  XrEyeGazeSampleTimeEXT st{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
  XrSpaceLocation gl{XR_TYPE_SPACE_LOCATION, &st};
  ASSERT_EQ(xrLocateSpace(gaze_space, view, 2'100'000'000, &gl), XR_SUCCESS);
  EXPECT_NEAR(gl.pose.orientation.x, std::sin(0.1f), 1e-6);
  EXPECT_EQ(st.time, 2'100'000'000);

  // Switching the controller off makes its actions inactive again.
  ASSERT_EQ(set_active(hs.session, simple, left, XR_FALSE), XR_SUCCESS);
  ASSERT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
  ASSERT_EQ(xrGetActionStateBoolean(hs.session, &get, &b), XR_SUCCESS);
  EXPECT_EQ(b.isActive, XR_FALSE);
  ASSERT_EQ(xrLocateSpace(grip_space, local, 2'000'000'000, &loc), XR_SUCCESS);
  EXPECT_EQ(loc.locationFlags, 0u);
  // Paths the profile does not have.
  EXPECT_EQ(set_active(hs.session, simple, eyes, XR_TRUE), XR_ERROR_PATH_UNSUPPORTED);
  EXPECT_EQ(set_bool(hs.session, left, gaze_path, XR_TRUE), XR_ERROR_PATH_UNSUPPORTED);

  // Interaction profile changes were announced: the eyes, the controller on and off.
  count_profile_events();
  EXPECT_EQ(profile_events, 3);
  hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
