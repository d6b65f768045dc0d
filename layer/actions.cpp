// SPDX-License-Identifier: Apache-2.0
// Actions and bindings for the emulated XR_EXT_eye_gaze_interaction: suggestions for
// /interaction_profiles/ext/eye_gaze_interaction are kept here (the runtime would refuse them);
// every other profile goes down. Attached actions bound to /user/eyes_ext/input/gaze_ext/pose
// are the gaze actions: active after an xrSyncActions that found fresh gaze with their set
// active and the session focused. The eye-gaze profile becomes /user/eyes_ext's current one at
// the first xrSyncActions after attaching (the only place a profile may change), which queues
// XrEventDataInteractionProfileChanged. The actions' states are read in action_state.cpp.
#include "layer/entry_points.hpp"
#include "layer/layer_state.hpp"

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace gazelod::layer {
namespace {

using Lock = std::lock_guard<std::mutex>;

EmulatedInstance* emulated() {
  return layer_state().emulated.get();
}

// xrDestroyActionSet: the set's actions can never be synced again.
void forget_action(EmulatedInstance& e, XrAction action) {
  e.actions.erase(action);
  std::erase(e.eye_bindings, action);
  for (auto& [handle, s] : e.sessions)
    if (auto it = s.gaze_actions.find(action); it != s.gaze_actions.end()) it->second.destroyed = true;
}

// xrDestroyAction: the handle may no longer be passed, but the action stays in its set (its
// gaze spaces keep locating while the set is synced).
void destroy_action_handle(EmulatedInstance& e, XrAction action) {
  if (auto it = e.actions.find(action); it != e.actions.end()) it->second.handle_destroyed = true;
  for (auto& [handle, s] : e.sessions)
    if (auto it = s.gaze_actions.find(action); it != s.gaze_actions.end()) it->second.destroyed = true;
}

}  // namespace

XrResult CreateActionSet(XrInstance instance, const XrActionSetCreateInfo* createInfo, XrActionSet* actionSet) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrCreateActionSet next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr || e->handle != instance) return XR_ERROR_HANDLE_INVALID;
      next = e->next.CreateActionSet;
    }
    const XrResult r = next(instance, createInfo, actionSet);
    if (XR_SUCCEEDED(r)) {
      Lock lock(layer_state().mutex);
      if (EmulatedInstance* e = emulated()) e->action_sets[*actionSet] = false;
    }
    return r;
  });
}

XrResult DestroyActionSet(XrActionSet actionSet) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrDestroyActionSet next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.DestroyActionSet;
    }
    const XrResult r = next(actionSet);
    if (XR_SUCCEEDED(r)) {
      Lock lock(layer_state().mutex);
      if (EmulatedInstance* e = emulated()) {
        std::vector<XrAction> members;
        for (const auto& [a, rec] : e->actions)
          if (rec.set == actionSet) members.push_back(a);
        for (XrAction a : members) forget_action(*e, a);
        e->action_sets.erase(actionSet);
      }
    }
    return r;
  });
}

XrResult CreateAction(XrActionSet actionSet, const XrActionCreateInfo* createInfo, XrAction* action) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrCreateAction next = nullptr;
    XrPath eyes = XR_NULL_PATH;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.CreateAction;
      eyes = e->paths.eyes_user;
    }
    if (createInfo == nullptr || (createInfo->countSubactionPaths > 0 && createInfo->subactionPaths == nullptr))
      return next(actionSet, createInfo, action);
    // /user/eyes_ext is this layer's top-level path: the runtime does not know it.
    std::vector<XrPath> kept;
    bool eyes_subaction = false;
    for (uint32_t i = 0; i < createInfo->countSubactionPaths; ++i) {
      if (createInfo->subactionPaths[i] == eyes && eyes != XR_NULL_PATH)
        eyes_subaction = true;
      else
        kept.push_back(createInfo->subactionPaths[i]);
    }
    XrActionCreateInfo down = *createInfo;
    down.countSubactionPaths = static_cast<uint32_t>(kept.size());
    down.subactionPaths = kept.empty() ? nullptr : kept.data();
    const XrResult r = next(actionSet, &down, action);
    if (XR_SUCCEEDED(r)) {
      Lock lock(layer_state().mutex);
      if (EmulatedInstance* e = emulated()) e->actions[*action] = {actionSet, createInfo->actionType, eyes_subaction};
    }
    return r;
  });
}

XrResult DestroyAction(XrAction action) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrDestroyAction next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.DestroyAction;
    }
    const XrResult r = next(action);
    if (XR_SUCCEEDED(r)) {
      Lock lock(layer_state().mutex);
      if (EmulatedInstance* e = emulated()) destroy_action_handle(*e, action);
    }
    return r;
  });
}

XrResult SuggestInteractionProfileBindings(XrInstance instance, const XrInteractionProfileSuggestedBinding* suggested) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrSuggestInteractionProfileBindings next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr || e->handle != instance) return XR_ERROR_HANDLE_INVALID;
      next = e->next.SuggestInteractionProfileBindings;
      if (suggested != nullptr && suggested->type == XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING &&
          suggested->interactionProfile == e->paths.eye_profile && e->paths.eye_profile != XR_NULL_PATH) {
        if (suggested->countSuggestedBindings == 0 || suggested->suggestedBindings == nullptr)
          return XR_ERROR_VALIDATION_FAILURE;
        std::vector<XrAction> actions;
        for (uint32_t i = 0; i < suggested->countSuggestedBindings; ++i) {
          const XrActionSuggestedBinding& b = suggested->suggestedBindings[i];
          const ActionRecord* it = live_action(*e, b.action);
          if (it == nullptr) return XR_ERROR_HANDLE_INVALID;
          if (auto set = e->action_sets.find(it->set); set != e->action_sets.end() && set->second)
            return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
          // The profile has one input, a pose.
          if (b.binding != e->paths.gaze_pose || it->type != XR_ACTION_TYPE_POSE_INPUT)
            return XR_ERROR_PATH_UNSUPPORTED;
          actions.push_back(b.action);
        }
        e->eye_bindings = std::move(actions);  // a new suggestion replaces the last one
        return XR_SUCCESS;
      }
    }
    return next(instance, suggested);
  });
}

XrResult AttachSessionActionSets(XrSession session, const XrSessionActionSetsAttachInfo* attachInfo) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrAttachSessionActionSets next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.AttachSessionActionSets;
    }
    const XrResult r = next(session, attachInfo);
    if (XR_FAILED(r) || attachInfo == nullptr || attachInfo->actionSets == nullptr) return r;
    Lock lock(layer_state().mutex);
    EmulatedInstance* e = emulated();
    if (e == nullptr) return r;
    auto s = e->sessions.find(session);
    if (s == e->sessions.end()) return r;
    s->second.attached = true;
    for (uint32_t i = 0; i < attachInfo->countActionSets; ++i) {
      const XrActionSet set = attachInfo->actionSets[i];
      e->action_sets[set] = true;
      for (XrAction a : e->eye_bindings) {
        auto rec = e->actions.find(a);
        if (rec != e->actions.end() && rec->second.set == set)
          s->second.gaze_actions[a] = GazeActionState{false, false, rec->second.eyes_subaction};
      }
    }
    return r;
  });
}

XrResult SyncActions(XrSession session, const XrActionsSyncInfo* syncInfo) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrSyncActions next = nullptr;
    XrPath eyes = XR_NULL_PATH;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.SyncActions;
      eyes = e->paths.eyes_user;
    }
    // A set made active for /user/eyes_ext only: the runtime knows no such path, and none of
    // its own bindings are under it, so that entry does not go down.
    XrActionsSyncInfo down_info{};
    std::vector<XrActiveActionSet> down_sets;
    const XrActionsSyncInfo* down = syncInfo;
    if (syncInfo != nullptr && syncInfo->activeActionSets != nullptr && eyes != XR_NULL_PATH) {
      for (uint32_t i = 0; i < syncInfo->countActiveActionSets; ++i)
        if (syncInfo->activeActionSets[i].subactionPath != eyes) down_sets.push_back(syncInfo->activeActionSets[i]);
      if (down_sets.size() != syncInfo->countActiveActionSets) {
        down_info = *syncInfo;
        down_info.countActiveActionSets = static_cast<uint32_t>(down_sets.size());
        down_info.activeActionSets = down_sets.empty() ? nullptr : down_sets.data();
        down = &down_info;
      }
    }
    const XrResult r = next(session, down);
    if (XR_FAILED(r) || syncInfo == nullptr) return r;
    Lock lock(layer_state().mutex);
    EmulatedInstance* e = emulated();
    if (e == nullptr) return r;
    auto s = e->sessions.find(session);
    if (s == e->sessions.end() || s->second.gaze_actions.empty()) return r;
    SessionRecord& rec = s->second;
    const bool focused = r == XR_SUCCESS;  // XR_SESSION_NOT_FOCUSED: every action inactive
    const bool fresh = focused && e->gaze_available && e->feed && e->feed->fresh();
    for (auto& [action, state] : rec.gaze_actions) {
      bool set_active = false;
      const auto a = e->actions.find(action);
      for (uint32_t i = 0; i < syncInfo->countActiveActionSets && a != e->actions.end(); ++i) {
        const XrActiveActionSet& active = syncInfo->activeActionSets[i];
        set_active = set_active || (active.actionSet == a->second.set && (active.subactionPath == XR_NULL_PATH ||
                                                                          active.subactionPath == e->paths.eyes_user));
      }
      state.active = fresh && set_active;  // a destroyed handle's action still syncs
    }
    if (!rec.profile_current && e->gaze_available) {
      rec.profile_current = true;
      e->profile_events.push_back(session);
    }
    return r;
  });
}

XrResult GetCurrentInteractionProfile(XrSession session, XrPath topLevelUserPath,
                                      XrInteractionProfileState* interactionProfile) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrGetCurrentInteractionProfile next = nullptr;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.GetCurrentInteractionProfile;
      if (topLevelUserPath == e->paths.eyes_user && topLevelUserPath != XR_NULL_PATH) {
        auto s = e->sessions.find(session);
        if (s == e->sessions.end()) return XR_ERROR_HANDLE_INVALID;
        if (interactionProfile == nullptr || interactionProfile->type != XR_TYPE_INTERACTION_PROFILE_STATE)
          return XR_ERROR_VALIDATION_FAILURE;
        if (!s->second.attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
        interactionProfile->interactionProfile = s->second.profile_current ? e->paths.eye_profile : XR_NULL_PATH;
        return XR_SUCCESS;
      }
    }
    return next(session, topLevelUserPath, interactionProfile);
  });
}

XrResult EnumerateBoundSourcesForAction(XrSession session, const XrBoundSourcesForActionEnumerateInfo* enumerateInfo,
                                        uint32_t capacity, uint32_t* count, XrPath* sources) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrEnumerateBoundSourcesForAction next = nullptr;
    XrPath extra = XR_NULL_PATH;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.EnumerateBoundSourcesForAction;
      SessionRecord* rec = nullptr;
      if (enumerateInfo != nullptr && gaze_action(*e, session, enumerateInfo->action, &rec) != nullptr &&
          rec->profile_current)
        extra = e->paths.gaze_pose;
    }
    if (extra == XR_NULL_PATH) return next(session, enumerateInfo, capacity, count, sources);
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    // The runtime's own sources (none, usually), then the gaze pose.
    uint32_t below = 0;
    XrResult r = next(session, enumerateInfo, 0, &below, nullptr);
    if (XR_FAILED(r)) return r;
    *count = below + 1;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < below + 1) return XR_ERROR_SIZE_INSUFFICIENT;
    if (sources == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    if (below > 0) {
      r = next(session, enumerateInfo, below, &below, sources);
      if (XR_FAILED(r)) return r;
    }
    sources[below] = extra;
    *count = below + 1;
    return XR_SUCCESS;
  });
}

XrResult GetInputSourceLocalizedName(XrSession session, const XrInputSourceLocalizedNameGetInfo* getInfo,
                                     uint32_t capacity, uint32_t* count, char* buffer) {
  return guarded(XR_ERROR_RUNTIME_FAILURE, [&]() -> XrResult {
    PFN_xrGetInputSourceLocalizedName next = nullptr;
    bool ours = false;
    {
      Lock lock(layer_state().mutex);
      EmulatedInstance* e = emulated();
      if (e == nullptr) return XR_ERROR_HANDLE_INVALID;
      next = e->next.GetInputSourceLocalizedName;
      ours = getInfo != nullptr && getInfo->sourcePath == e->paths.gaze_pose && e->paths.gaze_pose != XR_NULL_PATH;
      if (ours && e->sessions.count(session) == 0) return XR_ERROR_HANDLE_INVALID;
    }
    if (!ours) return next(session, getInfo, capacity, count, buffer);
    if (count == nullptr || getInfo->type != XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO ||
        getInfo->whichComponents == 0)
      return XR_ERROR_VALIDATION_FAILURE;
    std::string name;
    auto add = [&](XrInputSourceLocalizedNameFlags bit, const char* part) {
      if ((getInfo->whichComponents & bit) == 0) return;
      if (!name.empty()) name += ' ';
      name += part;
    };
    add(XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT, "Eyes");
    add(XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT, "Eye Gaze Interaction");
    add(XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT, "Gaze Pose");
    const auto needed = static_cast<uint32_t>(name.size() + 1);
    *count = needed;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < needed) return XR_ERROR_SIZE_INSUFFICIENT;
    if (buffer == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::memcpy(buffer, name.c_str(), needed);
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::layer
