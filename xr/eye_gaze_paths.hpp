// SPDX-License-Identifier: Apache-2.0
// The paths of XR_EXT_eye_gaze_interaction: the interaction
// profile, its top-level user path and the gaze pose input. The simulated runtime offers them,
// the eye-gaze layer emulates them and the plugin binds its gaze action to them: one spelling.
#pragma once

namespace gazelod::xr {

inline constexpr const char* kEyeGazeProfile = "/interaction_profiles/ext/eye_gaze_interaction";
inline constexpr const char* kEyesUserPath = "/user/eyes_ext";
inline constexpr const char* kGazePosePath = "/user/eyes_ext/input/gaze_ext/pose";

}  // namespace gazelod::xr
