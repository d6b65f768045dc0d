// SPDX-License-Identifier: Apache-2.0
// A deliberately faulty OpenXR client for the negative control of check_xr_run.sh: it runs a
// correct headless session (FOCUSED ... EXITING, frames submitted) but makes one invalid call
// (an XrSpaceLocation with the wrong structure type) that the core validation layer must
// report, so the check is shown to catch validation messages.
#include <openxr/openxr.h>

#include <cstdio>
#include <cstring>

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
    case XR_SESSION_STATE_EXITING:
      return "XR_SESSION_STATE_EXITING";
    default:
      return "other";
  }
}

XrSessionState pump(XrInstance instance, XrSessionState last) {
  XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(instance, &e) == XR_SUCCESS) {
    if (e.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      last = reinterpret_cast<XrEventDataSessionStateChanged&>(e).state;
      std::printf("state %s\n", state_name(last));
    }
    e = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  return last;
}

}  // namespace

int main() {
  const char* ext[] = {XR_MND_HEADLESS_EXTENSION_NAME};
  XrInstanceCreateInfo ci{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(ci.applicationInfo.applicationName, "gazelod-misuse-client");
  ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  ci.enabledExtensionCount = 1;
  ci.enabledExtensionNames = ext;
  XrInstance instance = XR_NULL_HANDLE;
  if (xrCreateInstance(&ci, &instance) != XR_SUCCESS) return 1;
  XrSystemGetInfo sgi{XR_TYPE_SYSTEM_GET_INFO};
  sgi.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  if (xrGetSystem(instance, &sgi, &system) != XR_SUCCESS) return 1;
  XrSessionCreateInfo sci{XR_TYPE_SESSION_CREATE_INFO};
  sci.systemId = system;
  XrSession session = XR_NULL_HANDLE;
  if (xrCreateSession(instance, &sci, &session) != XR_SUCCESS) return 1;
  XrSessionState state = pump(instance, XR_SESSION_STATE_UNKNOWN);
  XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
  bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  if (xrBeginSession(session, &bi) != XR_SUCCESS) return 1;
  XrReferenceSpaceCreateInfo rs{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  rs.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace local = XR_NULL_HANDLE;
  if (xrCreateReferenceSpace(session, &rs, &local) != XR_SUCCESS) return 1;
  bool misused = false;
  while (state != XR_SESSION_STATE_EXITING) {
    state = pump(instance, state);
    if (state == XR_SESSION_STATE_STOPPING) {
      if (xrEndSession(session) != XR_SUCCESS) return 1;
      continue;
    }
    if (state == XR_SESSION_STATE_EXITING) break;
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    if (xrWaitFrame(session, nullptr, &fs) != XR_SUCCESS || xrBeginFrame(session, nullptr) != XR_SUCCESS) return 1;
    if (!misused) {
      XrSpaceLocation wrong{XR_TYPE_SPACE_VELOCITY};  // the invalid call
      (void)xrLocateSpace(local, local, fs.predictedDisplayTime, &wrong);
      misused = true;
    }
    XrFrameEndInfo fe{XR_TYPE_FRAME_END_INFO};
    fe.displayTime = fs.predictedDisplayTime;
    fe.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    if (xrEndFrame(session, &fe) != XR_SUCCESS) return 1;
  }
  xrDestroySpace(local);
  xrDestroySession(session);
  xrDestroyInstance(instance);
  return 0;
}
