// SPDX-License-Identifier: Apache-2.0
// The interaction profiles the runtime accepts bindings for (OpenXR 1.0 section 6.4 and
// XR_EXT_eye_gaze_interaction), with their top-level user paths and input/output paths.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gazelod::xrrt {

enum class InputKind : unsigned char { boolean, scalar, vector2, pose, haptic };

struct InteractionProfile {
  std::string_view path;
  std::vector<std::string_view> user_paths;  // top-level paths, e.g. /user/hand/left
  // Components relative to a top-level path ("input/select/click"); an entry with a leading
  // "left:" or "right:" exists only on that hand.
  std::vector<std::string_view> components;
  bool needs_eye_gaze_extension = false;
};

const std::vector<InteractionProfile>& interaction_profiles();
const InteractionProfile* find_profile(std::string_view path);

// The top-level user path a full path starts with ("" when none): /user/hand/left, ...
std::string_view top_level_of(std::string_view path);
bool is_top_level_user_path(std::string_view path);
// True when `binding` (a full path such as /user/hand/left/input/trigger/value, or an
// identifier such as /user/hand/left/input/trigger) exists in the profile.
bool profile_has_binding(const InteractionProfile& profile, std::string_view binding);
// What kind of value an input path delivers.
InputKind input_kind(std::string_view binding);

}  // namespace gazelod::xrrt
