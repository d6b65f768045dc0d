// Interaction profile table and path classification (see interaction_profiles.hpp).
#include "sim/runtime/interaction_profiles.hpp"

namespace gazelod::xrrt {
namespace {

constexpr std::string_view kUserPaths[] = {"/user/hand/left", "/user/hand/right", "/user/head",
                                            "/user/gamepad", "/user/eyes_ext"};

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

const std::vector<InteractionProfile>& interaction_profiles() {
  static const std::vector<InteractionProfile> kProfiles = {
      {"/interaction_profiles/khr/simple_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/select/click", "input/menu/click", "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/oculus/touch_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"left:input/x/click", "left:input/x/touch", "left:input/y/click", "left:input/y/touch",
        "left:input/menu/click", "right:input/a/click", "right:input/a/touch", "right:input/b/click",
        "right:input/b/touch", "right:input/system/click", "input/squeeze/value", "input/trigger/value",
        "input/trigger/touch", "input/thumbstick", "input/thumbstick/x", "input/thumbstick/y",
        "input/thumbstick/click", "input/thumbstick/touch", "input/thumbrest/touch", "input/grip/pose",
        "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/htc/vive_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/system/click", "input/squeeze/click", "input/menu/click", "input/trigger/click",
        "input/trigger/value", "input/trackpad", "input/trackpad/x", "input/trackpad/y", "input/trackpad/click",
        "input/trackpad/touch", "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/valve/index_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/system/click", "input/system/touch", "input/a/click", "input/a/touch", "input/b/click",
        "input/b/touch", "input/squeeze/value", "input/squeeze/force", "input/trigger/click",
        "input/trigger/value", "input/trigger/touch", "input/thumbstick", "input/thumbstick/x",
        "input/thumbstick/y", "input/thumbstick/click", "input/thumbstick/touch", "input/trackpad",
        "input/trackpad/x", "input/trackpad/y", "input/trackpad/force", "input/trackpad/touch",
        "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {"/interaction_profiles/microsoft/motion_controller",
       {"/user/hand/left", "/user/hand/right"},
       {"input/menu/click", "input/squeeze/click", "input/trigger/value", "input/thumbstick",
        "input/thumbstick/x", "input/thumbstick/y", "input/thumbstick/click", "input/trackpad",
        "input/trackpad/x", "input/trackpad/y", "input/trackpad/click", "input/trackpad/touch",
        "input/grip/pose", "input/aim/pose", "output/haptic"}},
      {kEyeGazeProfile, {kEyesUserPath}, {"input/gaze_ext/pose"}, true},
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
    // Exact, or an identifier naming a component's parent ("input/trigger" for ".../value").
    if (c == rest || (c.size() > rest.size() && c.starts_with(rest) && c[rest.size()] == '/')) return true;
  }
  return false;
}

InputKind input_kind(std::string_view binding) {
  if (ends_with(binding, "/pose")) return InputKind::pose;
  if (ends_with(binding, "/haptic")) return InputKind::haptic;
  if (ends_with(binding, "/click") || ends_with(binding, "/touch")) return InputKind::boolean;
  if (ends_with(binding, "/thumbstick") || ends_with(binding, "/trackpad")) return InputKind::vector2;
  return InputKind::scalar;
}

}  // namespace gazelod::xrrt
