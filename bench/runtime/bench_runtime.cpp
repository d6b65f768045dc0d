// SPDX-License-Identifier: Apache-2.0
// Frames per second of the unpaced headless simulated runtime, driven through the Khronos
// loader by a trivial client: the bare frame loop, and the loop with the gaze work a
// gaze-contingent client does each frame (sync actions, locate gaze and head). Baseline in the
// same process: one empty xrPollEvent through the loader.
#include <openxr/openxr.h>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

struct Client {
  XrInstance instance = XR_NULL_HANDLE;
  XrSession session = XR_NULL_HANDLE;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction gaze = XR_NULL_HANDLE;
  XrSpace gaze_space = XR_NULL_HANDLE, view = XR_NULL_HANDLE, local = XR_NULL_HANDLE;
  bool ok = false;

  Client() {
    setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
    setenv("GAZELOD_SIM_PACED", "0", 1);
    setenv("GAZELOD_SIM_DURATION_S", "1000000", 1);  // never ends during a benchmark
    const char* ext[] = {XR_MND_HEADLESS_EXTENSION_NAME, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME};
    XrInstanceCreateInfo ci{XR_TYPE_INSTANCE_CREATE_INFO};
    std::strcpy(ci.applicationInfo.applicationName, "bench_runtime");
    ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    ci.enabledExtensionCount = 2;
    ci.enabledExtensionNames = ext;
    if (xrCreateInstance(&ci, &instance) != XR_SUCCESS) return;
    XrSystemGetInfo sgi{XR_TYPE_SYSTEM_GET_INFO};
    sgi.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    if (xrGetSystem(instance, &sgi, &system) != XR_SUCCESS) return;
    XrSessionCreateInfo sci{XR_TYPE_SESSION_CREATE_INFO};
    sci.systemId = system;
    if (xrCreateSession(instance, &sci, &session) != XR_SUCCESS) return;
    XrActionSetCreateInfo asi{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::strcpy(asi.actionSetName, "gaze");
    std::strcpy(asi.localizedActionSetName, "Gaze");
    xrCreateActionSet(instance, &asi, &set);
    XrActionCreateInfo aci{XR_TYPE_ACTION_CREATE_INFO};
    aci.actionType = XR_ACTION_TYPE_POSE_INPUT;
    std::strcpy(aci.actionName, "gaze");
    std::strcpy(aci.localizedActionName, "Gaze");
    xrCreateAction(set, &aci, &gaze);
    XrPath profile = XR_NULL_PATH, binding = XR_NULL_PATH;
    xrStringToPath(instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile);
    xrStringToPath(instance, "/user/eyes_ext/input/gaze_ext/pose", &binding);
    const XrActionSuggestedBinding b{gaze, binding};
    XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    sb.interactionProfile = profile;
    sb.countSuggestedBindings = 1;
    sb.suggestedBindings = &b;
    if (xrSuggestInteractionProfileBindings(instance, &sb) != XR_SUCCESS) return;
    XrSessionActionSetsAttachInfo at{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    at.countActionSets = 1;
    at.actionSets = &set;
    if (xrAttachSessionActionSets(session, &at) != XR_SUCCESS) return;
    XrActionSpaceCreateInfo as{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    as.action = gaze;
    as.poseInActionSpace.orientation.w = 1.0f;
    xrCreateActionSpace(session, &as, &gaze_space);
    XrReferenceSpaceCreateInfo rs{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    rs.poseInReferenceSpace.orientation.w = 1.0f;
    rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    xrCreateReferenceSpace(session, &rs, &view);
    rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    xrCreateReferenceSpace(session, &rs, &local);
    XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
    bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    if (xrBeginSession(session, &bi) != XR_SUCCESS) return;
    drain();
    ok = true;
  }
  ~Client() {
    if (session != XR_NULL_HANDLE) xrDestroySession(session);
    if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
  }
  void drain() {
    XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(instance, &e) == XR_SUCCESS) e = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  std::int64_t frames_not_rendered = 0;  // must stay 0: the session is still focused
  XrTime frame() {
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    if (xrWaitFrame(session, nullptr, &fs) != XR_SUCCESS || !fs.shouldRender) ++frames_not_rendered;
    xrBeginFrame(session, nullptr);
    XrFrameEndInfo fe{XR_TYPE_FRAME_END_INFO};
    fe.displayTime = fs.predictedDisplayTime;
    fe.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    xrEndFrame(session, &fe);
    return fs.predictedDisplayTime;
  }
};

Client& client() {
  static Client c;
  return c;
}

void BM_EmptyPollEvent(benchmark::State& state) {  // baseline: one loader call
  Client& c = client();
  if (!c.ok) return state.SkipWithError("runtime not available");
  XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
  for (auto _ : state) {
    e.type = XR_TYPE_EVENT_DATA_BUFFER;
    benchmark::DoNotOptimize(xrPollEvent(c.instance, &e));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EmptyPollEvent);

void BM_FrameLoop(benchmark::State& state) {  // wait + begin + end, no layers
  Client& c = client();
  if (!c.ok) return state.SkipWithError("runtime not available");
  for (auto _ : state) benchmark::DoNotOptimize(c.frame());
  c.drain();
  if (c.frames_not_rendered != 0) state.SkipWithError("the session left FOCUSED during the run");
  state.SetItemsProcessed(state.iterations());  // items/s = frames per second
}
// Fixed counts keep the simulated time (11 ms a frame at 90 Hz) inside the scenario.
BENCHMARK(BM_FrameLoop)->Iterations(2'000'000);

void BM_FrameLoopWithGaze(benchmark::State& state) {  // + sync, locate gaze and head
  Client& c = client();
  if (!c.ok) return state.SkipWithError("runtime not available");
  const XrActiveActionSet active{c.set, XR_NULL_PATH};
  XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  std::int64_t tracked = 0;
  for (auto _ : state) {
    const XrTime t = c.frame();
    xrSyncActions(c.session, &sync);
    XrEyeGazeSampleTimeEXT st{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
    XrSpaceLocation gaze{XR_TYPE_SPACE_LOCATION, &st};
    xrLocateSpace(c.gaze_space, c.view, t, &gaze);
    XrSpaceVelocity vel{XR_TYPE_SPACE_VELOCITY};
    XrSpaceLocation head{XR_TYPE_SPACE_LOCATION, &vel};
    xrLocateSpace(c.view, c.local, t, &head);
    tracked += (gaze.locationFlags & XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT) != 0;
  }
  c.drain();
  if (c.frames_not_rendered != 0) state.SkipWithError("the session left FOCUSED during the run");
  state.counters["gaze_tracked_fraction"] = double(tracked) / double(std::max<std::int64_t>(1, state.iterations()));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FrameLoopWithGaze)->Iterations(300'000);

}  // namespace

BENCHMARK_MAIN();
