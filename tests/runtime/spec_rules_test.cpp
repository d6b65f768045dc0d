// SPDX-License-Identifier: Apache-2.0
// Rules of the OpenXR 1.0 specification that Khronos's conformance suite (CTS 1.1.41) found the
// runtime breaking, each pinned here so that it holds without the CTS: queued events of a
// destroyed session, headless frames with layers they cannot show, strict binding paths and the core
// 1.0 interaction profiles, action-set priority, subaction paths in xrSyncActions, impossible
// type conversions, and a default pose for activated controllers.
#include "tests/runtime/xr_client.hpp"

#include <cstring>
#include <string>

namespace gazelod::xrrt_test {
namespace {

XrActionSet make_set(XrInstance instance, const char* name, std::uint32_t priority) {
  XrActionSetCreateInfo info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(info.actionSetName, name);
  std::strcpy(info.localizedActionSetName, name);
  info.priority = priority;
  XrActionSet set = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateActionSet(instance, &info, &set), XR_SUCCESS);
  return set;
}

XrAction make_action(XrActionSet set, const char* name, XrActionType type, const std::vector<XrPath>& subactions = {}) {
  XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
  info.actionType = type;
  std::strcpy(info.actionName, name);
  std::strcpy(info.localizedActionName, name);
  info.countSubactionPaths = static_cast<std::uint32_t>(subactions.size());
  info.subactionPaths = subactions.empty() ? nullptr : subactions.data();
  XrAction action = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateAction(set, &info, &action), XR_SUCCESS);
  return action;
}

XrResult suggest(XrInstance instance, const char* profile, const std::vector<XrActionSuggestedBinding>& bindings) {
  XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sb.interactionProfile = path(instance, profile);
  sb.countSuggestedBindings = static_cast<std::uint32_t>(bindings.size());
  sb.suggestedBindings = bindings.data();
  return xrSuggestInteractionProfileBindings(instance, &sb);
}

void attach(XrSession session, const std::vector<XrActionSet>& sets) {
  XrSessionActionSetsAttachInfo info{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  info.countActionSets = static_cast<std::uint32_t>(sets.size());
  info.actionSets = sets.data();
  ASSERT_EQ(xrAttachSessionActionSets(session, &info), XR_SUCCESS);
}

XrResult sync(XrSession session, const std::vector<XrActiveActionSet>& sets) {
  XrActionsSyncInfo info{XR_TYPE_ACTIONS_SYNC_INFO};
  info.countActiveActionSets = static_cast<std::uint32_t>(sets.size());
  info.activeActionSets = sets.data();
  return xrSyncActions(session, &info);
}

bool active(XrSession session, XrAction action, XrActionType type) {
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = action;
  switch (type) {
    case XR_ACTION_TYPE_BOOLEAN_INPUT: {
      XrActionStateBoolean s{XR_TYPE_ACTION_STATE_BOOLEAN};
      EXPECT_EQ(xrGetActionStateBoolean(session, &get, &s), XR_SUCCESS);
      return s.isActive == XR_TRUE;
    }
    case XR_ACTION_TYPE_FLOAT_INPUT: {
      XrActionStateFloat s{XR_TYPE_ACTION_STATE_FLOAT};
      EXPECT_EQ(xrGetActionStateFloat(session, &get, &s), XR_SUCCESS);
      return s.isActive == XR_TRUE;
    }
    case XR_ACTION_TYPE_VECTOR2F_INPUT: {
      XrActionStateVector2f s{XR_TYPE_ACTION_STATE_VECTOR2F};
      EXPECT_EQ(xrGetActionStateVector2f(session, &get, &s), XR_SUCCESS);
      return s.isActive == XR_TRUE;
    }
    default: {
      XrActionStatePose s{XR_TYPE_ACTION_STATE_POSE};
      EXPECT_EQ(xrGetActionStatePose(session, &get, &s), XR_SUCCESS);
      return s.isActive == XR_TRUE;
    }
  }
}

// The runtime discards queued events holding a destroyed session (section 2.9).
TEST(RuntimeSpecRules, EventsOfADestroyedSessionAreDiscarded) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));  // queues IDLE and READY, not polled
  ASSERT_EQ(xrDestroySession(hs.session), XR_SUCCESS);
  hs.session = XR_NULL_HANDLE;
  XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
  EXPECT_EQ(xrPollEvent(hs.instance, &e), XR_EVENT_UNAVAILABLE) << "event type " << e.type;
  hs.destroy();
}

// A headless session shows nothing, so it accepts frames whose layers it could not show.
TEST(RuntimeSpecRules, HeadlessFramesAcceptLayersTheyCannotShow) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
  XrCompositionLayerProjection projection{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  projection.space = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  projection.viewCount = 0;  // no views at all
  XrCompositionLayerQuad quad{XR_TYPE_COMPOSITION_LAYER_QUAD};
  quad.space = projection.space;  // and a null swapchain
  const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&projection),
                                                  reinterpret_cast<const XrCompositionLayerBaseHeader*>(&quad)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = fs.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.layerCount = 2;
  end.layers = layers;
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
  // The frame rules themselves still hold: no second xrEndFrame without xrBeginFrame.
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_ERROR_CALL_ORDER_INVALID);
  hs.destroy();
}

TEST(RuntimeSpecRules, CoreProfilesAndStrictBindingPaths) {
  use_runtime(5.0);
  const XrInstance inst = create_instance({});
  ASSERT_NE(inst, XR_NULL_HANDLE);
  const XrActionSet set = make_set(inst, "set", 0);
  const XrAction b = make_action(set, "b", XR_ACTION_TYPE_BOOLEAN_INPUT);
  const XrAction v = make_action(set, "v", XR_ACTION_TYPE_VECTOR2F_INPUT);
  const XrAction h = make_action(set, "h", XR_ACTION_TYPE_VIBRATION_OUTPUT);
  // The four core 1.0 profiles that were missing.
  EXPECT_EQ(suggest(inst, "/interaction_profiles/google/daydream_controller",
                    {{v, path(inst, "/user/hand/right/input/trackpad")},
                     {b, path(inst, "/user/hand/left/input/select/click")}}),
            XR_SUCCESS);
  EXPECT_EQ(suggest(inst, "/interaction_profiles/htc/vive_pro", {{b, path(inst, "/user/head/input/mute_mic/click")}}),
            XR_SUCCESS);
  EXPECT_EQ(suggest(inst, "/interaction_profiles/microsoft/xbox_controller",
                    {{v, path(inst, "/user/gamepad/input/thumbstick_left")},
                     {h, path(inst, "/user/gamepad/output/haptic_right_trigger")}}),
            XR_SUCCESS);
  EXPECT_EQ(suggest(inst, "/interaction_profiles/oculus/go_controller",
                    {{b, path(inst, "/user/hand/left/input/back/click")}}),
            XR_SUCCESS);
  // An identifier without its component is a binding; "input" alone or a path past a component is not.
  const char* simple = "/interaction_profiles/khr/simple_controller";
  EXPECT_EQ(suggest(inst, simple, {{b, path(inst, "/user/hand/left/input/select")}}), XR_SUCCESS);
  for (const char* bad :
       {"/user/hand/right/input", "/user/hand/right/output", "/user/hand/right/input/select/click/invalid",
        "/user/hand/left/input_bad/menu/click", "/user/head/input/select/click"})
    EXPECT_EQ(suggest(inst, simple, {{b, path(inst, bad)}}), XR_ERROR_PATH_UNSUPPORTED) << bad;
  // /user/eyes_ext is a user path only with XR_EXT_eye_gaze_interaction enabled.
  XrActionCreateInfo eyes_action{XR_TYPE_ACTION_CREATE_INFO};
  eyes_action.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(eyes_action.actionName, "gaze");
  std::strcpy(eyes_action.localizedActionName, "gaze");
  const XrPath eyes = path(inst, "/user/eyes_ext");
  eyes_action.countSubactionPaths = 1;
  eyes_action.subactionPaths = &eyes;
  XrAction refused = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateAction(set, &eyes_action, &refused), XR_ERROR_PATH_UNSUPPORTED);
  xrDestroyInstance(inst);
}

// One session with a left controller switched on through XR_EXT_conformance_automation.
struct ControllerRig {
  HeadlessSession hs;
  XrPath left = XR_NULL_PATH, right = XR_NULL_PATH, simple = XR_NULL_PATH;

  void create() {
    ASSERT_NO_FATAL_FAILURE(hs.create({XR_EXT_CONFORMANCE_AUTOMATION_EXTENSION_NAME}));
    left = path(hs.instance, "/user/hand/left");
    right = path(hs.instance, "/user/hand/right");
    simple = path(hs.instance, "/interaction_profiles/khr/simple_controller");
  }
  void start(const std::vector<XrActionSet>& sets) {
    ASSERT_NO_FATAL_FAILURE(attach(hs.session, sets));
    ASSERT_NO_FATAL_FAILURE(hs.begin());
    auto set_active = proc<PFN_xrSetInputDeviceActiveEXT>(hs.instance, "xrSetInputDeviceActiveEXT");
    ASSERT_EQ(set_active(hs.session, simple, left, XR_TRUE), XR_SUCCESS);
  }
};

// A source bound in several active sets feeds only the highest-priority ones (section 11.5.1);
// an action keeps the sources no higher set binds.
TEST(RuntimeSpecRules, ActionSetPriorityDecidesWhoGetsASource) {
  use_runtime(5.0);
  ControllerRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  const XrInstance inst = rig.hs.instance;
  const XrActionSet high = make_set(inst, "high", 2), low = make_set(inst, "low", 1);
  const XrAction high_select = make_action(high, "high_select", XR_ACTION_TYPE_BOOLEAN_INPUT);
  const XrAction low_select = make_action(low, "low_select", XR_ACTION_TYPE_BOOLEAN_INPUT);
  const XrAction low_both = make_action(low, "low_both", XR_ACTION_TYPE_BOOLEAN_INPUT);
  const XrPath select = path(inst, "/user/hand/left/input/select/click");
  const XrPath menu = path(inst, "/user/hand/left/input/menu/click");
  ASSERT_EQ(suggest(inst, "/interaction_profiles/khr/simple_controller",
                    {{high_select, select}, {low_select, select}, {low_both, select}, {low_both, menu}}),
            XR_SUCCESS);
  ASSERT_NO_FATAL_FAILURE(rig.start({high, low}));
  ASSERT_EQ(sync(rig.hs.session, {{low, XR_NULL_PATH}, {high, XR_NULL_PATH}}), XR_SUCCESS);
  EXPECT_TRUE(active(rig.hs.session, high_select, XR_ACTION_TYPE_BOOLEAN_INPUT));
  EXPECT_FALSE(active(rig.hs.session, low_select, XR_ACTION_TYPE_BOOLEAN_INPUT)) << "blocked by the higher set";
  EXPECT_TRUE(active(rig.hs.session, low_both, XR_ACTION_TYPE_BOOLEAN_INPUT)) << "still has the menu button";
  // Without the higher set, the lower one gets the source back.
  ASSERT_EQ(sync(rig.hs.session, {{low, XR_NULL_PATH}}), XR_SUCCESS);
  EXPECT_TRUE(active(rig.hs.session, low_select, XR_ACTION_TYPE_BOOLEAN_INPUT));
  rig.hs.destroy();
}

TEST(RuntimeSpecRules, SyncRefusesASubactionPathNoActionDeclares) {
  use_runtime(5.0);
  ControllerRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  const XrInstance inst = rig.hs.instance;
  const XrActionSet set = make_set(inst, "set", 0);
  make_action(set, "left_only", XR_ACTION_TYPE_BOOLEAN_INPUT, {rig.left});
  ASSERT_NO_FATAL_FAILURE(rig.start({set}));
  EXPECT_EQ(sync(rig.hs.session, {{set, rig.left}}), XR_SUCCESS);
  EXPECT_EQ(sync(rig.hs.session, {{set, rig.right}}), XR_ERROR_PATH_UNSUPPORTED);
  rig.hs.destroy();
}

// Boolean and float sources convert into each other; no other pairing feeds an action.
TEST(RuntimeSpecRules, ImpossibleTypeConversionsLeaveTheActionInactive) {
  use_runtime(5.0);
  ControllerRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  const XrInstance inst = rig.hs.instance;
  const XrActionSet set = make_set(inst, "set", 0);
  const XrAction as_float = make_action(set, "as_float", XR_ACTION_TYPE_FLOAT_INPUT);
  const XrAction as_vector = make_action(set, "as_vector", XR_ACTION_TYPE_VECTOR2F_INPUT);
  const XrAction as_pose = make_action(set, "as_pose", XR_ACTION_TYPE_POSE_INPUT);
  const XrAction grip_as_bool = make_action(set, "grip_as_bool", XR_ACTION_TYPE_BOOLEAN_INPUT);
  const XrPath select = path(inst, "/user/hand/left/input/select/click");
  ASSERT_EQ(suggest(inst, "/interaction_profiles/khr/simple_controller",
                    {{as_float, select},
                     {as_vector, select},
                     {as_pose, select},
                     {grip_as_bool, path(inst, "/user/hand/left/input/grip/pose")}}),
            XR_SUCCESS);
  ASSERT_NO_FATAL_FAILURE(rig.start({set}));
  ASSERT_EQ(sync(rig.hs.session, {{set, XR_NULL_PATH}}), XR_SUCCESS);
  EXPECT_TRUE(active(rig.hs.session, as_float, XR_ACTION_TYPE_FLOAT_INPUT));
  EXPECT_FALSE(active(rig.hs.session, as_vector, XR_ACTION_TYPE_VECTOR2F_INPUT));
  EXPECT_FALSE(active(rig.hs.session, as_pose, XR_ACTION_TYPE_POSE_INPUT));
  EXPECT_FALSE(active(rig.hs.session, grip_as_bool, XR_ACTION_TYPE_BOOLEAN_INPUT));
  rig.hs.destroy();
}

// An activated controller is tracked at a resting pose until a test places it (the CTS waits
// for it to become locatable); switched off, it is not located at all.
TEST(RuntimeSpecRules, ActivatedControllerIsLocatableAtARestingPose) {
  use_runtime(5.0);
  ControllerRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  const XrInstance inst = rig.hs.instance;
  const XrActionSet set = make_set(inst, "set", 0);
  const XrAction grip = make_action(set, "grip", XR_ACTION_TYPE_POSE_INPUT, {rig.left});
  ASSERT_EQ(suggest(inst, "/interaction_profiles/khr/simple_controller",
                    {{grip, path(inst, "/user/hand/left/input/grip/pose")}}),
            XR_SUCCESS);
  XrActionSpaceCreateInfo asci{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  asci.action = grip;
  asci.subactionPath = rig.left;
  asci.poseInActionSpace.orientation.w = 1.0f;
  XrSpace grip_space = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSpace(rig.hs.session, &asci, &grip_space), XR_SUCCESS);
  const XrSpace local = rig.hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  ASSERT_NO_FATAL_FAILURE(rig.start({set}));
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  ASSERT_EQ(xrLocateSpace(grip_space, local, 2'000'000'000, &loc), XR_SUCCESS);
  EXPECT_EQ(loc.locationFlags, 0u) << "not current before the next xrSyncActions";
  ASSERT_EQ(sync(rig.hs.session, {{set, XR_NULL_PATH}}), XR_SUCCESS);
  ASSERT_EQ(xrLocateSpace(grip_space, local, 2'000'000'000, &loc), XR_SUCCESS);
  const XrSpaceLocationFlags tracked = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT |
                                       XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
                                       XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  EXPECT_EQ(loc.locationFlags & tracked, tracked);
  EXPECT_LT(loc.pose.position.x, 0.0f) << "the left hand rests left of the eyes";
  EXPECT_LT(loc.pose.position.z, 0.0f) << "and in front";
  rig.hs.destroy();
}

// An action space without a subaction path follows the first device it was located through,
// loses tracking at once when that device is switched off (its profile changes only at the next
// sync), and stays locatable through it after its action is destroyed (what the CTS expects).
TEST(RuntimeSpecRules, ActionSpacesFollowOneDeviceAndOutliveTheirAction) {
  use_runtime(5.0);
  ControllerRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  const XrInstance inst = rig.hs.instance;
  const XrActionSet set = make_set(inst, "set", 0);
  const XrAction grip = make_action(set, "grip", XR_ACTION_TYPE_POSE_INPUT, {rig.left, rig.right});
  ASSERT_EQ(suggest(inst, "/interaction_profiles/khr/simple_controller",
                    {{grip, path(inst, "/user/hand/left/input/grip/pose")},
                     {grip, path(inst, "/user/hand/right/input/grip/pose")}}),
            XR_SUCCESS);
  XrActionSpaceCreateInfo asci{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  asci.action = grip;
  asci.poseInActionSpace.orientation.w = 1.0f;
  XrSpace either = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSpace(rig.hs.session, &asci, &either), XR_SUCCESS);
  const XrSpace local = rig.hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  ASSERT_NO_FATAL_FAILURE(rig.start({set}));  // the left controller on
  auto set_active = proc<PFN_xrSetInputDeviceActiveEXT>(inst, "xrSetInputDeviceActiveEXT");
  const std::vector<XrActiveActionSet> both{{set, rig.left}, {set, rig.right}};
  ASSERT_EQ(sync(rig.hs.session, both), XR_SUCCESS);
  const auto located = [&] {
    XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
    EXPECT_EQ(xrLocateSpace(either, local, 2'000'000'000, &loc), XR_SUCCESS);
    return (loc.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT) != 0;
  };
  EXPECT_TRUE(located()) << "through the left hand";
  ASSERT_EQ(set_active(rig.hs.session, rig.simple, rig.right, XR_TRUE), XR_SUCCESS);
  ASSERT_EQ(set_active(rig.hs.session, rig.simple, rig.left, XR_FALSE), XR_SUCCESS);
  EXPECT_FALSE(located()) << "the left hand is off now, before any sync";
  ASSERT_EQ(sync(rig.hs.session, both), XR_SUCCESS);
  EXPECT_FALSE(located()) << "still following the left hand, not the right";
  ASSERT_EQ(set_active(rig.hs.session, rig.simple, rig.left, XR_TRUE), XR_SUCCESS);
  ASSERT_EQ(sync(rig.hs.session, both), XR_SUCCESS);
  EXPECT_TRUE(located());
  ASSERT_EQ(xrDestroyAction(grip), XR_SUCCESS);
  EXPECT_TRUE(located()) << "the space outlives its action";
  EXPECT_EQ(sync(rig.hs.session, both), XR_SUCCESS) << "the destroyed action's subaction paths stay declared";
  EXPECT_TRUE(located());
  rig.hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
