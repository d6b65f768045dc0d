// SPDX-License-Identifier: Apache-2.0
// Interaction profile table and path classification (see interaction_profiles.hpp).
#include "sim/runtime/interaction_profiles.hpp"

#include "xr/eye_gaze_paths.hpp"

#include <algorithm>

namespace gazelod::xrrt {
namespace {

constexpr std::string_view kUserPaths[] = {"/user/hand/left", "/user/hand/right", "/user/head", "/user/gamepad",
                                           xr::kEyesUserPath};

}  // namespace

const std::vector<InteractionProfile>& interaction_profiles() {
  static const std::vector<InteractionProfile> kProfiles = {
      {"/interaction_profiles/khr/simple_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/select/click", "input/menu/click", "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/oculus/touch_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"left:input/x/click",     "left:input/x/touch",
        "left:input/y/click",     "left:input/y/touch",
        "left:input/menu/click",  "right:input/a/click",
        "right:input/a/touch",    "right:input/b/click",
        "right:input/b/touch",    "right:input/system/click",
        "input/squeeze/value",    "input/trigger/value",
        "input/trigger/touch",    "input/thumbstick",
        "input/thumbstick/x",     "input/thumbstick/y",
        "input/thumbstick/click", "input/thumbstick/touch",
        "input/thumbrest/touch",  "input/grip/pose",
        "input/aim/pose",         "output/haptic"}},
      {"/interaction_profiles/htc/vive_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/system/click", "input/squeeze/click", "input/menu/click", "input/trigger/click", "input/trigger/value",
        "input/trackpad", "input/trackpad/x", "input/trackpad/y", "input/trackpad/click", "input/trackpad/touch",
        "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/valve/index_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/system/click",   "input/system/touch",  "input/a/click",          "input/a/touch",
        "input/b/click",        "input/b/touch",       "input/squeeze/value",    "input/squeeze/force",
        "input/trigger/click",  "input/trigger/value", "input/trigger/touch",    "input/thumbstick",
        "input/thumbstick/x",   "input/thumbstick/y",  "input/thumbstick/click", "input/thumbstick/touch",
        "input/trackpad",       "input/trackpad/x",    "input/trackpad/y",       "input/trackpad/force",
        "input/trackpad/touch", "input/grip/pose",     "input/aim/pose",         "output/haptic"}},
      {"/interaction_profiles/microsoft/motion_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/menu/click", "input/squeeze/click", "input/trigger/value", "input/thumbstick", "input/thumbstick/x",
        "input/thumbstick/y", "input/thumbstick/click", "input/trackpad", "input/trackpad/x", "input/trackpad/y",
        "input/trackpad/click", "input/trackpad/touch", "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/google/daydream_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/select/click", "input/trackpad", "input/trackpad/x", "input/trackpad/y", "input/trackpad/click",
        "input/trackpad/touch", "input/grip/pose", "input/aim/pose"}},
      {"/interaction_profiles/htc/vive_pro",
       {"/user/head"},
       {"input/system/click", "input/volume_up/click", "input/volume_down/click", "input/mute_mic/click"}},
      {"/interaction_profiles/microsoft/xbox_controller",
       {"/user/gamepad"},
       {"input/menu/click",
        "input/view/click",
        "input/a/click",
        "input/b/click",
        "input/x/click",
        "input/y/click",
        "input/dpad_down/click",
        "input/dpad_right/click",
        "input/dpad_up/click",
        "input/dpad_left/click",
        "input/shoulder_left/click",
        "input/shoulder_right/click",
        "input/thumbstick_left/click",
        "input/thumbstick_right/click",
        "input/trigger_left/value",
        "input/trigger_right/value",
        "input/thumbstick_left",
        "input/thumbstick_left/x",
        "input/thumbstick_left/y",
        "input/thumbstick_right",
        "input/thumbstick_right/x",
        "input/thumbstick_right/y",
        "output/haptic_left",
        "output/haptic_right",
        "output/haptic_left_trigger",
        "output/haptic_right_trigger"}},
      {"/interaction_profiles/oculus/go_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/system/click", "input/trigger/click", "input/back/click", "input/trackpad", "input/trackpad/x",
        "input/trackpad/y", "input/trackpad/click", "input/trackpad/touch", "input/grip/pose", "input/aim/pose"}},
      {xr::kEyeGazeProfile, {xr::kEyesUserPath}, {"input/gaze_ext/pose"}, true},
  };
  return kProfiles;
}

const InteractionProfile* find_profile(std::string_view path) {
  for (const InteractionProfile& p : interaction_profiles())
    if (p.path == path) return &p;
  return nullptr;
}

std::string_view top_level_of(std::string_view path) {
  for (std::string_view u : kUserPaths)
    if (path.substr(0, u.size()) == u && (path.size() == u.size() || path[u.size()] == '/')) return u;
  return {};
}

bool is_top_level_user_path(std::string_view path) {
  return !path.empty() && top_level_of(path) == path;
}

bool profile_has_binding(const InteractionProfile& profile, std::string_view binding) {
  const std::string_view top = top_level_of(binding);
  if (top.empty() || binding.size() <= top.size() + 1) return false;
  bool listed = false;
  for (std::string_view u : profile.user_paths) listed = listed || u == top;
  if (!listed) return false;
  const std::string_view rest = binding.substr(top.size() + 1);
  const std::string_view side = top == "/user/hand/left" ? "left:" : top == "/user/hand/right" ? "right:" : "";
  for (std::string_view c : profile.components) {
    if (c.starts_with("left:") || c.starts_with("right:")) {
      if (side.empty() || !c.starts_with(side)) continue;
      c.remove_prefix(side.size());
    }
    if (c == rest) return true;
    // An identifier without its component ("input/trigger" for "input/trigger/value", section
    // 6.3.2): exactly "input/<identifier>" or "output/<identifier>", never "input" alone.
    const bool identifier = std::count(rest.begin(), rest.end(), '/') == 1;
    if (identifier && c.size() > rest.size() && c.starts_with(rest) && c[rest.size()] == '/') return true;
  }
  return false;
}

InputKind input_kind(std::string_view binding) {
  const std::string_view last = binding.substr(binding.rfind('/') + 1);  // npos + 1 == 0
  if (last == "pose") return InputKind::pose;
  if (binding.find("/output/") != std::string_view::npos) return InputKind::haptic;
  if (last == "click" || last == "touch") return InputKind::boolean;
  // 2D identifiers (thumbstick, thumbstick_left, trackpad) bound without a component.
  if (last.starts_with("thumbstick") || last == "trackpad") return InputKind::vector2;
  return InputKind::scalar;
}

}  // namespace gazelod::xrrt
