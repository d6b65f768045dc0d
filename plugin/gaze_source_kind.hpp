// SPDX-License-Identifier: Apache-2.0
// Where the plugin's gaze comes from this frame, in the order it tries them.
#pragma once

#include <cstdint>

namespace gazelod {

enum class GazeSourceKind : std::uint8_t {
  openxr,      // the runtime's XR_EXT_eye_gaze_interaction
  external,    // PluginConfig::external_source (a HID tracker, a trace replay)
  head_fixed,  // none: straight ahead in the head, with a widened foveal cone
  pushed,      // samples the application pushes (data mode, gzl_push_gaze_sample)
};
const char* to_string(GazeSourceKind kind);

}  // namespace gazelod
