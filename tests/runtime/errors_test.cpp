// SPDX-License-Identifier: Apache-2.0
// Error paths get the specification's codes: calls in the wrong session state, invalid or
// destroyed handles, unsupported extensions, form factors, view configurations and paths.
// Handle checks are also exercised on the runtime directly (dlopen + negotiation), since the
// loader screens unknown handles before they reach a runtime.
#include "sim/runtime/xr_headers.hpp"
#include "tests/runtime/xr_client.hpp"
#include "xr/loader_negotiation.hpp"

#include <dlfcn.h>

#include <cstring>
#include <cstdlib>
#include <vector>

namespace gazelod::xrrt_test {
namespace {

void fill_action_set(XrActionSetCreateInfo& info, const char* name) {
  info = {XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(info.actionSetName, name);
  std::strcpy(info.localizedActionSetName, name);
}

TEST(RuntimeErrors, SessionStateRules) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.displayTime = 2'000'000'000;
  // Not running yet.
  EXPECT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(xrBeginFrame(hs.session, nullptr), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(xrEndSession(hs.session), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(xrRequestExitSession(hs.session), XR_ERROR_SESSION_NOT_RUNNING);
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO;
  EXPECT_EQ(xrBeginSession(hs.session, &begin), XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  EXPECT_EQ(xrBeginSession(hs.session, &begin), XR_ERROR_SESSION_RUNNING);
  // Frame calls out of order.
  EXPECT_EQ(xrBeginFrame(hs.session, nullptr), XR_ERROR_CALL_ORDER_INVALID);
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_ERROR_CALL_ORDER_INVALID);
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_ERROR_CALL_ORDER_INVALID);
  ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
  end.displayTime = fs.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_ADDITIVE;
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED);
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
  // A second begin without a wait, and a begin over a begun frame (discarded).
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  EXPECT_EQ(xrBeginFrame(hs.session, nullptr), XR_FRAME_DISCARDED);
  // Ending while focused is not allowed; request exit walks down to STOPPING.
  EXPECT_EQ(xrEndSession(hs.session), XR_ERROR_SESSION_NOT_STOPPING);
  hs.pump();
  EXPECT_EQ(xrRequestExitSession(hs.session), XR_SUCCESS);
  hs.pump();
  ASSERT_GE(hs.states.size(), 3u);
  EXPECT_EQ(hs.states.back(), XR_SESSION_STATE_STOPPING);
  EXPECT_EQ(xrEndSession(hs.session), XR_SUCCESS);
  hs.pump();
  ASSERT_GE(hs.states.size(), 2u);
  EXPECT_EQ(hs.states[hs.states.size() - 2], XR_SESSION_STATE_IDLE);
  EXPECT_EQ(hs.states.back(), XR_SESSION_STATE_EXITING);
  EXPECT_EQ(xrEndSession(hs.session), XR_ERROR_SESSION_NOT_RUNNING);
  hs.destroy();
}

TEST(RuntimeErrors, LifecycleStatesInSpecOrder) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  const std::vector<XrSessionState> want = {XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY,
                                            XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE,
                                            XR_SESSION_STATE_FOCUSED};
  EXPECT_EQ(hs.states, want);
  hs.destroy();
}

TEST(RuntimeErrors, ScenarioEndMovesSessionToStoppingThenExiting) {
  use_runtime(0.25);  // 0.25 s at the display rate, unpaced
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  int frames = 0;
  XrTime last = 0;
  while (hs.states.back() != XR_SESSION_STATE_STOPPING && frames < 10'000) {
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
    if (last != 0) {
      EXPECT_EQ(fs.predictedDisplayTime - last, fs.predictedDisplayPeriod);
    }
    last = fs.predictedDisplayTime;
    ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = fs.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ASSERT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
    hs.pump();
    ++frames;
  }
  // The scenario ends once the predicted display time reaches 0.25 s past the time base.
  EXPECT_GE(last - 1'000'000'000, 250'000'000);
  EXPECT_LT(last - 1'000'000'000, 250'000'000 + 2 * 20'000'000);
  EXPECT_EQ(hs.states.back(), XR_SESSION_STATE_STOPPING);
  ASSERT_EQ(xrEndSession(hs.session), XR_SUCCESS);
  hs.pump();
  EXPECT_EQ(hs.states.back(), XR_SESSION_STATE_EXITING);
  hs.destroy();
}

TEST(RuntimeErrors, UnsupportedExtensionsFormFactorsAndViews) {
  use_runtime(5.0);
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "errors");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  const char* bogus[] = {"XR_GAZELOD_no_such_extension"};
  info.enabledExtensionCount = 1;
  info.enabledExtensionNames = bogus;
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_EXTENSION_NOT_PRESENT);

  instance = create_instance({});
  ASSERT_NE(instance, XR_NULL_HANDLE);
  // Extension commands of extensions not enabled.
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrSetInputDeviceActiveEXT", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(xrGetInstanceProcAddr(instance, "xrCreateVulkanInstanceKHR", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  // Eye gaze profile without its extension.
  XrPath profile = XR_NULL_PATH;
  ASSERT_EQ(xrStringToPath(instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile), XR_SUCCESS);
  XrActionSetCreateInfo set_info;
  fill_action_set(set_info, "set");
  XrActionSet set = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSet(instance, &set_info, &set), XR_SUCCESS);
  XrActionCreateInfo action_info{XR_TYPE_ACTION_CREATE_INFO};
  action_info.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(action_info.actionName, "pose");
  std::strcpy(action_info.localizedActionName, "Pose");
  XrAction action = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateAction(set, &action_info, &action), XR_SUCCESS);
  XrPath gaze_path = XR_NULL_PATH;
  ASSERT_EQ(xrStringToPath(instance, "/user/eyes_ext/input/gaze_ext/pose", &gaze_path), XR_SUCCESS);
  XrActionSuggestedBinding b{action, gaze_path};
  XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sb.interactionProfile = profile;
  sb.countSuggestedBindings = 1;
  sb.suggestedBindings = &b;
  EXPECT_EQ(xrSuggestInteractionProfileBindings(instance, &sb), XR_ERROR_PATH_UNSUPPORTED);
  // A known profile with a path it does not have.
  ASSERT_EQ(xrStringToPath(instance, "/interaction_profiles/khr/simple_controller", &sb.interactionProfile),
            XR_SUCCESS);
  ASSERT_EQ(xrStringToPath(instance, "/user/hand/left/input/trigger/value", &b.binding), XR_SUCCESS);
  EXPECT_EQ(xrSuggestInteractionProfileBindings(instance, &sb), XR_ERROR_PATH_UNSUPPORTED);
  ASSERT_EQ(xrStringToPath(instance, "/user/hand/left/input/grip/pose", &b.binding), XR_SUCCESS);
  EXPECT_EQ(xrSuggestInteractionProfileBindings(instance, &sb), XR_SUCCESS);
  // Paths.
  XrPath p = XR_NULL_PATH;
  EXPECT_EQ(xrStringToPath(instance, "/User/Bad", &p), XR_ERROR_PATH_FORMAT_INVALID);
  EXPECT_EQ(xrStringToPath(instance, "/user//hand", &p), XR_ERROR_PATH_FORMAT_INVALID);
  EXPECT_EQ(xrStringToPath(instance, "/user/hand/", &p), XR_ERROR_PATH_FORMAT_INVALID);
  uint32_t n = 0;
  EXPECT_EQ(xrPathToString(instance, 987654, 0, &n, nullptr), XR_ERROR_PATH_INVALID);
  char small[4];
  EXPECT_EQ(xrPathToString(instance, profile, sizeof small, &n, small), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(n, std::strlen("/interaction_profiles/ext/eye_gaze_interaction") + 1);
  // Form factor, system and view configurations.
  XrSystemGetInfo sys{XR_TYPE_SYSTEM_GET_INFO};
  sys.formFactor = XR_FORM_FACTOR_HANDHELD_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  EXPECT_EQ(xrGetSystem(instance, &sys, &system), XR_ERROR_FORM_FACTOR_UNSUPPORTED);
  sys.formFactor = XR_FORM_FACTOR_MAX_ENUM;  // not a form factor at all: still unsupported (CTS)
  EXPECT_EQ(xrGetSystem(instance, &sys, &system), XR_ERROR_FORM_FACTOR_UNSUPPORTED);
  system = get_system(instance);
  uint32_t count = 0;
  EXPECT_EQ(
      xrEnumerateViewConfigurationViews(instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO, 0, &count, nullptr),
      XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
  EXPECT_EQ(
      xrEnumerateEnvironmentBlendModes(instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO, 0, &count, nullptr),
      XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
  EXPECT_EQ(xrEnumerateViewConfigurationViews(instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &count,
                                              nullptr),
            XR_SUCCESS);
  EXPECT_EQ(count, 2u);
  XrViewConfigurationView one{XR_TYPE_VIEW_CONFIGURATION_VIEW};
  EXPECT_EQ(
      xrEnumerateViewConfigurationViews(instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 1, &count, &one),
      XR_ERROR_SIZE_INSUFFICIENT);
  // A session needs a graphics binding unless XR_MND_headless is enabled.
  XrSessionCreateInfo si{XR_TYPE_SESSION_CREATE_INFO};
  si.systemId = system;
  XrSession session = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateSession(instance, &si, &session), XR_ERROR_GRAPHICS_DEVICE_INVALID);
  EXPECT_EQ(xrDestroyInstance(instance), XR_SUCCESS);
}

// GAZELOD_SIM_EYE_GAZE_EXTENSION=0: a runtime without eye gaze, as the eye-gaze layer meets it.
TEST(RuntimeErrors, EyeGazeExtensionCanBeHidden) {
  use_runtime(5.0);
  const auto listed = [] {
    std::uint32_t n = 0;
    EXPECT_EQ(xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr), XR_SUCCESS);
    std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES});
    EXPECT_EQ(xrEnumerateInstanceExtensionProperties(nullptr, n, &n, props.data()), XR_SUCCESS);
    for (const auto& p : props)
      if (std::strcmp(p.extensionName, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME) == 0) return true;
    return false;
  };
  EXPECT_TRUE(listed());
  setenv("GAZELOD_SIM_EYE_GAZE_EXTENSION", "0", 1);
  EXPECT_FALSE(listed());
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "errors");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  const char* eye[] = {XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME};
  info.enabledExtensionCount = 1;
  info.enabledExtensionNames = eye;
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_EXTENSION_NOT_PRESENT);
  unsetenv("GAZELOD_SIM_EYE_GAZE_EXTENSION");
  EXPECT_TRUE(listed());
}

TEST(RuntimeErrors, ActionSystemRules) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  XrActionSetCreateInfo set_info;
  fill_action_set(set_info, "main");
  XrActionSet set = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSet(hs.instance, &set_info, &set), XR_SUCCESS);
  XrActionSet dup = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateActionSet(hs.instance, &set_info, &dup), XR_ERROR_NAME_DUPLICATED);
  fill_action_set(set_info, "Bad Name");
  EXPECT_EQ(xrCreateActionSet(hs.instance, &set_info, &dup), XR_ERROR_PATH_FORMAT_INVALID);
  XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
  ai.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
  std::strcpy(ai.actionName, "select");
  std::strcpy(ai.localizedActionName, "Select");
  XrPath bad_subaction = XR_NULL_PATH;
  ASSERT_EQ(xrStringToPath(hs.instance, "/user/hand/left/input", &bad_subaction), XR_SUCCESS);
  ai.countSubactionPaths = 1;
  ai.subactionPaths = &bad_subaction;
  XrAction action = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateAction(set, &ai, &action), XR_ERROR_PATH_UNSUPPORTED);
  ai.countSubactionPaths = 0;
  ai.subactionPaths = nullptr;
  ASSERT_EQ(xrCreateAction(set, &ai, &action), XR_SUCCESS);
  // Getting state before attaching.
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = action;
  XrActionStateBoolean bs{XR_TYPE_ACTION_STATE_BOOLEAN};
  EXPECT_EQ(xrGetActionStateBoolean(hs.session, &get, &bs), XR_ERROR_ACTIONSET_NOT_ATTACHED);
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &set;
  ASSERT_EQ(xrAttachSessionActionSets(hs.session, &attach), XR_SUCCESS);
  EXPECT_EQ(xrAttachSessionActionSets(hs.session, &attach), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  std::strcpy(ai.actionName, "late");
  std::strcpy(ai.localizedActionName, "Late");
  XrAction late = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateAction(set, &ai, &late), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  XrActionStatePose ps{XR_TYPE_ACTION_STATE_POSE};
  EXPECT_EQ(xrGetActionStatePose(hs.session, &get, &ps), XR_ERROR_ACTION_TYPE_MISMATCH);
  EXPECT_EQ(xrGetActionStateBoolean(hs.session, &get, &bs), XR_SUCCESS);
  EXPECT_EQ(bs.isActive, XR_FALSE);  // nothing bound
  XrPath left = XR_NULL_PATH;
  ASSERT_EQ(xrStringToPath(hs.instance, "/user/hand/left", &left), XR_SUCCESS);
  get.subactionPath = left;  // not one of the action's subaction paths
  EXPECT_EQ(xrGetActionStateBoolean(hs.session, &get, &bs), XR_ERROR_PATH_UNSUPPORTED);
  // Syncing before the session is focused.
  const XrActiveActionSet active{set, XR_NULL_PATH};
  XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  EXPECT_EQ(xrSyncActions(hs.session, &sync), XR_SESSION_NOT_FOCUSED);
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  EXPECT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
  // Locating at an invalid time.
  const XrSpace local = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  EXPECT_EQ(xrLocateSpace(local, local, 0, &loc), XR_ERROR_TIME_INVALID);
  XrReferenceSpaceCreateInfo rs{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_UNBOUNDED_MSFT;
  rs.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace space = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateReferenceSpace(hs.session, &rs, &space), XR_ERROR_REFERENCE_SPACE_UNSUPPORTED);
  rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  rs.poseInReferenceSpace.orientation.w = 2.0f;
  EXPECT_EQ(xrCreateReferenceSpace(hs.session, &rs, &space), XR_ERROR_POSE_INVALID);
  // A headless session has no swapchain format.
  uint32_t formats = 99;
  EXPECT_EQ(xrEnumerateSwapchainFormats(hs.session, 0, &formats, nullptr), XR_SUCCESS);
  EXPECT_EQ(formats, 0u);
  hs.destroy();
}

// The runtime's own handle checks, called without the loader in between.
struct DirectRuntime {
  void* lib = nullptr;
  PFN_xrGetInstanceProcAddr gipa = nullptr;
  template <class PFN>
  PFN get(XrInstance instance, const char* name) {
    PFN_xrVoidFunction fn = nullptr;
    EXPECT_EQ(gipa(instance, name, &fn), XR_SUCCESS) << name;
    return reinterpret_cast<PFN>(fn);
  }
};

TEST(RuntimeErrors, InvalidAndDestroyedHandlesDirect) {
  use_runtime(5.0);
  DirectRuntime rt;
  rt.lib = dlopen(GAZELOD_XR_RUNTIME_LIB, RTLD_NOW | RTLD_LOCAL);
  ASSERT_NE(rt.lib, nullptr) << dlerror();
  using Negotiate = XrResult (*)(const xr::XrNegotiateLoaderInfo*, xr::XrNegotiateRuntimeRequest*);
  auto negotiate = reinterpret_cast<Negotiate>(dlsym(rt.lib, "xrNegotiateLoaderRuntimeInterface"));
  ASSERT_NE(negotiate, nullptr);
  xr::XrNegotiateLoaderInfo li{
      xr::XR_LOADER_INTERFACE_STRUCT_LOADER_INFO, 1, sizeof(li), 1, 1, XR_MAKE_VERSION(1, 0, 0),
      XR_MAKE_VERSION(1, 0xffff, 0xffff)};
  xr::XrNegotiateRuntimeRequest rr{xr::XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST, 1, sizeof(rr), 0, 0, nullptr};
  ASSERT_EQ(negotiate(&li, &rr), XR_SUCCESS);
  rt.gipa = rr.getInstanceProcAddr;
  ASSERT_NE(rt.gipa, nullptr);
  // Only the global commands are reachable without an instance.
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(rt.gipa(XR_NULL_HANDLE, "xrGetSystem", &fn), XR_ERROR_HANDLE_INVALID);
  auto create = rt.get<PFN_xrCreateInstance>(XR_NULL_HANDLE, "xrCreateInstance");
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "direct");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  const char* bogus[] = {"XR_GAZELOD_no_such_extension"};
  info.enabledExtensionCount = 1;
  info.enabledExtensionNames = bogus;
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(create(&info, &instance), XR_ERROR_EXTENSION_NOT_PRESENT);
  const char* headless[] = {XR_MND_HEADLESS_EXTENSION_NAME};
  info.enabledExtensionNames = headless;
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(2, 0, 0);
  EXPECT_EQ(create(&info, &instance), XR_ERROR_API_VERSION_UNSUPPORTED);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  ASSERT_EQ(create(&info, &instance), XR_SUCCESS);

  auto get_system = rt.get<PFN_xrGetSystem>(instance, "xrGetSystem");
  auto create_session = rt.get<PFN_xrCreateSession>(instance, "xrCreateSession");
  auto destroy_session = rt.get<PFN_xrDestroySession>(instance, "xrDestroySession");
  auto begin_session = rt.get<PFN_xrBeginSession>(instance, "xrBeginSession");
  auto create_space = rt.get<PFN_xrCreateReferenceSpace>(instance, "xrCreateReferenceSpace");
  auto locate = rt.get<PFN_xrLocateSpace>(instance, "xrLocateSpace");
  auto destroy_instance = rt.get<PFN_xrDestroyInstance>(instance, "xrDestroyInstance");
  auto poll = rt.get<PFN_xrPollEvent>(instance, "xrPollEvent");
  XrSystemGetInfo sys{XR_TYPE_SYSTEM_GET_INFO};
  sys.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  EXPECT_EQ(get_system(reinterpret_cast<XrInstance>(uintptr_t(0xdead)), &sys, &system), XR_ERROR_HANDLE_INVALID);
  ASSERT_EQ(get_system(instance, &sys, &system), XR_SUCCESS);
  XrSessionCreateInfo si{XR_TYPE_SESSION_CREATE_INFO};
  si.systemId = system + 7;
  XrSession session = XR_NULL_HANDLE;
  EXPECT_EQ(create_session(instance, &si, &session), XR_ERROR_SYSTEM_INVALID);
  si.systemId = system;
  ASSERT_EQ(create_session(instance, &si, &session), XR_SUCCESS);
  XrReferenceSpaceCreateInfo rs{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  rs.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace space = XR_NULL_HANDLE;
  ASSERT_EQ(create_space(session, &rs, &space), XR_SUCCESS);
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  EXPECT_EQ(locate(space, space, 2'000'000'000, &loc), XR_SUCCESS);
  EXPECT_EQ(locate(space, reinterpret_cast<XrSpace>(uintptr_t(0xbeef)), 2'000'000'000, &loc), XR_ERROR_HANDLE_INVALID);
  // Destroying the session destroys its spaces; both handles are then invalid.
  ASSERT_EQ(destroy_session(session), XR_SUCCESS);
  EXPECT_EQ(destroy_session(session), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(locate(space, space, 2'000'000'000, &loc), XR_ERROR_HANDLE_INVALID);
  XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
  bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  EXPECT_EQ(begin_session(session, &bi), XR_ERROR_HANDLE_INVALID);
  ASSERT_EQ(destroy_instance(instance), XR_SUCCESS);
  XrEventDataBuffer ev{XR_TYPE_EVENT_DATA_BUFFER};
  EXPECT_EQ(poll(instance, &ev), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(rt.gipa(instance, "xrGetSystem", &fn), XR_ERROR_HANDLE_INVALID);
  dlclose(rt.lib);
}

}  // namespace
}  // namespace gazelod::xrrt_test
