// SPDX-License-Identifier: Apache-2.0
// An application that uses only the eye-gaze interaction profile, against the simulated
// runtime without XR_EXT_eye_gaze_interaction (GAZELOD_SIM_EYE_GAZE_EXTENSION=0) and the layer
// replaying a trace: the extension is advertised, suggest / attach / sync / get state / locate
// work, the pose is the trace's gaze at the requested time on the runtime's head pose, and
// XrEyeGazeSampleTimeEXT says when the sample is for. And the runtime-has-the-extension case:
// the same poses with the layer as without it, unless the configuration overrides.
#include "tests/layer/layer_test_util.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <fstream>
#include <thread>
#include <vector>

namespace gazelod::layer_test {
namespace {

constexpr XrSpaceLocationFlags kAll = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                                      XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT |
                                      XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
constexpr double kFloatRad = 2e-6;  // XrPosef is single precision

glm::dquat q_of(const XrPosef& p) {
  return glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
}
glm::dvec3 p_of(const XrPosef& p) {
  return {p.position.x, p.position.y, p.position.z};
}

bool has_extension(const char* layer, const char* name) {
  uint32_t n = 0;
  if (xrEnumerateInstanceExtensionProperties(layer, 0, &n, nullptr) != XR_SUCCESS) return false;
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES});
  if (xrEnumerateInstanceExtensionProperties(layer, n, &n, props.data()) != XR_SUCCESS) return false;
  for (const auto& p : props)
    if (std::strcmp(p.extensionName, name) == 0) return true;
  return false;
}

TEST(LayerGazeClient, RuntimeWithoutEyeGazeGetsItFromTheLayer) {
  const std::string dir = scratch_dir();
  // A blink from 1.0 s to 1.3 s: longer than the 150 ms hold, so gaze goes stale there.
  const auto records = write_trace(dir + "/trace.csv", 3.0, 200.0, 1.0, 1.3);
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  apply(setup);
  EXPECT_TRUE(has_extension(nullptr, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME));
  EXPECT_TRUE(has_extension("XR_APILAYER_GAZELOD_eye_gaze", XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME));
  setup.layer = false;
  apply(setup);
  EXPECT_FALSE(has_extension(nullptr, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME));  // the runtime lacks it
  setup.layer = true;
  apply(setup);

  GazeRig rig;
  rig.create(/*eyes_subaction=*/true);
  if (HasFatalFailure()) return;
  EXPECT_EQ(rig.supported, XR_TRUE);
  // Attached, not synced: no profile yet, and no event.
  EXPECT_EQ(rig.current_profile(), XR_NULL_PATH);
  EXPECT_EQ(rig.drain_profile_events(), 0);
  // A sync before the first frame: the trace has no place on the session's clock yet.
  ASSERT_EQ(rig.sync(), XR_SUCCESS);
  EXPECT_FALSE(rig.active());
  EXPECT_EQ(rig.drain_profile_events(), 1);  // the profile changed in that xrSyncActions
  EXPECT_EQ(rig.current_profile(), rig.profile);
  EXPECT_EQ(rig.drain_profile_events(), 0);  // once

  int located = 0, stale = 0;
  for (int f = 0; f < 200; ++f) {
    const XrTime t = rig.frame();
    ASSERT_EQ(rig.sync(), XR_SUCCESS);
    const auto expected = expected_gaze(records, rig.first_frame, t);
    ASSERT_EQ(rig.active(), expected.has_value()) << "frame " << f;
    EXPECT_EQ(rig.active(rig.eyes), expected.has_value());
    const auto in_view = rig.locate(rig.gaze_space, rig.view, t);
    EXPECT_EQ(in_view.velocity_flags, 0u);
    if (!expected) {
      ++stale;
      EXPECT_EQ(in_view.flags, 0u);
      EXPECT_EQ(in_view.sample_time, 0);
      continue;
    }
    ++located;
    ASSERT_EQ(in_view.flags, kAll) << "frame " << f;
    EXPECT_LT(angle_rad(direction_of(in_view.pose), expected->direction), kFloatRad) << "frame " << f;
    EXPECT_LT(glm::length(p_of(in_view.pose) - expected->origin_m), 1e-6);
    EXPECT_EQ(in_view.sample_time, expected->t_ns);
    // Between two frames (and two samples): interpolated, for that time.
    const XrTime mid = t + 2'500'000;
    const auto at_mid = rig.locate(rig.gaze_space, rig.view, mid);
    const auto expected_mid = expected_gaze(records, rig.first_frame, mid);
    if (expected_mid) {
      EXPECT_LT(angle_rad(direction_of(at_mid.pose), expected_mid->direction), kFloatRad);
      EXPECT_EQ(at_mid.sample_time, expected_mid->t_ns);
    } else {
      EXPECT_EQ(at_mid.flags, 0u);  // the hold ran out between the frame and this time
    }
    // In LOCAL: the runtime's head pose composed with the eye-in-head pose.
    const auto head = rig.locate(rig.view, rig.local, t);
    const auto in_local = rig.locate(rig.gaze_space, rig.local, t);
    ASSERT_EQ(in_local.flags, kAll);
    const glm::dvec3 dir_local = glm::normalize(q_of(head.pose)) * expected->direction;
    EXPECT_LT(angle_rad(direction_of(in_local.pose), dir_local), 4 * kFloatRad);
    EXPECT_LT(glm::length(p_of(in_local.pose) - (p_of(head.pose) + q_of(head.pose) * expected->origin_m)), 1e-5);
    // And the other way round: LOCAL in the gaze space is the inverse.
    const auto inverse = rig.locate(rig.local, rig.gaze_space, t);
    ASSERT_EQ(inverse.flags, kAll);
    const glm::dquat round_trip = q_of(in_local.pose) * q_of(inverse.pose);
    EXPECT_GT(std::abs(round_trip.w), 1.0 - 1e-6);
  }
  EXPECT_GT(located, 150);
  EXPECT_GT(stale, 10);  // the blink, past the hold

  // The bound source and its name.
  XrBoundSourcesForActionEnumerateInfo bound{XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO};
  bound.action = rig.gaze;
  uint32_t n = 0;
  ASSERT_EQ(xrEnumerateBoundSourcesForAction(rig.hs.session, &bound, 0, &n, nullptr), XR_SUCCESS);
  ASSERT_EQ(n, 1u);
  XrPath source = XR_NULL_PATH;
  ASSERT_EQ(xrEnumerateBoundSourcesForAction(rig.hs.session, &bound, 1, &n, &source), XR_SUCCESS);
  EXPECT_EQ(source, rig.pose_path);
  XrInputSourceLocalizedNameGetInfo name_info{XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO};
  name_info.sourcePath = source;
  name_info.whichComponents = XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT |
                              XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT |
                              XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT;
  ASSERT_EQ(xrGetInputSourceLocalizedName(rig.hs.session, &name_info, 0, &n, nullptr), XR_SUCCESS);
  std::vector<char> name(n);
  EXPECT_EQ(xrGetInputSourceLocalizedName(rig.hs.session, &name_info, 1, &n, name.data()), XR_ERROR_SIZE_INSUFFICIENT);
  ASSERT_EQ(xrGetInputSourceLocalizedName(rig.hs.session, &name_info, n, &n, name.data()), XR_SUCCESS);
  EXPECT_STREQ(name.data(), "Eyes Eye Gaze Interaction Gaze Pose");

  // Suggestions are locked after attach; layer-owned handles go away cleanly.
  const XrActionSuggestedBinding b{rig.gaze, rig.pose_path};
  XrInteractionProfileSuggestedBinding again{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  again.interactionProfile = rig.profile;
  again.countSuggestedBindings = 1;
  again.suggestedBindings = &b;
  EXPECT_EQ(xrSuggestInteractionProfileBindings(rig.hs.instance, &again), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  EXPECT_EQ(xrDestroySpace(rig.gaze_space), XR_SUCCESS);
  EXPECT_EQ(xrDestroyAction(rig.gaze), XR_SUCCESS);
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = rig.gaze;
  XrActionStatePose state{XR_TYPE_ACTION_STATE_POSE};
  EXPECT_EQ(xrGetActionStatePose(rig.hs.session, &get, &state), XR_ERROR_HANDLE_INVALID);
  rig.destroy();
}

TEST(LayerGazeClient, BadSuggestionsAreRefusedLikeARuntimeWould) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 1.0);
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  apply(setup);
  HeadlessSession hs;
  hs.create({XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME});
  XrActionSet set = XR_NULL_HANDLE;
  XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(set_info.actionSetName, "s");
  std::strcpy(set_info.localizedActionSetName, "S");
  ASSERT_EQ(xrCreateActionSet(hs.instance, &set_info, &set), XR_SUCCESS);
  XrAction button = XR_NULL_HANDLE;
  XrActionCreateInfo a{XR_TYPE_ACTION_CREATE_INFO};
  a.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
  std::strcpy(a.actionName, "b");
  std::strcpy(a.localizedActionName, "B");
  ASSERT_EQ(xrCreateAction(set, &a, &button), XR_SUCCESS);
  XrPath profile = XR_NULL_PATH, pose = XR_NULL_PATH, grip = XR_NULL_PATH;
  xrStringToPath(hs.instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile);
  xrStringToPath(hs.instance, "/user/eyes_ext/input/gaze_ext/pose", &pose);
  xrStringToPath(hs.instance, "/user/hand/left/input/grip/pose", &grip);
  XrActionSuggestedBinding b{button, pose};
  XrInteractionProfileSuggestedBinding s{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  s.interactionProfile = profile;
  s.countSuggestedBindings = 1;
  s.suggestedBindings = &b;
  EXPECT_EQ(xrSuggestInteractionProfileBindings(hs.instance, &s), XR_ERROR_PATH_UNSUPPORTED);  // not a pose action
  b.binding = grip;
  EXPECT_EQ(xrSuggestInteractionProfileBindings(hs.instance, &s), XR_ERROR_PATH_UNSUPPORTED);  // not in the profile
  hs.destroy();
}

// /user/eyes_ext is the layer's own top-level path: the runtime under it never learns it, so it
// must never reach the runtime (which would answer XR_ERROR_PATH_UNSUPPORTED for a path the
// application did declare). And xrDestroyAction removes the handle, not the action: its gaze
// space keeps locating while its set is synced (the specification's xrDestroyAction).
TEST(LayerGazeClient, EyesSubactionStaysInTheLayerAndADestroyedActionStillLocates) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 3.0);
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  apply(setup);
  GazeRig rig;
  rig.create(/*eyes_subaction=*/true, /*extras=*/true);
  if (HasFatalFailure()) return;
  XrPath left = XR_NULL_PATH;
  ASSERT_EQ(xrStringToPath(rig.hs.instance, "/user/hand/left", &left), XR_SUCCESS);
  XrActionSpaceCreateInfo space_info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  space_info.action = rig.other_pose;
  space_info.subactionPath = rig.eyes;
  space_info.poseInActionSpace.orientation.w = 1.0f;
  XrSpace other_space = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateActionSpace(rig.hs.session, &space_info, &other_space), XR_SUCCESS);
  int located = 0;
  for (int f = 0; f < 40; ++f) {
    const XrTime t = rig.frame();
    ASSERT_EQ(rig.sync(rig.eyes), XR_SUCCESS) << "frame " << f;
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = rig.button;
    get.subactionPath = rig.eyes;
    XrActionStateBoolean button{XR_TYPE_ACTION_STATE_BOOLEAN};
    button.isActive = XR_TRUE;
    ASSERT_EQ(xrGetActionStateBoolean(rig.hs.session, &get, &button), XR_SUCCESS);
    EXPECT_EQ(button.isActive, XR_FALSE);  // nothing but a pose is bound under /user/eyes_ext
    get.subactionPath = left;
    ASSERT_EQ(xrGetActionStateBoolean(rig.hs.session, &get, &button), XR_SUCCESS);  // the runtime's
    get.action = rig.other_pose;
    get.subactionPath = rig.eyes;
    XrActionStatePose pose{XR_TYPE_ACTION_STATE_POSE};
    ASSERT_EQ(xrGetActionStatePose(rig.hs.session, &get, &pose), XR_SUCCESS);
    EXPECT_EQ(pose.isActive, XR_FALSE);
    EXPECT_EQ(rig.locate(other_space, rig.local, t).flags, 0u);
    located += rig.active(rig.eyes) && rig.locate(rig.gaze_space, rig.local, t).flags == kAll ? 1 : 0;
  }
  EXPECT_GT(located, 30);
  ASSERT_EQ(xrDestroyAction(rig.gaze), XR_SUCCESS);
  located = 0;
  for (int f = 0; f < 20; ++f) {
    const XrTime t = rig.frame();
    ASSERT_EQ(rig.sync(), XR_SUCCESS);
    located += rig.locate(rig.gaze_space, rig.local, t).flags == kAll ? 1 : 0;
  }
  EXPECT_GT(located, 15) << "the gaze space stopped locating when its action's handle was destroyed";
  rig.destroy();
}

// A headless client locating the gaze in LOCAL for `frames` frames.
std::vector<GazeRig::Located> run_client(const LayerSetup& setup, int frames) {
  apply(setup);
  GazeRig rig;
  rig.create();
  std::vector<GazeRig::Located> out;
  for (int f = 0; f < frames; ++f) {
    const XrTime t = rig.frame();
    EXPECT_EQ(rig.sync(), XR_SUCCESS);
    out.push_back(rig.locate(rig.gaze_space, rig.local, t));
  }
  rig.destroy();
  return out;
}

bool same(const GazeRig::Located& a, const GazeRig::Located& b) {
  return a.flags == b.flags && a.sample_time == b.sample_time && std::memcmp(&a.pose, &b.pose, sizeof a.pose) == 0;
}

TEST(LayerGazeClient, RuntimeWithEyeGazePassesThroughUnchanged) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 2.0);
  LayerSetup setup;
  setup.runtime_eye_gaze = true;
  setup.trace = dir + "/trace.csv";  // configured, but the runtime's own gaze wins
  setup.layer = false;
  const auto without = run_client(setup, 60);
  setup.layer = true;
  const auto with = run_client(setup, 60);
  ASSERT_EQ(without.size(), with.size());
  int located = 0;
  for (std::size_t i = 0; i < with.size(); ++i) {
    EXPECT_TRUE(same(with[i], without[i])) << "frame " << i;
    located += with[i].flags != 0 ? 1 : 0;
  }
  EXPECT_GT(located, 50);

  // Told to override, the layer serves the trace instead of the runtime's gaze.
  std::ofstream(dir + "/override.json") << R"({"override": true})";
  setup.config = dir + "/override.json";
  const auto overridden = run_client(setup, 60);
  int differ = 0;
  for (std::size_t i = 0; i < overridden.size(); ++i) differ += same(overridden[i], without[i]) ? 0 : 1;
  EXPECT_GT(differ, 50);
}

TEST(LayerGazeClient, LocateFromManyThreadsWhileTheFrameLoopSyncs) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 60.0, 100.0);
  LayerSetup setup;
  setup.duration_s = 70.0;  // the runtime keeps the session focused for 5000 frames
  setup.trace = dir + "/trace.csv";
  apply(setup);
  GazeRig rig;
  rig.create();
  std::atomic<XrTime> latest{rig.frame()};
  ASSERT_EQ(rig.sync(), XR_SUCCESS);
  std::atomic<bool> stop{false};
  std::atomic<int> bad{0}, done{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i)
    threads.emplace_back([&] {
      while (!stop) {
        XrEyeGazeSampleTimeEXT sample{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
        XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION, &sample};
        if (xrLocateSpace(rig.gaze_space, rig.local, latest.load(), &loc) != XR_SUCCESS)
          ++bad;
        else if (loc.locationFlags != 0 && !(std::abs(glm::length(q_of(loc.pose)) - 1.0) < 1e-3))
          ++bad;
        ++done;
      }
    });
  // The frame loop goes on until the threads have located a few thousand times, however the
  // scheduler interleaves them: frames within the trace's length, then syncs alone.
  for (long i = 0; i < 50'000'000 && (i < 150 || done.load() < 4000); ++i) {
    if (i < 5000)
      latest = rig.frame();
    else
      std::this_thread::yield();
    EXPECT_EQ(rig.sync(), XR_SUCCESS);
  }
  stop = true;
  for (auto& t : threads) t.join();
  EXPECT_EQ(bad.load(), 0);
  EXPECT_GE(done.load(), 4000);
  rig.destroy();
}

}  // namespace
}  // namespace gazelod::layer_test
