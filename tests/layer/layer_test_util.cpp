// SPDX-License-Identifier: Apache-2.0
#include "tests/layer/layer_test_util.hpp"

#include "gaze/replay_source.hpp"
#include "gaze/trace_open.hpp"
#include "gaze/trace_reader.hpp"
#include "gaze/trace_writer.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#ifndef GAZELOD_LAYER_MANIFEST_DIR
#error "GAZELOD_LAYER_MANIFEST_DIR must name the folder of the layer manifest under test"
#endif

namespace gazelod::layer_test {

void apply(const LayerSetup& s) {
  xrrt_test::use_runtime(s.duration_s, s.paced);
  setenv("GAZELOD_SIM_EYE_GAZE_EXTENSION", s.runtime_eye_gaze ? "1" : "0", 1);
  if (s.layer) {
    setenv("XR_API_LAYER_PATH", (s.layer_dir.empty() ? std::string(GAZELOD_LAYER_MANIFEST_DIR) : s.layer_dir).c_str(),
           1);
    setenv("XR_ENABLE_API_LAYERS", "XR_APILAYER_GAZELOD_eye_gaze", 1);
  } else {
    unsetenv("XR_API_LAYER_PATH");
    unsetenv("XR_ENABLE_API_LAYERS");
  }
  if (s.trace.empty())
    unsetenv("GAZELOD_LAYER_TRACE");
  else
    setenv("GAZELOD_LAYER_TRACE", s.trace.c_str(), 1);
  if (s.config.empty())
    unsetenv("GAZELOD_LAYER_CONFIG");
  else
    setenv("GAZELOD_LAYER_CONFIG", s.config.c_str(), 1);
}

std::string scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(GAZELOD_BINARY_DIR) / "tests" / "layer" / "scratch" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::vector<gaze::TraceRecord> write_trace(const std::string& path, double seconds, double rate_hz, double blink_from_s,
                                           double blink_to_s) {
  {
    std::ofstream out(path);
    gaze::TraceWriterOptions o;
    o.write_head = false;
    gaze::TraceWriter w(out, o);
    const auto n = static_cast<int>(std::lround(seconds * rate_hz));
    for (int i = 0; i < n; ++i) {
      const double t = i / rate_hz;
      gaze::TraceRecord r;
      r.gaze.t_ns = static_cast<std::int64_t>(std::llround(t * 1e9));
      const double yaw = 8.0 * std::sin(2.0 * std::numbers::pi * 0.3 * t);
      const double pitch = 4.0 * std::sin(2.0 * std::numbers::pi * 0.2 * t + 1.0);
      r.gaze.direction = gaze::direction_from_yaw_pitch_deg(yaw, pitch);
      r.gaze.origin_m = {0.001, -0.002, 0.003};
      r.gaze.valid = !(t >= blink_from_s && t < blink_to_s);
      r.gaze.confidence = r.gaze.valid ? 1.0f : 0.0f;
      w.write(r);
    }
  }
  auto stream = gaze::open_trace(path, gaze::TraceFormat::gazelod);
  return gaze::ReplaySource::load(*stream);
}

std::optional<gaze::GazeSample> expected_gaze(const std::vector<gaze::TraceRecord>& records,
                                              std::int64_t first_frame_ns, std::int64_t t_ns) {
  gaze::ReplaySource replay(records);
  const std::int64_t offset = first_frame_ns - records.front().gaze.t_ns;
  auto s = replay.sample_at(t_ns - offset);
  if (s) s->t_ns += offset;
  return s;
}

std::string capture_stderr(const std::function<void()>& body) {
  char name[] = "/tmp/gazelod-layer-stderr-XXXXXX";
  const int fd = mkstemp(name);
  EXPECT_GE(fd, 0);
  std::fflush(stderr);
  const int saved = dup(2);
  dup2(fd, 2);
  body();
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  close(fd);
  std::ifstream in(name);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(name);
  return text.str();
}

int count_lines_with(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) n += line.find(needle) != std::string::npos ? 1 : 0;
  return n;
}

void GazeRig::create(bool eyes_subaction, bool extras) {
  std::vector<const char*> enabled = extensions;
  enabled.push_back(XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
  hs.create(enabled);
  ASSERT_NE(hs.session, XR_NULL_HANDLE);
  XrSystemEyeGazeInteractionPropertiesEXT eye{XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
  XrSystemProperties props{XR_TYPE_SYSTEM_PROPERTIES, &eye};
  XRRT_ASSERT_XR(xrGetSystemProperties(hs.instance, hs.system, &props));
  ASSERT_EQ(props.next, &eye);  // the chain the application built is given back intact
  supported = eye.supportsEyeGazeInteraction;

  XRRT_ASSERT_XR(xrStringToPath(hs.instance, "/user/eyes_ext", &eyes));
  XRRT_ASSERT_XR(xrStringToPath(hs.instance, "/interaction_profiles/ext/eye_gaze_interaction", &profile));
  XRRT_ASSERT_XR(xrStringToPath(hs.instance, "/user/eyes_ext/input/gaze_ext/pose", &pose_path));
  XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(set_info.actionSetName, "gaze");
  std::strcpy(set_info.localizedActionSetName, "Gaze");
  XRRT_ASSERT_XR(xrCreateActionSet(hs.instance, &set_info, &set));
  XrActionCreateInfo action_info{XR_TYPE_ACTION_CREATE_INFO};
  action_info.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strcpy(action_info.actionName, "gaze_pose");
  std::strcpy(action_info.localizedActionName, "Gaze pose");
  if (eyes_subaction) {
    action_info.countSubactionPaths = 1;
    action_info.subactionPaths = &eyes;
  }
  XRRT_ASSERT_XR(xrCreateAction(set, &action_info, &gaze));
  if (extras) {
    XrPath two[2] = {eyes, XR_NULL_PATH};
    XRRT_ASSERT_XR(xrStringToPath(hs.instance, "/user/hand/left", &two[1]));
    XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
    info.countSubactionPaths = 2;
    info.subactionPaths = two;
    info.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
    std::strcpy(info.actionName, "button");
    std::strcpy(info.localizedActionName, "Button");
    XRRT_ASSERT_XR(xrCreateAction(set, &info, &button));
    info.actionType = XR_ACTION_TYPE_POSE_INPUT;
    std::strcpy(info.actionName, "other_pose");
    std::strcpy(info.localizedActionName, "Other pose");
    XRRT_ASSERT_XR(xrCreateAction(set, &info, &other_pose));
  }
  const XrActionSuggestedBinding b{gaze, pose_path};
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

XrTime GazeRig::frame() {
  XrFrameState state{XR_TYPE_FRAME_STATE};
  EXPECT_EQ(xrWaitFrame(hs.session, nullptr, &state), XR_SUCCESS);
  EXPECT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = state.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  EXPECT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
  if (first_frame == 0) first_frame = state.predictedDisplayTime;
  return state.predictedDisplayTime;
}

XrResult GazeRig::sync() {
  return sync(XR_NULL_PATH);
}

XrResult GazeRig::sync(XrPath subaction) {
  XrActiveActionSet active{set, subaction};
  XrActionsSyncInfo info{XR_TYPE_ACTIONS_SYNC_INFO};
  info.countActiveActionSets = 1;
  info.activeActionSets = &active;
  return xrSyncActions(hs.session, &info);
}

bool GazeRig::active(XrPath subaction) {
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = gaze;
  get.subactionPath = subaction;
  XrActionStatePose state{XR_TYPE_ACTION_STATE_POSE};
  EXPECT_EQ(xrGetActionStatePose(hs.session, &get, &state), XR_SUCCESS);
  return state.isActive == XR_TRUE;
}

GazeRig::Located GazeRig::locate(XrSpace space, XrSpace base, XrTime t) {
  XrSpaceVelocity velocity{XR_TYPE_SPACE_VELOCITY};
  velocity.velocityFlags = XR_SPACE_VELOCITY_LINEAR_VALID_BIT;  // must be overwritten
  XrEyeGazeSampleTimeEXT sample{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT, &velocity};
  sample.time = -1;
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION, &sample};
  EXPECT_EQ(xrLocateSpace(space, base, t, &loc), XR_SUCCESS);
  return {loc.locationFlags, loc.pose, sample.time, velocity.velocityFlags};
}

int GazeRig::drain_profile_events() {
  int n = 0;
  for (;;) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    if (xrPollEvent(hs.instance, &event) != XR_SUCCESS) break;
    if (event.type == XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED) {
      EXPECT_EQ(reinterpret_cast<const XrEventDataInteractionProfileChanged&>(event).session, hs.session);
      ++n;
    } else if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      hs.states.push_back(reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state);
    }
  }
  return n;
}

XrPath GazeRig::current_profile() {
  XrInteractionProfileState state{XR_TYPE_INTERACTION_PROFILE_STATE};
  EXPECT_EQ(xrGetCurrentInteractionProfile(hs.session, eyes, &state), XR_SUCCESS);
  return state.interactionProfile;
}

glm::dvec3 direction_of(const XrPosef& pose) {
  const glm::dquat q(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
  return glm::normalize(q) * glm::dvec3(0.0, 0.0, -1.0);
}

double angle_rad(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace gazelod::layer_test
