// SPDX-License-Identifier: Apache-2.0
// Binding resolution (see action_bindings.hpp).
#include "sim/runtime/action_bindings.hpp"
#include "sim/runtime/interaction_profiles.hpp"

#include <algorithm>

namespace gazelod::xrrt {

namespace {

// The conversions of section 11.5.2 ("Action type conversions"): boolean and float sources
// feed each other's actions; a vector2, pose or haptic action takes only its own kind. Any other
// pairing leaves the binding unused (the action inactive), not an error.
bool feeds(XrActionType action, InputKind source) {
  switch (action) {
    case XR_ACTION_TYPE_BOOLEAN_INPUT:
    case XR_ACTION_TYPE_FLOAT_INPUT:
      return source == InputKind::boolean || source == InputKind::scalar;
    case XR_ACTION_TYPE_VECTOR2F_INPUT:
      return source == InputKind::vector2;
    case XR_ACTION_TYPE_POSE_INPUT:
      return source == InputKind::pose;
    case XR_ACTION_TYPE_VIBRATION_OUTPUT:
      return source == InputKind::haptic;
    default:
      return false;
  }
}

}  // namespace

std::vector<XrPath> bound_sources(const Instance& inst, const Session& session, const Action& action,
                                  XrPath subaction) {
  std::vector<XrPath> out;
  for (const auto& [top, device] : session.devices) {
    if (!device.active || device.profile == XR_NULL_PATH) continue;
    if (subaction != XR_NULL_PATH && subaction != top) continue;
    if (!action.subaction_paths.empty() &&
        std::find(action.subaction_paths.begin(), action.subaction_paths.end(), top) == action.subaction_paths.end())
      continue;
    auto it = inst.suggested.find(device.profile);
    if (it == inst.suggested.end()) continue;
    const std::string* top_str = inst.paths.find(top);
    for (const auto& [action_id, binding] : it->second) {
      if (action_id != action.id) continue;
      const std::string* b = inst.paths.find(binding);
      if (b != nullptr && top_str != nullptr && top_level_of(*b) == *top_str && feeds(action.type, input_kind(*b)))
        out.push_back(binding);
    }
  }
  return out;
}

bool is_attached(const Session& session, const Action& action) {
  return std::find(session.attached_sets.begin(), session.attached_sets.end(), action.set_id) !=
         session.attached_sets.end();
}

XrResult check_subaction(const Instance& inst, const Action& action, XrPath subaction) {
  if (subaction == XR_NULL_PATH) return XR_SUCCESS;
  if (inst.paths.find(subaction) == nullptr) return XR_ERROR_PATH_INVALID;
  if (std::find(action.subaction_paths.begin(), action.subaction_paths.end(), subaction) ==
      action.subaction_paths.end())
    return XR_ERROR_PATH_UNSUPPORTED;
  return XR_SUCCESS;
}

}  // namespace gazelod::xrrt
