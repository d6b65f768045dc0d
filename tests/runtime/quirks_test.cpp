// SPDX-License-Identifier: Apache-2.0
// The scenario's gaze-delivery quirks (docs/runtime.md, "Gaze quirks"): a
// runtime that never delivers, one that reports sample time 0, one that echoes the requested
// time, and a system without eye gaze; and bad scenarios / variables refused at
// xrCreateInstance with XR_ERROR_INITIALIZATION_FAILED.
#include "sim/simulator.hpp"
#include "tests/runtime/xr_client.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>

namespace gazelod::xrrt_test {
namespace {

constexpr XrTime kTimeBaseNs = 1'000'000'000;

// The embedded default scenario with runtime options replaced, written to a file.
std::string scenario_with_runtime(const std::string& name, const nlohmann::json& runtime) {
  nlohmann::json j = nlohmann::json::parse(sim::default_scenario_json());
  for (const auto& [key, value] : runtime.items()) j["runtime"][key] = value;
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/runtime/" + name + ".json";
  std::ofstream(path) << j.dump(2);
  return path;
}

struct Gaze {
  XrActionStatePose state{XR_TYPE_ACTION_STATE_POSE};
  XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
  XrEyeGazeSampleTimeEXT sample_time{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
  XrTime query = 0;
  XrBool32 supported = XR_FALSE;
};

// Runs a headless session with a gaze action for a few frames; returns the last gaze read.
Gaze read_gaze(const std::string& scenario_file) {
  use_runtime(2.0, false, scenario_file);
  Gaze g;
  HeadlessSession hs;
  hs.create({XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME});
  XrSystemEyeGazeInteractionPropertiesEXT eye{XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
  XrSystemProperties props{XR_TYPE_SYSTEM_PROPERTIES, &eye};
  EXPECT_EQ(xrGetSystemProperties(hs.instance, hs.system, &props), XR_SUCCESS);
  g.supported = eye.supportsEyeGazeInteraction;
  XrActionSetCreateInfo asi{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(asi.actionSetName, "gaze");
  std::strcpy(asi.localizedActionSetName, "Gaze");
  XrActionSet set = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateActionSet(hs.instance, &asi, &set), XR_SUCCESS);
  XrActionCreateInfo aci{XR_TYPE_ACTION_CREATE_INFO};
  aci.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(aci.actionName, "gaze");
  std::strcpy(aci.localizedActionName, "Gaze");
  XrAction action = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateAction(set, &aci, &action), XR_SUCCESS);
  XrPath profile = XR_NULL_PATH, binding = XR_NULL_PATH;
  xrStringToPath(hs.instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile);
  xrStringToPath(hs.instance, "/user/eyes_ext/input/gaze_ext/pose", &binding);
  const XrActionSuggestedBinding b{action, binding};
  XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  sb.interactionProfile = profile;
  sb.countSuggestedBindings = 1;
  sb.suggestedBindings = &b;
  EXPECT_EQ(xrSuggestInteractionProfileBindings(hs.instance, &sb), XR_SUCCESS);
  XrSessionActionSetsAttachInfo at{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  at.countActionSets = 1;
  at.actionSets = &set;
  EXPECT_EQ(xrAttachSessionActionSets(hs.session, &at), XR_SUCCESS);
  XrActionSpaceCreateInfo as{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  as.action = action;
  as.poseInActionSpace.orientation.w = 1.0f;
  XrSpace gaze_space = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateActionSpace(hs.session, &as, &gaze_space), XR_SUCCESS);
  const XrSpace view = hs.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  hs.begin();
  const XrActiveActionSet active{set, XR_NULL_PATH};
  XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  for (int i = 0; i < 30; ++i) {
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    EXPECT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
    EXPECT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = action;
    EXPECT_EQ(xrGetActionStatePose(hs.session, &get, &g.state), XR_SUCCESS);
    g.query = fs.predictedDisplayTime + 3'000'000;  // between tracker samples
    g.location.next = &g.sample_time;
    EXPECT_EQ(xrLocateSpace(gaze_space, view, g.query, &g.location), XR_SUCCESS);
  }
  hs.destroy();
  return g;
}

TEST(RuntimeQuirks, NormalDeliveryReportsTheTrueSampleTime) {
  const Gaze g = read_gaze(scenario_with_runtime("quirk_normal", {{"gaze_delivery", "normal"}}));
  EXPECT_EQ(g.supported, XR_TRUE);
  EXPECT_EQ(g.state.isActive, XR_TRUE);
  ASSERT_NE(g.location.locationFlags, 0u);
  EXPECT_GT(g.sample_time.time, kTimeBaseNs);
  EXPECT_LE(g.sample_time.time, g.query);
}

TEST(RuntimeQuirks, SampleTimeZero) {
  const Gaze g = read_gaze(scenario_with_runtime("quirk_zero", {{"gaze_delivery", "sample_time_zero"}}));
  EXPECT_NE(g.location.locationFlags, 0u);
  EXPECT_EQ(g.sample_time.time, 0);
}

TEST(RuntimeQuirks, SampleTimeIsRequestTime) {
  const Gaze g = read_gaze(scenario_with_runtime("quirk_request", {{"gaze_delivery", "sample_time_is_request_time"}}));
  EXPECT_NE(g.location.locationFlags, 0u);
  EXPECT_EQ(g.sample_time.time, g.query);
}

TEST(RuntimeQuirks, NeverDeliversAdvertisesButNeverLocates) {
  const Gaze g = read_gaze(scenario_with_runtime("quirk_never", {{"gaze_delivery", "never_delivers"}}));
  EXPECT_EQ(g.supported, XR_TRUE);
  EXPECT_EQ(g.state.isActive, XR_TRUE);
  EXPECT_EQ(g.location.locationFlags, 0u);
  EXPECT_EQ(g.sample_time.time, 0);
}

TEST(RuntimeQuirks, SystemWithoutEyeGaze) {
  const Gaze g = read_gaze(scenario_with_runtime("quirk_unsupported", {{"eye_gaze_supported", false}}));
  EXPECT_EQ(g.supported, XR_FALSE);
  EXPECT_EQ(g.state.isActive, XR_FALSE);
  EXPECT_EQ(g.location.locationFlags, 0u);
}

TEST(RuntimeQuirks, BadScenarioOrVariableFailsInstanceCreation) {
  const std::string bad = std::string(GAZELOD_BINARY_DIR) + "/tests/runtime/quirk_bad.json";
  std::ofstream(bad) << "{ \"version\": 1, ";
  use_runtime(2.0, false, bad);
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "bad");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  XrInstance instance = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_INITIALIZATION_FAILED);
  use_runtime(2.0);
  setenv("GAZELOD_SIM_DURATION_S", "soon", 1);
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_INITIALIZATION_FAILED);
  setenv("GAZELOD_SIM_DURATION_S", "-1", 1);
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_INITIALIZATION_FAILED);
  // The longest scenario plus the second of slack `gazelod run` adds: a scenario that
  // validates also runs (it once failed here, past 1e6).
  setenv("GAZELOD_SIM_DURATION_S", "1000001", 1);
  ASSERT_EQ(xrCreateInstance(&info, &instance), XR_SUCCESS);
  xrDestroyInstance(instance);
  instance = XR_NULL_HANDLE;
  setenv("GAZELOD_SIM_DURATION_S", "1000001.5", 1);
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_INITIALIZATION_FAILED);
  use_runtime(2.0);
  setenv("GAZELOD_SIM_PACED", "yes", 1);
  EXPECT_EQ(xrCreateInstance(&info, &instance), XR_ERROR_INITIALIZATION_FAILED);
}

}  // namespace
}  // namespace gazelod::xrrt_test
