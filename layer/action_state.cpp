// SPDX-License-Identifier: Apache-2.0
// Action state queries for the emulated XR_EXT_eye_gaze_interaction: a gaze action is active
// after an xrSyncActions that found fresh gaze (actions.cpp), and /user/eyes_ext, a top-level
// path only this layer knows, is answered here for every action type (the eye-gaze profile has
// one input, a pose) so that the runtime never sees it.
#include "layer/entry_points.hpp"
#include "layer/layer_state.hpp"

#include <optional>
#include <type_traits>

namespace gazelod::layer {
namespace {

using Lock = std::lock_guard<std::mutex>;

EmulatedInstance* emulated() {
  return layer_state().emulated.get();
}

// Queries with the subaction path /user/eyes_ext, which only this layer knows: the runtime
// must not see it. An action created with it gets an answer here; one created without it,
// XR_ERROR_PATH_UNSUPPORTED, as from a runtime; nullopt: not such a query, pass it down.
template <typename State>
std::optional<XrResult> eyes_query(XrStructureType type, XrSession session, const XrActionStateGetInfo* getInfo,
                                   State* state) {
  Lock lock(layer_state().mutex);
  EmulatedInstance* e = emulated();
  if (e == nullptr || getInfo == nullptr || getInfo->subactionPath == XR_NULL_PATH ||
      getInfo->subactionPath != e->paths.eyes_user)
    return std::nullopt;
  const ActionRecord* a = live_action(*e, getInfo->action);
  if (a == nullptr) return std::nullopt;  // not an action of this instance: the runtime says so
  if (state == nullptr || state->type != type) return XR_ERROR_VALIDATION_FAILURE;
  if (!a->eyes_subaction) return XR_ERROR_PATH_UNSUPPORTED;
  const GazeActionState* g = gaze_action(*e, session, getInfo->action, nullptr);
  // The eye-gaze profile has one input, a pose: nothing else is bound to /user/eyes_ext.
  void* next = state->next;
  *state = State{};
  state->type = type;
  state->next = next;
  if constexpr (std::is_same_v<State, XrActionStatePose>) state->isActive = g != nullptr && g->active;
  return XR_SUCCESS;
}

// The other action types, only for /user/eyes_ext (eyes_query); everything else goes down.
template <typename State, typename Next>
XrResult other_state(XrStructureType type, XrSession session, const XrActionStateGetInfo* getInfo, State* state,
                     Next NextDispatch::*member) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    if (auto r = eyes_query(type, session, getInfo, state)) return *r;
    Next next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.*member;
    }
    return next(session, getInfo, state);
  });
}

}  // namespace

XrResult GetActionStatePose(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStatePose* state) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    if (auto r = eyes_query(XR_TYPE_ACTION_STATE_POSE, session, getInfo, state)) return *r;
    PFN_xrGetActionStatePose next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.GetActionStatePose;
      const GazeActionState* g = getInfo ? gaze_action(*e, session, getInfo->action, nullptr) : nullptr;
      // Gaze inactive: the runtime may still have a binding of its own for the action.
      if (g != nullptr && g->active && getInfo->subactionPath == XR_NULL_PATH) {
        if (state == nullptr || state->type != XR_TYPE_ACTION_STATE_POSE) return XR_ERROR_VALIDATION_FAILURE;
        state->isActive = XR_TRUE;
        return XR_SUCCESS;
      }
    }
    return next(session, getInfo, state);
  });
}

XrResult GetActionStateBoolean(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateBoolean* state) {
  return other_state(XR_TYPE_ACTION_STATE_BOOLEAN, session, getInfo, state, &NextDispatch::GetActionStateBoolean);
}

XrResult GetActionStateFloat(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateFloat* state) {
  return other_state(XR_TYPE_ACTION_STATE_FLOAT, session, getInfo, state, &NextDispatch::GetActionStateFloat);
}

XrResult GetActionStateVector2f(XrSession session, const XrActionStateGetInfo* getInfo, XrActionStateVector2f* state) {
  return other_state(XR_TYPE_ACTION_STATE_VECTOR2F, session, getInfo, state, &NextDispatch::GetActionStateVector2f);
}

}  // namespace gazelod::layer
