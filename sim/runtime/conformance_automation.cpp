// SPDX-License-Identifier: Apache-2.0
// XR_EXT_conformance_automation: tests switch devices on and off and set their inputs and
// poses; values take effect at the next xrSyncActions. A location set on
// /user/eyes_ext/input/gaze_ext/pose replaces the simulated gaze.
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/interaction_profiles.hpp"
#include "sim/runtime/pose_math.hpp"
#include "sim/runtime/runtime_state.hpp"

#include <algorithm>

namespace gazelod::xrrt {
namespace {

// Checks session, top-level path and input path; returns the device to write to.
XrResult find_device(XrSession session, XrPath top, XrPath input, InputDevice** device) {
  Session* s = find_session(session);
  if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
  const Instance& inst = *instance_of(*s);
  const std::string* top_str = inst.paths.find(top);
  const std::string* input_str = inst.paths.find(input);
  if (top_str == nullptr || input_str == nullptr) return XR_ERROR_PATH_INVALID;
  if (!is_top_level_user_path(*top_str) || top_level_of(*input_str) != *top_str) return XR_ERROR_PATH_UNSUPPORTED;
  *device = &s->devices[top];
  return XR_SUCCESS;
}

}  // namespace

XrResult SetInputDeviceActiveEXT(XrSession session, XrPath interactionProfile, XrPath topLevelPath, XrBool32 isActive) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    Instance& inst = *instance_of(*s);
    const std::string* profile_str = inst.paths.find(interactionProfile);
    const std::string* top_str = inst.paths.find(topLevelPath);
    if (profile_str == nullptr || top_str == nullptr) return XR_ERROR_PATH_INVALID;
    const InteractionProfile* profile = find_profile(*profile_str);
    if (profile == nullptr ||
        std::find(profile->user_paths.begin(), profile->user_paths.end(), *top_str) == profile->user_paths.end())
      return XR_ERROR_PATH_UNSUPPORTED;
    InputDevice& d = s->devices[topLevelPath];
    d.change_pending = true;  // applied, and reported, by the next xrSyncActions
    d.pending_active = isActive == XR_TRUE;
    d.pending_profile = d.pending_active ? interactionProfile : XR_NULL_PATH;
    return XR_SUCCESS;
  });
}

XrResult SetInputDeviceStateBoolEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath, XrBool32 state) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    InputDevice* d = nullptr;
    if (XrResult r = find_device(session, topLevelPath, inputSourcePath, &d); r != XR_SUCCESS) return r;
    d->bools[inputSourcePath] = state == XR_TRUE;
    return XR_SUCCESS;
  });
}

XrResult SetInputDeviceStateFloatEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath, float state) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    InputDevice* d = nullptr;
    if (XrResult r = find_device(session, topLevelPath, inputSourcePath, &d); r != XR_SUCCESS) return r;
    d->floats[inputSourcePath] = state;
    return XR_SUCCESS;
  });
}

XrResult SetInputDeviceStateVector2fEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath,
                                        XrVector2f state) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    InputDevice* d = nullptr;
    if (XrResult r = find_device(session, topLevelPath, inputSourcePath, &d); r != XR_SUCCESS) return r;
    d->vec2s[inputSourcePath] = state;
    return XR_SUCCESS;
  });
}

XrResult SetInputDeviceLocationEXT(XrSession session, XrPath topLevelPath, XrPath inputSourcePath, XrSpace space,
                                   XrPosef pose) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    InputDevice* d = nullptr;
    if (XrResult r = find_device(session, topLevelPath, inputSourcePath, &d); r != XR_SUCCESS) return r;
    const Space* sp = find_space(space);
    if (sp == nullptr || sp->session_id != handle_id(session)) return XR_ERROR_HANDLE_INVALID;
    if (!is_unit_orientation(pose)) return XR_ERROR_POSE_INVALID;
    d->locations[inputSourcePath] = InputDevice::Location{sp->id, pose};
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
