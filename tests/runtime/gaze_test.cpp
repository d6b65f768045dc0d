// SPDX-License-Identifier: Apache-2.0
// Eye gaze and head motion located through the Khronos loader match the simulator: the gaze
// action space (XR_EXT_eye_gaze_interaction) against Simulator::tracker_at at the same time,
// within 1e-4 rad, with the true sample time; VIEW's angular velocity against head_at.
#include "sim/simulator.hpp"
#include "tests/runtime/xr_client.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>

namespace gazelod::xrrt_test {
namespace {

constexpr XrTime kTimeBaseNs = 1'000'000'000;  // scenario time 0 (docs/runtime.md)
constexpr double kDurationS = 2.0;

sim::Simulator expected_simulator(double duration_s) {
  sim::Scenario sc = sim::load_scenario_json(sim::default_scenario_json(), "<embedded default scenario>");
  sc.duration_s = duration_s;
  return sim::Simulator(std::move(sc));
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

glm::dquat to_glm(const XrQuaternionf& q) {
  return glm::dquat(q.w, q.x, q.y, q.z);
}
glm::dvec3 to_glm(const XrVector3f& v) {
  return glm::dvec3(v.x, v.y, v.z);
}

struct GazeRig {
  HeadlessSession hs;
  XrActionSet set = XR_NULL_HANDLE;
  XrAction gaze = XR_NULL_HANDLE;
  XrSpace gaze_space = XR_NULL_HANDLE, view = XR_NULL_HANDLE, local = XR_NULL_HANDLE;

  void create() {
    hs.create({XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME});
    XrSystemEyeGazeInteractionPropertiesEXT eye{XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
    XrSystemProperties props{XR_TYPE_SYSTEM_PROPERTIES, &eye};
    XRRT_ASSERT_XR(xrGetSystemProperties(hs.instance, hs.system, &props));
    ASSERT_EQ(eye.supportsEyeGazeInteraction, XR_TRUE);

    XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::strcpy(set_info.actionSetName, "gaze");
    std::strcpy(set_info.localizedActionSetName, "Gaze");
    XRRT_ASSERT_XR(xrCreateActionSet(hs.instance, &set_info, &set));
    XrActionCreateInfo action_info{XR_TYPE_ACTION_CREATE_INFO};
    action_info.actionType = XR_ACTION_TYPE_POSE_INPUT;
    std::strcpy(action_info.actionName, "gaze_pose");
    std::strcpy(action_info.localizedActionName, "Gaze pose");
    XRRT_ASSERT_XR(xrCreateAction(set, &action_info, &gaze));
    XrPath profile = XR_NULL_PATH, binding = XR_NULL_PATH;
    XRRT_ASSERT_XR(xrStringToPath(hs.instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile));
    XRRT_ASSERT_XR(xrStringToPath(hs.instance, "/user/eyes_ext/input/gaze_ext/pose", &binding));
    const XrActionSuggestedBinding b{gaze, binding};
    XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    suggested.interactionProfile = profile;
    suggested.countSuggestedBindings = 1;
    suggested.suggestedBindings = &b;
    XRRT_ASSERT_XR(xrSuggestInteractionProfileBindings(hs.instance, &suggested));
    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &set;
    XRRT_ASSERT_XR(xrAttachSessionActionSets(hs.session, &attach));
    XrActionSpaceCreateInfo space_info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    space_info.action = gaze;
    space_info.poseInActionSpace.orientation.w = 1.0f;
    XRRT_ASSERT_XR(xrCreateActionSpace(hs.session, &space_info, &gaze_space));
    view = hs.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
    local = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
    hs.begin();
  }

  XrTime next_frame() {
    XrFrameState state{XR_TYPE_FRAME_STATE};
    EXPECT_EQ(xrWaitFrame(hs.session, nullptr, &state), XR_SUCCESS);
    EXPECT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    EXPECT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
    const XrActiveActionSet active{set, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    EXPECT_EQ(xrSyncActions(hs.session, &sync), XR_SUCCESS);
    return state.predictedDisplayTime;
  }
};

TEST(RuntimeGaze, GazeThroughLoaderMatchesSimulatorTracker) {
  use_runtime(kDurationS);
  GazeRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  sim::Simulator expected = expected_simulator(kDurationS);
  int compared = 0, untracked = 0;
  for (int frame = 0; frame < 150; ++frame) {
    const XrTime t = rig.next_frame();
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = rig.gaze;
    XrActionStatePose pose_state{XR_TYPE_ACTION_STATE_POSE};
    ASSERT_EQ(xrGetActionStatePose(rig.hs.session, &get, &pose_state), XR_SUCCESS);
    ASSERT_EQ(pose_state.isActive, XR_TRUE);
    // Ask at the frame time and half a frame later, so times between tracker samples count.
    for (XrTime query : {t, t + 5'555'555}) {
      XrEyeGazeSampleTimeEXT sample_time{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
      XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION, &sample_time};
      ASSERT_EQ(xrLocateSpace(rig.gaze_space, rig.view, query, &loc), XR_SUCCESS);
      const gaze::GazeSample g = expected.tracker_at(query - kTimeBaseNs);
      if (!g.valid) {
        EXPECT_EQ(loc.locationFlags, 0u) << "an invalid tracker sample must not be reported as tracked";
        ++untracked;
        continue;
      }
      const XrSpaceLocationFlags all = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                                       XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT |
                                       XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
      ASSERT_EQ(loc.locationFlags, all);
      // The pose's -Z axis is the gaze direction (head space, since the base is VIEW).
      const glm::dvec3 dir = to_glm(loc.pose.orientation) * glm::dvec3(0, 0, -1);
      EXPECT_LT(angle_between(dir, glm::normalize(g.direction)), 1e-4) << "t_ns=" << query - kTimeBaseNs;
      EXPECT_NEAR(loc.pose.position.x, g.origin_m.x, 1e-5);
      EXPECT_NEAR(loc.pose.position.y, g.origin_m.y, 1e-5);
      EXPECT_NEAR(loc.pose.position.z, g.origin_m.z, 1e-5);
      EXPECT_EQ(sample_time.time, g.t_ns + kTimeBaseNs) << "the true sample time";
      EXPECT_LE(sample_time.time, query);
      ++compared;
    }
  }
  EXPECT_GT(compared, 100) << "untracked samples: " << untracked;
  rig.hs.destroy();
}

TEST(RuntimeGaze, GazeInLocalIsHeadPoseTimesEyeInHead) {
  use_runtime(kDurationS);
  GazeRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create());
  sim::Simulator expected = expected_simulator(kDurationS);
  int compared = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const XrTime t = rig.next_frame();
    XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
    ASSERT_EQ(xrLocateSpace(rig.gaze_space, rig.local, t, &loc), XR_SUCCESS);
    const gaze::GazeSample g = expected.tracker_at(t - kTimeBaseNs);
    if (!g.valid) continue;
    const sim::HeadState h = expected.head_at(t - kTimeBaseNs);
    const glm::dvec3 world_dir = h.orientation * glm::normalize(g.direction);
    const glm::dvec3 dir = to_glm(loc.pose.orientation) * glm::dvec3(0, 0, -1);
    EXPECT_LT(angle_between(dir, world_dir), 1e-4);
    ++compared;
  }
  EXPECT_GT(compared, 30);
  rig.hs.destroy();
}

TEST(RuntimeHead, ViewAngularVelocityMatchesHeadScript) {
  use_runtime(kDurationS);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  const XrSpace view = hs.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  const XrSpace local = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  sim::Simulator expected = expected_simulator(kDurationS);
  double max_speed = 0.0;
  for (XrTime t = kTimeBaseNs + 1'000'000; t < kTimeBaseNs + 1'900'000'000; t += 7'000'000) {
    XrSpaceVelocity vel{XR_TYPE_SPACE_VELOCITY};
    XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION, &vel};
    ASSERT_EQ(xrLocateSpace(view, local, t, &loc), XR_SUCCESS);
    ASSERT_TRUE(vel.velocityFlags & XR_SPACE_VELOCITY_ANGULAR_VALID_BIT);
    ASSERT_TRUE(vel.velocityFlags & XR_SPACE_VELOCITY_LINEAR_VALID_BIT);
    const sim::HeadState h = expected.head_at(t - kTimeBaseNs);
    const glm::dvec3 w = to_glm(vel.angularVelocity);
    EXPECT_NEAR(w.x, h.angular_velocity_rad_s.x, 1e-4) << "t_ns=" << t - kTimeBaseNs;
    EXPECT_NEAR(w.y, h.angular_velocity_rad_s.y, 1e-4);
    EXPECT_NEAR(w.z, h.angular_velocity_rad_s.z, 1e-4);
    // And the pose is the script's.
    const glm::dquat d = glm::conjugate(h.orientation) * to_glm(loc.pose.orientation);
    EXPECT_LT(2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w)), 1e-4);
    max_speed = std::max(max_speed, glm::length(h.angular_velocity_rad_s));
  }
  RecordProperty("max_head_speed_rad_s", std::to_string(max_speed));
  hs.destroy();
}

TEST(RuntimeHead, ReportedAngularVelocityAgreesWithReportedPoses) {
  // Independent of the script's own velocity: differentiate the poses the runtime reports.
  use_runtime(kDurationS);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  const XrSpace view = hs.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  const XrSpace local = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  constexpr XrTime kStep = 1'000'000;  // 1 ms central difference
  for (XrTime t = kTimeBaseNs + 50'000'000; t < kTimeBaseNs + 1'900'000'000; t += 37'000'000) {
    XrSpaceVelocity vel{XR_TYPE_SPACE_VELOCITY};
    XrSpaceLocation now{XR_TYPE_SPACE_LOCATION, &vel}, before{XR_TYPE_SPACE_LOCATION}, after{XR_TYPE_SPACE_LOCATION};
    ASSERT_EQ(xrLocateSpace(view, local, t, &now), XR_SUCCESS);
    ASSERT_EQ(xrLocateSpace(view, local, t - kStep, &before), XR_SUCCESS);
    ASSERT_EQ(xrLocateSpace(view, local, t + kStep, &after), XR_SUCCESS);
    glm::dquat dq = to_glm(after.pose.orientation) * glm::conjugate(to_glm(before.pose.orientation));
    if (dq.w < 0) dq = -dq;
    const glm::dvec3 axis_sin(dq.x, dq.y, dq.z);
    const double half = std::atan2(glm::length(axis_sin), dq.w);
    const glm::dvec3 w_fd =
        glm::length(axis_sin) > 0 ? axis_sin / glm::length(axis_sin) * (2.0 * half / (2e-9 * kStep)) : glm::dvec3(0.0);
    // Float poses and the finite difference limit the agreement (~1e-7 / 2 ms).
    EXPECT_LT(glm::length(w_fd - to_glm(vel.angularVelocity)), 2e-2) << "t_ns=" << t - kTimeBaseNs;
  }
  hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
