// SPDX-License-Identifier: Apache-2.0
// The layer's bookkeeping, all behind one mutex (any command may come from any thread; the HID
// source's reader thread only ever touches its own queue): the instance it emulates eye gaze
// for, that instance's actions and eye-gaze bindings, its sessions (attached action sets, the
// gaze actions' active state from the last xrSyncActions, the interaction profile of
// /user/eyes_ext), the layer-owned gaze spaces, and the events it owes the application.
//
// One emulating instance at a time, as the Khronos loader 1.0.20 allows one instance at a
// time; instances the layer passes through need no state beyond their next xrGetInstanceProcAddr.
#pragma once

#include "layer/dispatch_table.hpp"
#include "layer/gaze_feed.hpp"
#include "layer/pose_math.hpp"

#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace gazelod::layer {

struct Paths {
  XrPath eyes_user = XR_NULL_PATH;    // /user/eyes_ext
  XrPath gaze_pose = XR_NULL_PATH;    // /user/eyes_ext/input/gaze_ext/pose
  XrPath eye_profile = XR_NULL_PATH;  // /interaction_profiles/ext/eye_gaze_interaction
};

struct ActionRecord {
  XrActionSet set = XR_NULL_HANDLE;
  XrActionType type = XR_ACTION_TYPE_POSE_INPUT;
  bool eyes_subaction = false;  // created with /user/eyes_ext among its subaction paths
  // xrDestroyAction: the handle is gone, the action is not (its spaces stay locatable and it
  // still takes part in xrSyncActions, as the specification requires).
  bool handle_destroyed = false;
};

struct GazeActionState {
  bool active = false;     // as of the last xrSyncActions
  bool destroyed = false;  // its handle was destroyed (xrDestroyAction); it and its spaces live on
  bool eyes_subaction = false;
};

// A gaze space's handle is a VIEW reference space the layer created on the runtime: a unique,
// valid handle (xrDestroySpace, session teardown work unchanged) that locates the head.
struct GazeSpace {
  XrSession session = XR_NULL_HANDLE;
  XrAction action = XR_NULL_HANDLE;
  Pose pose_in_action;
  std::optional<Pose> last_layer_eye;  // the eye a composition layer in this space was last placed by
};

struct SessionRecord {
  bool attached = false;
  std::unordered_map<XrAction, GazeActionState> gaze_actions;  // attached, bound to the eye profile
  bool profile_current = false;  // /user/eyes_ext -> the eye-gaze profile (from an xrSyncActions)
  bool frames_started = false;
  std::int64_t last_display_time_ns = 0;
};

struct EmulatedInstance {
  XrInstance handle = XR_NULL_HANDLE;
  NextDispatch next;
  bool gaze_available = false;
  Paths paths;
  Pose tracker_in_head;
  std::unique_ptr<GazeFeed> feed;                     // null without gaze
  std::unordered_map<XrActionSet, bool> action_sets;  // -> attached to some session
  std::unordered_map<XrAction, ActionRecord> actions;
  std::vector<XrAction> eye_bindings;  // the last suggestion for the eye-gaze profile
  std::unordered_map<XrSession, SessionRecord> sessions;
  std::unordered_map<XrSpace, GazeSpace> gaze_spaces;
  std::deque<XrSession> profile_events;  // XrEventDataInteractionProfileChanged owed
};

struct LayerState {
  std::mutex mutex;
  std::unique_ptr<EmulatedInstance> emulated;
  std::unordered_map<XrInstance, PFN_xrGetInstanceProcAddr> passed_through;
  PFN_xrGetInstanceProcAddr last_next_gipa = nullptr;  // for calls with no instance
};

LayerState& layer_state();

// The session's gaze action `action`, if it is one whose handle is valid (record: its session).
GazeActionState* gaze_action(EmulatedInstance& e, XrSession session, XrAction action, SessionRecord** record);
// The action's record while its handle is valid.
const ActionRecord* live_action(const EmulatedInstance& e, XrAction action);

// One line on stderr: "gazelod layer: <line>".
void log_line(const std::string& line);

// Runs `body`, turning any C++ exception into `failure` (none may cross the C ABI).
template <class F>
XrResult guarded(XrResult failure, F&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return XR_ERROR_OUT_OF_MEMORY;
  } catch (...) {
    return failure;
  }
}

}  // namespace gazelod::layer
