// SPDX-License-Identifier: Apache-2.0
// xrSyncActions and the action state queries, bound sources, localized names and haptics
// (OpenXR 1.0 sections 11.5-11.8). Input values come from XR_EXT_conformance_automation.
#include "sim/runtime/action_bindings.hpp"
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/events.hpp"
#include "sim/runtime/interaction_profiles.hpp"
#include "sim/runtime/runtime_state.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::xrrt {
namespace {

SourceValue read_source(const Instance& inst, const Session& s, XrPath source) {
  SourceValue v;
  const std::string* str = inst.paths.find(source);
  if (str == nullptr) return v;
  for (const auto& [top, device] : s.devices) {
    const std::string* top_str = inst.paths.find(top);
    if (top_str == nullptr || top_level_of(*str) != *top_str) continue;
    if (auto b = device.bools.find(source); b != device.bools.end()) v.value = b->second ? 1.0f : 0.0f;
    if (auto f = device.floats.find(source); f != device.floats.end()) v.value = f->second;
    if (auto q = device.vec2s.find(source); q != device.vec2s.end()) v.vec2 = q->second;
  }
  return v;
}

// Common checks of the xrGetActionState* family; on success sets `action`.
XrResult check_get(Session* s, const XrActionStateGetInfo* info, XrActionType type, const Action** action) {
  if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
  if (info == nullptr || info->type != XR_TYPE_ACTION_STATE_GET_INFO) return XR_ERROR_VALIDATION_FAILURE;
  const Action* a = find_action(info->action);
  if (a == nullptr || a->instance_id != s->instance_id) return XR_ERROR_HANDLE_INVALID;
  if (a->type != type) return XR_ERROR_ACTION_TYPE_MISMATCH;
  if (!is_attached(*s, *a)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
  if (XrResult r = check_subaction(*instance_of(*s), *a, info->subactionPath); r != XR_SUCCESS) return r;
  *action = a;
  return XR_SUCCESS;
}

// The entries of a snapshot that belong to the requested subaction path.
std::vector<SourceValue> select(const Instance& inst, const std::map<XrPath, SourceValue>& snapshot, XrPath subaction) {
  std::vector<SourceValue> out;
  const std::string* sub = inst.paths.find(subaction);
  for (const auto& [path, value] : snapshot) {
    const std::string* p = inst.paths.find(path);
    if (sub != nullptr && (p == nullptr || top_level_of(*p) != *sub)) continue;
    out.push_back(value);
  }
  return out;
}

float largest(const std::vector<SourceValue>& values) {
  float best = 0.0f;
  for (const SourceValue& v : values)
    if (std::abs(v.value) > std::abs(best)) best = v.value;
  return best;
}

XrVector2f longest(const std::vector<SourceValue>& values) {
  XrVector2f best{0.0f, 0.0f};
  for (const SourceValue& v : values)
    if (std::hypot(v.vec2.x, v.vec2.y) > std::hypot(best.x, best.y)) best = v.vec2;
  return best;
}

// Device changes asked for since the last sync become current now, with one
// XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED when any current profile changed.
void apply_device_changes(Instance& inst, Session& s) {
  bool changed = false;
  for (auto& [top, d] : s.devices) {
    if (!d.change_pending) continue;
    d.change_pending = false;
    changed = changed || d.active != d.pending_active || d.profile != d.pending_profile;
    d.active = d.pending_active;
    d.profile = d.pending_profile;
  }
  if (changed && s.actions_attached) queue_profile_changed(inst, s);
}

}  // namespace

XrResult SyncActions(XrSession session, const XrActionsSyncInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_ACTIONS_SYNC_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (info->countActiveActionSets > 0 && info->activeActionSets == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    Instance& inst = *instance_of(*s);
    for (std::uint32_t i = 0; i < info->countActiveActionSets; ++i) {
      const XrActiveActionSet& as = info->activeActionSets[i];
      const ActionSet* set = find_action_set(as.actionSet);
      if (set == nullptr || set->instance_id != inst.id) return XR_ERROR_HANDLE_INVALID;
      if (std::find(s->attached_sets.begin(), s->attached_sets.end(), set->id) == s->attached_sets.end())
        return XR_ERROR_ACTIONSET_NOT_ATTACHED;
      if (as.subactionPath != XR_NULL_PATH) {
        const std::string* p = inst.paths.find(as.subactionPath);
        if (p == nullptr) return XR_ERROR_PATH_INVALID;
        const auto& declared = set->subaction_paths;
        if (!is_top_level_user_path(*p) ||
            std::find(declared.begin(), declared.end(), as.subactionPath) == declared.end())
          return XR_ERROR_PATH_UNSUPPORTED;
      }
    }
    apply_device_changes(inst, *s);
    const bool focused = s->state == XR_SESSION_STATE_FOCUSED;
    const XrTime now = inst.clock.now();
    s->last_sync_time = now;
    s->synced_sets.clear();
    for (auto& [id, state] : s->action_states) {
      state.previous = std::move(state.current);
      state.current.clear();
    }
    if (!focused) return XR_SESSION_NOT_FOCUSED;  // every action inactive
    // Each active set's actions with their bound sources; then a source feeds only the actions
    // of the highest-priority active sets that bind it (section 11.5.1, "priority").
    struct Bound {
      std::uint64_t action_id;
      std::uint32_t priority;
      std::vector<XrPath> sources;
    };
    std::vector<Bound> bound;
    std::map<XrPath, std::uint32_t> top_priority;
    for (std::uint32_t i = 0; i < info->countActiveActionSets; ++i) {
      const XrActiveActionSet& as = info->activeActionSets[i];
      const ActionSet* set = find_action_set(as.actionSet);
      s->synced_sets.push_back(set->id);
      for (const auto& [aid, action] : runtime().actions.live) {
        if (action->set_id != set->id) continue;
        Bound b{aid, set->priority, bound_sources(inst, *s, *action, as.subactionPath)};
        for (XrPath src : b.sources) top_priority[src] = std::max(top_priority[src], set->priority);
        bound.push_back(std::move(b));
      }
    }
    for (const Bound& b : bound) {
      ActionState& st = s->action_states[b.action_id];
      for (XrPath src : b.sources)
        if (b.priority == top_priority[src]) st.current[src] = read_source(inst, *s, src);
    }
    for (const Bound& b : bound) {
      ActionState& st = s->action_states[b.action_id];
      const float before = largest(select(inst, st.previous, XR_NULL_PATH));
      const float after = largest(select(inst, st.current, XR_NULL_PATH));
      if (before != after) st.last_change_time = now;
    }
    return XR_SUCCESS;
  });
}

namespace {

// The shared part of xrGetActionState{Boolean,Float,Vector2f}: checks, then the bound sources'
// values now and at the previous sync, handed to `fill`, which sets the typed current state and
// whether it changed. isActive and lastChangeTime follow from whether any source is bound.
template <typename State, typename Fill>
XrResult get_action_state(XrSession session, const XrActionStateGetInfo* info, State* state, XrActionType action_type,
                          XrStructureType struct_type, Fill fill) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    const Action* a = nullptr;
    if (XrResult r = check_get(s, info, action_type, &a); r != XR_SUCCESS) return r;
    if (state == nullptr || state->type != struct_type) return XR_ERROR_VALIDATION_FAILURE;
    const Instance& inst = *instance_of(*s);
    const ActionState& st = s->action_states[a->id];
    const auto now = select(inst, st.current, info->subactionPath);
    const auto before = select(inst, st.previous, info->subactionPath);
    const bool changed = fill(now, before, *state);
    state->isActive = now.empty() ? XR_FALSE : XR_TRUE;
    state->changedSinceLastSync = (!now.empty() && !before.empty() && changed) ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = now.empty() ? 0 : st.last_change_time;
    return XR_SUCCESS;
  });
}

}  // namespace

XrResult GetActionStateBoolean(XrSession session, const XrActionStateGetInfo* info, XrActionStateBoolean* state) {
  return get_action_state(session, info, state, XR_ACTION_TYPE_BOOLEAN_INPUT, XR_TYPE_ACTION_STATE_BOOLEAN,
                          [](const auto& now, const auto& before, XrActionStateBoolean& out) {
                            const bool value = largest(now) > 0.5f;
                            out.currentState = value ? XR_TRUE : XR_FALSE;
                            return value != (largest(before) > 0.5f);
                          });
}

XrResult GetActionStateFloat(XrSession session, const XrActionStateGetInfo* info, XrActionStateFloat* state) {
  return get_action_state(session, info, state, XR_ACTION_TYPE_FLOAT_INPUT, XR_TYPE_ACTION_STATE_FLOAT,
                          [](const auto& now, const auto& before, XrActionStateFloat& out) {
                            out.currentState = largest(now);
                            return largest(now) != largest(before);
                          });
}

XrResult GetActionStateVector2f(XrSession session, const XrActionStateGetInfo* info, XrActionStateVector2f* state) {
  return get_action_state(session, info, state, XR_ACTION_TYPE_VECTOR2F_INPUT, XR_TYPE_ACTION_STATE_VECTOR2F,
                          [](const auto& now, const auto& before, XrActionStateVector2f& out) {
                            const XrVector2f v = longest(now), b = longest(before);
                            out.currentState = v;
                            return v.x != b.x || v.y != b.y;
                          });
}

XrResult GetActionStatePose(XrSession session, const XrActionStateGetInfo* info, XrActionStatePose* state) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    const Action* a = nullptr;
    if (XrResult r = check_get(s, info, XR_ACTION_TYPE_POSE_INPUT, &a); r != XR_SUCCESS) return r;
    if (state == nullptr || state->type != XR_TYPE_ACTION_STATE_POSE) return XR_ERROR_VALIDATION_FAILURE;
    const ActionState& st = s->action_states[a->id];
    state->isActive = select(*instance_of(*s), st.current, info->subactionPath).empty() ? XR_FALSE : XR_TRUE;
    return XR_SUCCESS;
  });
}

XrResult EnumerateBoundSourcesForAction(XrSession session, const XrBoundSourcesForActionEnumerateInfo* info,
                                        uint32_t capacity, uint32_t* count, XrPath* sources) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    const Action* a = find_action(info->action);
    if (a == nullptr || a->instance_id != s->instance_id) return XR_ERROR_HANDLE_INVALID;
    if (!is_attached(*s, *a)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    return two_call(capacity, count, sources, bound_sources(*instance_of(*s), *s, *a, XR_NULL_PATH));
  });
}

XrResult GetInputSourceLocalizedName(XrSession session, const XrInputSourceLocalizedNameGetInfo* info,
                                     uint32_t capacity, uint32_t* count, char* buffer) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO || info->whichComponents == 0)
      return XR_ERROR_VALIDATION_FAILURE;
    if (!s->actions_attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    const Instance& inst = *instance_of(*s);
    const std::string* src = inst.paths.find(info->sourcePath);
    if (src == nullptr) return XR_ERROR_PATH_INVALID;
    const std::string_view top = top_level_of(*src);
    if (top.empty()) return XR_ERROR_PATH_UNSUPPORTED;
    std::string name;
    auto add = [&](std::string_view part) {
      if (!name.empty()) name += ' ';
      name += part;
    };
    if (info->whichComponents & XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT) add(top);
    if (info->whichComponents & XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT) {
      for (const auto& [t, device] : s->devices)
        if (const std::string* ts = inst.paths.find(t); ts != nullptr && *ts == top && device.profile != XR_NULL_PATH)
          add(*inst.paths.find(device.profile));
    }
    if ((info->whichComponents & XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT) && src->size() > top.size() + 1)
      add(std::string_view(*src).substr(top.size() + 1));
    return two_call_string(capacity, count, buffer, name);
  });
}

XrResult ApplyHapticFeedback(XrSession session, const XrHapticActionInfo* info, const XrHapticBaseHeader* haptic) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_HAPTIC_ACTION_INFO || haptic == nullptr ||
        haptic->type != XR_TYPE_HAPTIC_VIBRATION)
      return XR_ERROR_VALIDATION_FAILURE;
    const Action* a = find_action(info->action);
    if (a == nullptr || a->instance_id != s->instance_id) return XR_ERROR_HANDLE_INVALID;
    if (a->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (!is_attached(*s, *a)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (XrResult r = check_subaction(*instance_of(*s), *a, info->subactionPath); r != XR_SUCCESS) return r;
    // There is no actuator to drive; the call is accepted as a real runtime would.
    return s->state == XR_SESSION_STATE_FOCUSED ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  });
}

XrResult StopHapticFeedback(XrSession session, const XrHapticActionInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_HAPTIC_ACTION_INFO) return XR_ERROR_VALIDATION_FAILURE;
    const Action* a = find_action(info->action);
    if (a == nullptr || a->instance_id != s->instance_id) return XR_ERROR_HANDLE_INVALID;
    if (a->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (!is_attached(*s, *a)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (XrResult r = check_subaction(*instance_of(*s), *a, info->subactionPath); r != XR_SUCCESS) return r;
    return s->state == XR_SESSION_STATE_FOCUSED ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  });
}

}  // namespace gazelod::xrrt
