// SPDX-License-Identifier: Apache-2.0
// Loader-side helpers for the runtime tests (see xr_client.hpp).
#include "tests/runtime/xr_client.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#ifndef GAZELOD_XR_RUNTIME_JSON
#error "GAZELOD_XR_RUNTIME_JSON must name the built runtime manifest"
#endif

namespace gazelod::xrrt_test {

void use_runtime(double duration_s, bool paced, const std::string& scenario_file) {
  setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
  setenv("GAZELOD_SIM_DURATION_S", std::to_string(duration_s).c_str(), 1);
  setenv("GAZELOD_SIM_PACED", paced ? "1" : "0", 1);
  if (scenario_file.empty())
    unsetenv("GAZELOD_SIM_SCENARIO");
  else
    setenv("GAZELOD_SIM_SCENARIO", scenario_file.c_str(), 1);
}

XrPath path(XrInstance instance, const char* s) {
  XrPath p = XR_NULL_PATH;
  EXPECT_EQ(xrStringToPath(instance, s, &p), XR_SUCCESS) << s;
  return p;
}

XrInstance create_instance(const std::vector<const char*>& extensions) {
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "gazelod-runtime-test");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.enabledExtensionNames = extensions.data();
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_SUCCESS);
  return instance;
}

XrSystemId get_system(XrInstance instance) {
  XrSystemGetInfo info{XR_TYPE_SYSTEM_GET_INFO};
  info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  EXPECT_EQ(xrGetSystem(instance, &info, &system), XR_SUCCESS);
  return system;
}

std::vector<XrSessionState> drain_states(XrInstance instance) {
  std::vector<XrSessionState> states;
  for (;;) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    const XrResult r = xrPollEvent(instance, &event);
    EXPECT_TRUE(r == XR_SUCCESS || r == XR_EVENT_UNAVAILABLE) << r;
    if (r != XR_SUCCESS) break;
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED)
      states.push_back(reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state);
  }
  return states;
}

void HeadlessSession::create(const std::vector<const char*>& extensions) {
  std::vector<const char*> ext = extensions;
  ext.push_back(XR_MND_HEADLESS_EXTENSION_NAME);
  instance = create_instance(ext);
  ASSERT_NE(instance, XR_NULL_HANDLE);
  system = get_system(instance);
  XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
  info.systemId = system;
  XRRT_ASSERT_XR(xrCreateSession(instance, &info, &session));
  pump();
}

void HeadlessSession::begin() {
  XrSessionBeginInfo info{XR_TYPE_SESSION_BEGIN_INFO};
  info.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  XRRT_ASSERT_XR(xrBeginSession(session, &info));
  pump();
  ASSERT_FALSE(states.empty());
  ASSERT_EQ(states.back(), XR_SESSION_STATE_FOCUSED);
}

XrSpace HeadlessSession::reference_space(XrReferenceSpaceType type) const {
  XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  info.referenceSpaceType = type;
  info.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace space = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateReferenceSpace(session, &info, &space), XR_SUCCESS);
  return space;
}

void HeadlessSession::destroy() {
  if (session != XR_NULL_HANDLE) xrDestroySession(session);
  if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
  session = XR_NULL_HANDLE;
  instance = XR_NULL_HANDLE;
}

}  // namespace gazelod::xrrt_test

// Under LeakSanitizer: the Debian OpenXR loader 1.0.20 does not free about 1.3 kB that
// xrCreateInstance allocates (inside libopenxr_loader.so, after xrDestroyInstance returned
// XR_SUCCESS). Suppress leaks whose stack lies in the loader only; the runtime's are reported.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libopenxr_loader.so\n";
}
