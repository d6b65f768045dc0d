// SPDX-License-Identifier: Apache-2.0
// Eye gaze from XR_EXT_eye_gaze_interaction (plugin/openxr_gaze_source.hpp).
#include "plugin/openxr_gaze_source.hpp"

#include "plugin/xr_check.hpp"
#include "xr/eye_gaze_paths.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>

namespace gazelod::plugin {
namespace {

void check(XrResult r, const char* call) {
  xr_check(r, call, "gazelod: eye gaze: ");
}

XrPath path(const XrDispatch& xr, XrInstance instance, const char* s) {
  XrPath p = XR_NULL_PATH;
  check(xr.string_to_path(instance, s, &p), "xrStringToPath");
  return p;
}

}  // namespace

bool system_supports_eye_gaze(const XrDispatch& xr, XrInstance instance, XrSystemId system) {
  XrSystemEyeGazeInteractionPropertiesEXT eye{XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
  XrSystemProperties props{XR_TYPE_SYSTEM_PROPERTIES};
  props.next = &eye;
  if (XR_FAILED(xr.get_system_properties(instance, system, &props))) return false;
  return eye.supportsEyeGazeInteraction == XR_TRUE;
}

OpenXrGazeSource::OpenXrGazeSource(const XrDispatch& xr, XrInstance instance, XrSession session, GazeInputMode mode,
                                   XrSpace gaze_space, XrAction gaze_action)
    : xr_(xr), instance_(instance), session_(session), mode_(mode) {
  // A throwing constructor runs no destructor: what create() made before the failing call (the
  // VIEW space, the action set) is released here.
  try {
    create(gaze_space, gaze_action);
  } catch (...) {
    release();
    throw;
  }
}

void OpenXrGazeSource::create(XrSpace gaze_space, XrAction gaze_action) {
  XrReferenceSpaceCreateInfo view_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  view_info.poseInReferenceSpace.orientation.w = 1.0f;
  check(xr_.create_reference_space(session_, &view_info, &view_space_), "xrCreateReferenceSpace(VIEW)");
  if (mode_ == GazeInputMode::app_space) {
    attached_ = true;
    set_app_space(gaze_space, gaze_action);
    return;
  }
  XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strncpy(set_info.actionSetName, "gazelod_eye_gaze", XR_MAX_ACTION_SET_NAME_SIZE - 1);
  std::strncpy(set_info.localizedActionSetName, "gazelod eye gaze", XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE - 1);
  check(xr_.create_action_set(instance_, &set_info, &action_set_), "xrCreateActionSet");

  XrActionCreateInfo action_info{XR_TYPE_ACTION_CREATE_INFO};
  action_info.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::strncpy(action_info.actionName, "eye_gaze", XR_MAX_ACTION_NAME_SIZE - 1);
  std::strncpy(action_info.localizedActionName, "Eye gaze", XR_MAX_LOCALIZED_ACTION_NAME_SIZE - 1);
  check(xr_.create_action(action_set_, &action_info, &gaze_action_), "xrCreateAction");
  if (mode_ == GazeInputMode::merge_binding) return;

  XrActionSuggestedBinding binding{gaze_action_, path(xr_, instance_, xr::kGazePosePath)};
  XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
  suggested.interactionProfile = path(xr_, instance_, xr::kEyeGazeProfile);
  suggested.countSuggestedBindings = 1;
  suggested.suggestedBindings = &binding;
  const XrResult r = xr_.suggest_interaction_profile_bindings(instance_, &suggested);
  if (r == XR_ERROR_ACTIONSETS_ALREADY_ATTACHED)
    throw XrCallError(
        "gazelod: eye gaze: the application attached its action sets already, so gazelod cannot add "
        "its own; create gazelod before xrAttachSessionActionSets (GZL_GAZE_INPUT_MERGE_BINDING) or "
        "pass your gaze action space (GZL_GAZE_INPUT_APP_SPACE)",
        r);
  check(r, "xrSuggestInteractionProfileBindings");
}

OpenXrGazeSource::~OpenXrGazeSource() {
  release();
}

void OpenXrGazeSource::release() {
  if (mode_ != GazeInputMode::app_space && gaze_space_ != XR_NULL_HANDLE) xr_.destroy_space(gaze_space_);
  gaze_space_ = XR_NULL_HANDLE;
  if (view_space_ != XR_NULL_HANDLE) xr_.destroy_space(view_space_);
  view_space_ = XR_NULL_HANDLE;
  // Destroying the action set destroys its actions.
  if (action_set_ != XR_NULL_HANDLE) xr_.destroy_action_set(action_set_);
  action_set_ = XR_NULL_HANDLE;
  if (mode_ != GazeInputMode::app_space) gaze_action_ = XR_NULL_HANDLE;
  status_ = "shut down";
}

void OpenXrGazeSource::set_app_space(XrSpace gaze_space, XrAction gaze_action) {
  gaze_space_ = gaze_space;
  gaze_action_ = gaze_action;
  ever_delivered_ = false;
  status_ =
      gaze_space == XR_NULL_HANDLE ? "no gaze space given yet (gzl_set_gaze_space)" : "waiting for the first gaze pose";
}

void OpenXrGazeSource::create_space() {
  XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
  info.action = gaze_action_;
  info.poseInActionSpace.orientation.w = 1.0f;
  check(xr_.create_action_space(session_, &info, &gaze_space_), "xrCreateActionSpace");
  attached_ = true;
  status_ = "waiting for the first gaze pose";
}

void OpenXrGazeSource::action_sets_attached() {
  if (mode_ == GazeInputMode::merge_binding && gaze_space_ == XR_NULL_HANDLE) create_space();
}

void OpenXrGazeSource::attach_and_own_sync() {
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &action_set_;
  const XrResult r = xr_.attach_session_action_sets(session_, &attach);
  if (r == XR_ERROR_ACTIONSETS_ALREADY_ATTACHED)
    throw XrCallError(
        "gazelod: eye gaze: the session's action sets are attached already (a session takes one "
        "xrAttachSessionActionSets); pass your gaze action space (GZL_GAZE_INPUT_APP_SPACE) or create "
        "gazelod before attaching and merge its binding (GZL_GAZE_INPUT_MERGE_BINDING)",
        r);
  check(r, "xrAttachSessionActionSets");
  own_sync_ = true;
  create_space();
}

// Our action inactive while the eyes' device is active under the eye-gaze profile: the
// binding was replaced by the application's own suggestion for that profile (a second
// suggestion for a profile replaces the first). Checked once, after a few inactive frames.
void OpenXrGazeSource::check_binding() {
  if (binding_lost_ || mode_ == GazeInputMode::app_space || ++inactive_calls_ != 10) return;
  XrInteractionProfileState profile{XR_TYPE_INTERACTION_PROFILE_STATE};
  XrPath eyes = XR_NULL_PATH;
  if (XR_FAILED(xr_.string_to_path(instance_, xr::kEyesUserPath, &eyes))) return;
  if (XR_FAILED(xr_.get_current_interaction_profile(session_, eyes, &profile))) return;
  XrPath eye_profile = XR_NULL_PATH;
  if (XR_FAILED(xr_.string_to_path(instance_, xr::kEyeGazeProfile, &eye_profile)) ||
      profile.interactionProfile != eye_profile)
    return;
  XrBoundSourcesForActionEnumerateInfo info{XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO};
  info.action = gaze_action_;
  std::uint32_t n = 0;
  if (XR_FAILED(xr_.enumerate_bound_sources_for_action(session_, &info, 0, &n, nullptr)) || n != 0) return;
  binding_lost_ = true;
  status_ = std::string("gazelod's eye-gaze binding was replaced by the application's own suggestion for ") +
            xr::kEyeGazeProfile +
            "; merge gazelod's binding into that suggestion (GZL_GAZE_INPUT_MERGE_BINDING) or pass "
            "your gaze action space (GZL_GAZE_INPUT_APP_SPACE)";
}

std::optional<gaze::GazeSample> OpenXrGazeSource::sample_at(std::int64_t t_ns) {
  if (gaze_space_ == XR_NULL_HANDLE || view_space_ == XR_NULL_HANDLE) return std::nullopt;
  if (own_sync_) {
    XrActiveActionSet active{action_set_, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    const XrResult r = xr_.sync_actions(session_, &sync);
    // SESSION_NOT_FOCUSED: inputs are inactive, which the locate below reports as invalid.
    if (XR_FAILED(r)) {
      status_ = "xrSyncActions failed";
      return std::nullopt;
    }
  }
  if (gaze_action_ != XR_NULL_HANDLE) {
    XrActionStatePose state{XR_TYPE_ACTION_STATE_POSE};
    XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
    get.action = gaze_action_;
    if (XR_FAILED(xr_.get_action_state_pose(session_, &get, &state)) || !state.isActive) {
      if (!binding_lost_) status_ = ever_delivered_ ? "eye gaze action inactive" : "eye gaze action never active";
      if (!ever_delivered_) check_binding();
      return std::nullopt;
    }
  }
  XrEyeGazeSampleTimeEXT sample_time{XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT};
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  loc.next = &sample_time;
  if (XR_FAILED(xr_.locate_space(gaze_space_, view_space_, static_cast<XrTime>(t_ns), &loc))) {
    status_ = "xrLocateSpace(gaze) failed";
    return std::nullopt;
  }
  const XrSpaceLocationFlags need = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  if ((loc.locationFlags & need) != need) {
    status_ = ever_delivered_ ? "gaze not tracked (blink or lost)" : "runtime has not delivered gaze";
    if (!ever_delivered_) return std::nullopt;
    // A blink or a short loss: an invalid sample, which the arbiter bridges and the conditioner
    // holds through (gaze_arbiter.hpp, blink_bridge_ns).
    gaze::GazeSample blink;
    blink.valid = false;
    blink.t_ns = sample_time.time > 0 ? static_cast<std::int64_t>(sample_time.time) : t_ns;
    return blink;
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
