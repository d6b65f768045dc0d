#include "plugin/openxr_gaze_source.hpp"

#include "plugin/xr_check.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace gazelod::plugin {
namespace {

void check(XrResult r, const char* call) { xr_check(r, call, "OpenXR eye gaze: "); }

XrPath path(XrInstance instance, const char* s) {
  XrPath p = XR_NULL_PATH;
  check(xrStringToPath(instance, s, &p), "xrStringToPath");
  return p;
}

}  // namespace

bool system_supports_eye_gaze(XrInstance instance, XrSystemId system) {
  XrSystemEyeGazeInteractionPropertiesEXT eye{XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
  XrSystemProperties props{XR_TYPE_SYSTEM_PROPERTIES};
  props.next = &eye;
  if (XR_FAILED(xrGetSystemProperties(instance, system, &props))) return false;
  return eye.supportsEyeGazeInteraction == XR_TRUE;
}

OpenXrGazeSource::OpenXrGazeSource(XrInstance instance, XrSession session)
    : instance_(instance), session_(session) {
  XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strncpy(set_info.actionSetName, "gazelod_eye_gaze", XR_MAX_ACTION_SET_NAME_SIZE - 1);
  std::strncpy(set_info.localizedActionSetName, "gazelod eye gaze", XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE - 1);
  check(xrCreateActionSet(instance_, &set_info, &action_set_), "xrCreateActionSet");

  XrActionCreateInfo action_info{XR_TYPE_ACTION_CREATE_INFO};
  action_info.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strncpy(action_info.actionName, "eye_gaze", XR_MAX_ACTION_NAME_SIZE - 1);
  std::strncpy(action_info.localizedActionName, "Eye gaze", XR_MAX_LOCALIZED_ACTION_NAME_SIZE - 1);
  check(xrCreateAction(action_set_, &action_info, &gaze_action_), "xrCreateAction");

  XrActionSuggestedBinding binding{gaze_action_, path(instance_, "/user/eyes_ext/input/gaze_ext/pose")};
  XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  suggested.interactionProfile = path(instance_, "/interaction_profiles/ext/eye_gaze_interaction");
  suggested.countSuggestedBindings = 1;
  suggested.suggestedBindings = &binding;
  check(xrSuggestInteractionProfileBindings(instance_, &suggested),
        "xrSuggestInteractionProfileBindings");

  XrReferenceSpaceCreateInfo view_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  view_info.poseInReferenceSpace.orientation.w = 1.0f;
  check(xrCreateReferenceSpace(session_, &view_info, &view_space_), "xrCreateReferenceSpace(VIEW)");
}

OpenXrGazeSource::~OpenXrGazeSource() {
  if (gaze_space_ != XR_NULL_HANDLE) xrDestroySpace(gaze_space_);
  if (view_space_ != XR_NULL_HANDLE) xrDestroySpace(view_space_);
  // Destroying the action set destroys its actions.
  if (action_set_ != XR_NULL_HANDLE) xrDestroyActionSet(action_set_);
}

void OpenXrGazeSource::create_space() {
  XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  info.action = gaze_action_;
  info.poseInActionSpace.orientation.w = 1.0f;
  check(xrCreateActionSpace(session_, &info, &gaze_space_), "xrCreateActionSpace");
  status_ = "waiting for the first gaze pose";
}

void OpenXrGazeSource::action_sets_attached() { create_space(); }

void OpenXrGazeSource::attach_and_own_sync() {
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &action_set_;
  check(xrAttachSessionActionSets(session_, &attach), "xrAttachSessionActionSets");
  own_sync_ = true;
  create_space();
}

std::optional<gaze::GazeSample> OpenXrGazeSource::sample_at(std::int64_t t_ns) {
  if (gaze_space_ == XR_NULL_HANDLE) return std::nullopt;
  if (own_sync_) {
    XrActiveActionSet active{action_set_, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    const XrResult r = xrSyncActions(session_, &sync);
    // SESSION_NOT_FOCUSED: inputs are inactive, which the locate below reports as invalid.
    if (XR_FAILED(r)) {
      status_ = "xrSyncActions failed";
      return std::nullopt;
    }
  }
  XrActionStatePose state{XR_TYPE_ACTION_STATE_POSE};
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = gaze_action_;
  if (XR_FAILED(xrGetActionStatePose(session_, &get, &state)) || !state.isActive) {
    status_ = ever_delivered_ ? "eye gaze action inactive" : "eye gaze action never active";
    return std::nullopt;
  }
  XrEyeGazeSampleTimeEXT sample_time{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  loc.next = &sample_time;
  if (XR_FAILED(xrLocateSpace(gaze_space_, view_space_, static_cast<XrTime>(t_ns), &loc))) {
    status_ = "xrLocateSpace(gaze) failed";
    return std::nullopt;
  }
  const XrSpaceLocationFlags need =
      XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  if ((loc.locationFlags & need) != need) {
    status_ = ever_delivered_ ? "gaze not tracked (blink or lost)" : "runtime has not delivered gaze";
    return std::nullopt;
  }
  const XrQuaternionf& q = loc.pose.orientation;
  const glm::dquat orientation(q.w, q.x, q.y, q.z);
  glm::dvec3 dir = orientation * glm::dvec3(0.0, 0.0, -1.0);
  const double len = glm::length(dir);
  if (!std::isfinite(len) || len < 1e-6) {
    status_ = "runtime delivered a degenerate gaze orientation";
    return std::nullopt;
  }
  gaze::GazeSample s;
  s.direction = dir / len;
  s.origin_m = {loc.pose.position.x, loc.pose.position.y, loc.pose.position.z};
  s.valid = true;
  s.confidence = 1.0f;
  // Runtimes differ (docs/runtime.md, Gaze quirks): some give 0, some echo the requested time.
  if (sample_time.time == 0) {
    s.t_ns = t_ns;
    sample_time_quality_ = "zero (untrusted; using the requested time)";
  } else if (sample_time.time == static_cast<XrTime>(t_ns)) {
    s.t_ns = t_ns;
    sample_time_quality_ = "requested time (untrusted)";
  } else {
    s.t_ns = static_cast<std::int64_t>(sample_time.time);
    sample_time_quality_ = "true sample time";
  }
  ever_delivered_ = true;
  status_ = "ok";
  return s;
}

}  // namespace gazelod::plugin
