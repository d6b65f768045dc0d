// SPDX-License-Identifier: Apache-2.0
// Action sets, actions, suggested bindings, attaching to a session and the current
// interaction profile (OpenXR 1.0 chapter 11 "Input and Haptics").
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/events.hpp"
#include "sim/runtime/interaction_profiles.hpp"
#include "sim/runtime/runtime_state.hpp"
#include "xr/eye_gaze_paths.hpp"

#include <algorithm>
#include <cstring>
#include <string>

namespace gazelod::xrrt {
namespace {

std::string bounded(const char* s, std::size_t cap) {
  return std::string(s, strnlen(s, cap));
}

bool any_set_attached(const Instance& inst) {
  for (const auto& [id, set] : runtime().action_sets.live)
    if (set->instance_id == inst.id && set->attached) return true;
  return false;
}

}  // namespace

XrResult CreateActionSet(XrInstance instance, const XrActionSetCreateInfo* info, XrActionSet* actionSet) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || actionSet == nullptr || info->type != XR_TYPE_ACTION_SET_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    const std::string name = bounded(info->actionSetName, XR_MAX_ACTION_SET_NAME_SIZE);
    const std::string localized = bounded(info->localizedActionSetName, XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE);
    if (name.empty()) return XR_ERROR_NAME_INVALID;
    if (!is_well_formed_name(name)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (localized.empty()) return XR_ERROR_LOCALIZED_NAME_INVALID;
    Runtime& rt = runtime();
    for (const auto& [id, s] : rt.action_sets.live) {
      if (s->instance_id != inst->id) continue;
      if (s->name == name) return XR_ERROR_NAME_DUPLICATED;
      if (s->localized_name == localized) return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
    }
    auto set = std::make_unique<ActionSet>();
    set->id = rt.next_id++;
    set->instance_id = inst->id;
    set->name = name;
    set->localized_name = localized;
    set->priority = info->priority;
    *actionSet = to_handle<XrActionSet>(set->id);
    rt.action_sets.live.emplace(set->id, std::move(set));
    return XR_SUCCESS;
  });
}

XrResult DestroyActionSet(XrActionSet actionSet) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_action_set(actionSet) == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_action_set(handle_id(actionSet));
    return XR_SUCCESS;
  });
}

XrResult CreateAction(XrActionSet actionSet, const XrActionCreateInfo* info, XrAction* action) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    ActionSet* set = find_action_set(actionSet);
    if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || action == nullptr || info->type != XR_TYPE_ACTION_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    if (set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    switch (info->actionType) {
      case XR_ACTION_TYPE_BOOLEAN_INPUT:
      case XR_ACTION_TYPE_FLOAT_INPUT:
      case XR_ACTION_TYPE_VECTOR2F_INPUT:
      case XR_ACTION_TYPE_POSE_INPUT:
      case XR_ACTION_TYPE_VIBRATION_OUTPUT:
        break;
      default:
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const std::string name = bounded(info->actionName, XR_MAX_ACTION_NAME_SIZE);
    const std::string localized = bounded(info->localizedActionName, XR_MAX_LOCALIZED_ACTION_NAME_SIZE);
    if (name.empty()) return XR_ERROR_NAME_INVALID;
    if (!is_well_formed_name(name)) return XR_ERROR_PATH_FORMAT_INVALID;
    if (localized.empty()) return XR_ERROR_LOCALIZED_NAME_INVALID;
    Instance* inst = runtime().instances.find(set->instance_id);
    std::vector<XrPath> subactions;
    for (std::uint32_t i = 0; i < info->countSubactionPaths; ++i) {
      if (info->subactionPaths == nullptr) return XR_ERROR_VALIDATION_FAILURE;
      const std::string* p = inst->paths.find(info->subactionPaths[i]);
      if (p == nullptr) return XR_ERROR_PATH_INVALID;
      if (!is_top_level_user_path(*p)) return XR_ERROR_PATH_UNSUPPORTED;
      // /user/eyes_ext exists only with XR_EXT_eye_gaze_interaction enabled.
      if (*p == xr::kEyesUserPath && !inst->ext_eye_gaze) return XR_ERROR_PATH_UNSUPPORTED;
      if (std::find(subactions.begin(), subactions.end(), info->subactionPaths[i]) != subactions.end())
        return XR_ERROR_PATH_UNSUPPORTED;  // duplicates
      subactions.push_back(info->subactionPaths[i]);
    }
    Runtime& rt = runtime();
    for (const auto& [id, a] : rt.actions.live) {
      if (a->set_id != set->id) continue;
      if (a->name == name) return XR_ERROR_NAME_DUPLICATED;
      if (a->localized_name == localized) return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
    }
    auto a = std::make_unique<Action>();
    a->id = rt.next_id++;
    a->set_id = set->id;
    a->instance_id = set->instance_id;
    a->name = name;
    a->localized_name = localized;
    a->type = info->actionType;
    for (XrPath p : subactions)
      if (std::find(set->subaction_paths.begin(), set->subaction_paths.end(), p) == set->subaction_paths.end())
        set->subaction_paths.push_back(p);
    a->subaction_paths = std::move(subactions);
    *action = to_handle<XrAction>(a->id);
    rt.actions.live.emplace(a->id, std::move(a));
    return XR_SUCCESS;
  });
}

XrResult DestroyAction(XrAction action) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_action(action) == nullptr) return XR_ERROR_HANDLE_INVALID;
    runtime().actions.live.erase(handle_id(action));
    return XR_SUCCESS;
  });
}

XrResult SuggestInteractionProfileBindings(XrInstance instance, const XrInteractionProfileSuggestedBinding* s) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (s == nullptr || s->type != XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING) return XR_ERROR_VALIDATION_FAILURE;
    if (s->countSuggestedBindings == 0 || s->suggestedBindings == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const std::string* profile_path = inst->paths.find(s->interactionProfile);
    if (profile_path == nullptr) return XR_ERROR_PATH_INVALID;
    const InteractionProfile* profile = find_profile(*profile_path);
    if (profile == nullptr || (profile->needs_eye_gaze_extension && !inst->ext_eye_gaze))
      return XR_ERROR_PATH_UNSUPPORTED;
    std::vector<std::pair<std::uint64_t, XrPath>> bindings;
    for (std::uint32_t i = 0; i < s->countSuggestedBindings; ++i) {
      const XrActionSuggestedBinding& b = s->suggestedBindings[i];
      const Action* a = find_action(b.action);
      if (a == nullptr || a->instance_id != inst->id) return XR_ERROR_HANDLE_INVALID;
      const std::string* path = inst->paths.find(b.binding);
      if (path == nullptr) return XR_ERROR_PATH_INVALID;
      if (!profile_has_binding(*profile, *path)) return XR_ERROR_PATH_UNSUPPORTED;
      const ActionSet* set = runtime().action_sets.find(a->set_id);
      if (set != nullptr && set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
      bindings.emplace_back(a->id, b.binding);
    }
    if (any_set_attached(*inst)) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    inst->suggested[s->interactionProfile] = std::move(bindings);  // replaces earlier suggestions
    return XR_SUCCESS;
  });
}

XrResult AttachSessionActionSets(XrSession session, const XrSessionActionSetsAttachInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO || info->countActionSets == 0 ||
        info->actionSets == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    if (s->actions_attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    Instance& inst = *instance_of(*s);
    std::vector<ActionSet*> sets;
    for (std::uint32_t i = 0; i < info->countActionSets; ++i) {
      ActionSet* set = find_action_set(info->actionSets[i]);
      if (set == nullptr || set->instance_id != inst.id) return XR_ERROR_HANDLE_INVALID;
      sets.push_back(set);
    }
    for (ActionSet* set : sets) {
      set->attached = true;
      s->attached_sets.push_back(set->id);
    }
    s->actions_attached = true;
    // The eye tracker is present from the start when the system has one; controllers become
    // present when XR_EXT_conformance_automation activates them.
    const sim::Scenario& sc = inst.simulator->scenario();
    const XrPath eye_profile = inst.paths.intern(xr::kEyeGazeProfile);
    if (inst.ext_eye_gaze && sc.runtime.eye_gaze_supported && inst.suggested.count(eye_profile) != 0) {
      InputDevice& eyes = s->devices[inst.paths.intern(xr::kEyesUserPath)];
      eyes.change_pending = true;  // current from the first xrSyncActions
      eyes.pending_active = true;
      eyes.pending_profile = eye_profile;
    }
    return XR_SUCCESS;
  });
}

XrResult GetCurrentInteractionProfile(XrSession session, XrPath topLevelUserPath, XrInteractionProfileState* state) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (state == nullptr || state->type != XR_TYPE_INTERACTION_PROFILE_STATE) return XR_ERROR_VALIDATION_FAILURE;
    Instance& inst = *instance_of(*s);
    const std::string* top = inst.paths.find(topLevelUserPath);
    if (top == nullptr) return XR_ERROR_PATH_INVALID;
    if (!is_top_level_user_path(*top)) return XR_ERROR_PATH_UNSUPPORTED;
    if (!s->actions_attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    auto it = s->devices.find(topLevelUserPath);
    state->interactionProfile = (it != s->devices.end() && it->second.active) ? it->second.profile : XR_NULL_PATH;
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
