// SPDX-License-Identifier: Apache-2.0
// layer_gaze_client: a small OpenXR application that uses only the eye-gaze interaction
// profile, run through check_xr_run.sh (with the core validation layer) and by the install
// test. Headless; an ordinary event loop (begin on READY, end on STOPPING, quit on EXITING)
// that syncs, reads the gaze action and locates its space in LOCAL with XrEyeGazeSampleTimeEXT
// every frame. Prints the session states as hello_xr does.
//   layer_gaze_client [--write-trace FILE] [--expect-gaze | --expect-no-gaze]
// --write-trace writes a 10 s synthetic trace and points GAZELOD_LAYER_TRACE at it first.
// Exit 0 when the run matched the expectation (gaze located in >= 10 frames with a sample time,
// or never located), 1 otherwise, 2 on bad usage.
#include "gaze/trace_reader.hpp"
#include "gaze/trace_writer.hpp"

#include <openxr/openxr.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <string>

namespace {

const char* state_name(XrSessionState s) {
  switch (s) {
    case XR_SESSION_STATE_IDLE:
      return "XR_SESSION_STATE_IDLE";
    case XR_SESSION_STATE_READY:
      return "XR_SESSION_STATE_READY";
    case XR_SESSION_STATE_SYNCHRONIZED:
      return "XR_SESSION_STATE_SYNCHRONIZED";
    case XR_SESSION_STATE_VISIBLE:
      return "XR_SESSION_STATE_VISIBLE";
    case XR_SESSION_STATE_FOCUSED:
      return "XR_SESSION_STATE_FOCUSED";
    case XR_SESSION_STATE_STOPPING:
      return "XR_SESSION_STATE_STOPPING";
    case XR_SESSION_STATE_LOSS_PENDING:
      return "XR_SESSION_STATE_LOSS_PENDING";
    case XR_SESSION_STATE_EXITING:
      return "XR_SESSION_STATE_EXITING";
    default:
      return "XR_SESSION_STATE_UNKNOWN";
  }
}

bool ok(XrResult r, const char* call) {
  if (XR_SUCCEEDED(r)) return true;
  std::fprintf(stderr, "layer_gaze_client: %s failed: %d\n", call, static_cast<int>(r));
  return false;
}

void write_trace(const std::string& path) {
  std::ofstream out(path);
  gazelod::gaze::TraceWriterOptions o;
  o.write_head = false;
  gazelod::gaze::TraceWriter w(out, o);
  for (int i = 0; i < 2000; ++i) {  // 10 s at 200 Hz
    gazelod::gaze::TraceRecord r;
    const double t = i / 200.0;
    r.gaze.t_ns = static_cast<std::int64_t>(std::llround(t * 1e9));
    r.gaze.direction =
        gazelod::gaze::direction_from_yaw_pitch_deg(6.0 * std::sin(2.0 * std::numbers::pi * 0.4 * t), 2.0);
    r.gaze.valid = true;
    r.gaze.confidence = 1.0f;
    w.write(r);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // lines in order with the runtime's and layers' stderr
  int expect = 1;                            // 1 gaze, 0 no gaze
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--write-trace" && i + 1 < argc) {
      write_trace(argv[++i]);
      setenv("GAZELOD_LAYER_TRACE", argv[i], 1);
    } else if (a == "--expect-gaze") {
      expect = 1;
    } else if (a == "--expect-no-gaze") {
      expect = 0;
    } else {
      std::fprintf(stderr, "usage: layer_gaze_client [--write-trace FILE] [--expect-gaze | --expect-no-gaze]\n");
      return 2;
    }
  }
  const char* extensions[] = {XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME, XR_MND_HEADLESS_EXTENSION_NAME};
  XrInstanceCreateInfo ci{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(ci.applicationInfo.applicationName, "layer_gaze_client");
  ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  ci.enabledExtensionCount = 2;
  ci.enabledExtensionNames = extensions;
  XrInstance instance = XR_NULL_HANDLE;
  if (!ok(xrCreateInstance(&ci, &instance), "xrCreateInstance")) return 1;
  XrSystemGetInfo sgi{XR_TYPE_SYSTEM_GET_INFO};
  sgi.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  if (!ok(xrGetSystem(instance, &sgi, &system), "xrGetSystem")) return 1;
  XrSystemEyeGazeInteractionPropertiesEXT eye{XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
  XrSystemProperties props{XR_TYPE_SYSTEM_PROPERTIES, &eye};
  if (!ok(xrGetSystemProperties(instance, system, &props), "xrGetSystemProperties")) return 1;
  std::printf("supportsEyeGazeInteraction %s\n", eye.supportsEyeGazeInteraction ? "true" : "false");

  XrActionSetCreateInfo asi{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(asi.actionSetName, "gaze");
  std::strcpy(asi.localizedActionSetName, "Gaze");
  XrActionSet set = XR_NULL_HANDLE;
  if (!ok(xrCreateActionSet(instance, &asi, &set), "xrCreateActionSet")) return 1;
  XrActionCreateInfo aci{XR_TYPE_ACTION_CREATE_INFO};
  aci.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(aci.actionName, "gaze_pose");
  std::strcpy(aci.localizedActionName, "Gaze pose");
  XrAction action = XR_NULL_HANDLE;
  if (!ok(xrCreateAction(set, &aci, &action), "xrCreateAction")) return 1;
  XrPath profile = XR_NULL_PATH, binding = XR_NULL_PATH;
  xrStringToPath(instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile);
  xrStringToPath(instance, "/user/eyes_ext/input/gaze_ext/pose", &binding);
  const XrActionSuggestedBinding b{action, binding};
  XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sb.interactionProfile = profile;
  sb.countSuggestedBindings = 1;
  sb.suggestedBindings = &b;
  if (!ok(xrSuggestInteractionProfileBindings(instance, &sb), "xrSuggestInteractionProfileBindings")) return 1;

  XrSessionCreateInfo sci{XR_TYPE_SESSION_CREATE_INFO};
  sci.systemId = system;
  XrSession session = XR_NULL_HANDLE;
  if (!ok(xrCreateSession(instance, &sci, &session), "xrCreateSession")) return 1;
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &set;
  if (!ok(xrAttachSessionActionSets(session, &attach), "xrAttachSessionActionSets")) return 1;
  XrActionSpaceCreateInfo spi{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  spi.action = action;
  spi.poseInActionSpace.orientation.w = 1.0f;
  XrSpace gaze_space = XR_NULL_HANDLE, local = XR_NULL_HANDLE;
  if (!ok(xrCreateActionSpace(session, &spi, &gaze_space), "xrCreateActionSpace")) return 1;
  XrReferenceSpaceCreateInfo rsi{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  rsi.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  rsi.poseInReferenceSpace.orientation.w = 1.0f;
  if (!ok(xrCreateReferenceSpace(session, &rsi, &local), "xrCreateReferenceSpace")) return 1;

  bool running = false, quit = false;
  int frames = 0, located = 0, bad_time = 0, profile_events = 0;
  while (!quit) {
    for (;;) {
      XrEventDataBuffer ev{XR_TYPE_EVENT_DATA_BUFFER};
      const XrResult r = xrPollEvent(instance, &ev);
      if (r == XR_EVENT_UNAVAILABLE) break;
      if (!ok(r, "xrPollEvent")) return 1;
      if (ev.type == XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED) ++profile_events;
      if (ev.type != XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) continue;
      const auto state = reinterpret_cast<const XrEventDataSessionStateChanged&>(ev).state;
      std::printf("session state %s\n", state_name(state));
      if (state == XR_SESSION_STATE_READY) {
        XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
        bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        if (!ok(xrBeginSession(session, &bi), "xrBeginSession")) return 1;
        running = true;
      } else if (state == XR_SESSION_STATE_STOPPING) {
        if (!ok(xrEndSession(session), "xrEndSession")) return 1;
        running = false;
      } else if (state == XR_SESSION_STATE_EXITING || state == XR_SESSION_STATE_LOSS_PENDING) {
        quit = true;
      }
    }
    if (!running || quit) continue;
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    if (!ok(xrWaitFrame(session, nullptr, &fs), "xrWaitFrame")) return 1;
    if (!ok(xrBeginFrame(session, nullptr), "xrBeginFrame")) return 1;
    XrActiveActionSet active{set, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    const XrResult sr = xrSyncActions(session, &sync);
    if (!ok(sr, "xrSyncActions")) return 1;
    XrActionStateGetInfo gi{XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = action;
    XrActionStatePose st{XR_TYPE_ACTION_STATE_POSE};
    if (!ok(xrGetActionStatePose(session, &gi, &st), "xrGetActionStatePose")) return 1;
    XrEyeGazeSampleTimeEXT sample{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
    XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION, &sample};
    if (!ok(xrLocateSpace(gaze_space, local, fs.predictedDisplayTime, &loc), "xrLocateSpace")) return 1;
    if (st.isActive && (loc.locationFlags & XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT) != 0) {
      ++located;
      // A sample for this frame: at most the replay's hold before the requested time.
      if (sample.time <= 0 || sample.time > fs.predictedDisplayTime ||
          fs.predictedDisplayTime - sample.time > 200'000'000)
        ++bad_time;
    }
    XrFrameEndInfo fe{XR_TYPE_FRAME_END_INFO};
    fe.displayTime = fs.predictedDisplayTime;
    fe.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    if (!ok(xrEndFrame(session, &fe), "xrEndFrame")) return 1;
    ++frames;
  }
  std::printf("layer_gaze_client: %d frames, gaze located in %d (sample time wrong in %d), %d profile events\n", frames,
              located, bad_time, profile_events);
  xrDestroySpace(gaze_space);
  xrDestroySession(session);
  xrDestroyInstance(instance);
  if (expect == 1) return located >= 10 && bad_time == 0 && profile_events == 1 ? 0 : 1;
  return located == 0 ? 0 : 1;
}
