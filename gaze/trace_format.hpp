// SPDX-License-Identifier: Apache-2.0
// Column names and version of gazelod's gaze-trace CSV format (spec: docs/gaze.md).
// One place for the names so that writer, reader and importers cannot drift apart.
#pragma once

#include <string_view>

namespace gazelod::gaze::trace_format {

// First line of every file the writer produces. The reader accepts files without it (hand
// written traces) and rejects a version newer than it knows.
inline constexpr std::string_view kMagic = "# gazelod-trace";
inline constexpr int kVersion = 1;

inline constexpr std::string_view kTimeNs = "t_ns";
inline constexpr std::string_view kTimeS = "t_s";
inline constexpr std::string_view kGazeX = "gaze_x";
inline constexpr std::string_view kGazeY = "gaze_y";
inline constexpr std::string_view kGazeZ = "gaze_z";
inline constexpr std::string_view kYawDeg = "gaze_yaw_deg";
inline constexpr std::string_view kPitchDeg = "gaze_pitch_deg";
inline constexpr std::string_view kEyeX = "eye_px";  // gaze origin, head space, metres
inline constexpr std::string_view kEyeY = "eye_py";
inline constexpr std::string_view kEyeZ = "eye_pz";
inline constexpr std::string_view kValid = "valid";
inline constexpr std::string_view kConfidence = "confidence";
inline constexpr std::string_view kHeadQw = "head_qw";
inline constexpr std::string_view kHeadQx = "head_qx";
inline constexpr std::string_view kHeadQy = "head_qy";
inline constexpr std::string_view kHeadQz = "head_qz";
inline constexpr std::string_view kHeadPx = "head_px";
inline constexpr std::string_view kHeadPy = "head_py";
inline constexpr std::string_view kHeadPz = "head_pz";
inline constexpr std::string_view kHeadValid = "head_valid";

}  // namespace gazelod::gaze::trace_format
