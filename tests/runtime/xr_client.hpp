// SPDX-License-Identifier: Apache-2.0
// Helpers for tests that drive the simulated runtime through the Khronos loader: environment
// set-up (XR_RUNTIME_JSON, scenario overrides), instance / headless session creation, event
// pumping and extension function lookup.
#pragma once

#include <openxr/openxr.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gazelod::xrrt_test {

#define XRRT_ASSERT_XR(call) ASSERT_EQ((call), XR_SUCCESS) << #call

// Points the loader at the built runtime and sets the scenario variables (duration in seconds,
// unpaced unless `paced`). An empty scenario_file means the embedded default.
void use_runtime(double duration_s, bool paced = false, const std::string& scenario_file = "");

XrInstance create_instance(const std::vector<const char*>& extensions);
// xrStringToPath, failing the test on error.
XrPath path(XrInstance instance, const char* s);
XrSystemId get_system(XrInstance instance);

template <class PFN>
PFN proc(XrInstance instance, const char* name) {
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(instance, name, &fn), XR_SUCCESS) << name;
  return reinterpret_cast<PFN>(fn);
}

// Polls every queued event; returns the session states seen, in order.
std::vector<XrSessionState> drain_states(XrInstance instance);

// A headless session (XR_MND_headless), begun and pumped until FOCUSED.
struct HeadlessSession {
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  std::vector<XrSessionState> states;  // every state seen so far

  void create(const std::vector<const char*>& extensions);  // creates, does not begin
  void begin();                                             // begins, pumps to FOCUSED
  XrSpace reference_space(XrReferenceSpaceType type) const;
  void pump() {
    for (XrSessionState s : drain_states(instance)) states.push_back(s);
  }
  void destroy();
};

}  // namespace gazelod::xrrt_test
