// SPDX-License-Identifier: Apache-2.0
// Displays as the acuity model sees them: per-view pixels and asymmetric field of view, as
// OpenXR reports them (XrFovf angleLeft/Right/Up/Down, radians, left and down negative),
// the highest spatial frequency a view can show (xi, Reddy 1998 section 3.4), and named presets.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace gazelod::lod {

// Field of view of one view, OpenXR convention: angle_left_rad < angle_right_rad,
// angle_down_rad < angle_up_rad; left and down are usually negative.
struct FovRad {
  double angle_left_rad = 0.0;
  double angle_right_rad = 0.0;
  double angle_up_rad = 0.0;
  double angle_down_rad = 0.0;
};

// One view (one eye of an HMD, or a desktop window).
struct ViewSpec {
  int width_px = 0;
  int height_px = 0;
  FovRad fov;
};

struct DisplaySpec {
  std::string name;   // preset key ("quest3") or "custom"
  std::string label;  // "Meta Quest 3"
  ViewSpec views[2];  // per-eye; view_count 1 for a desktop
  int view_count = 2;
  double refresh_hz = 90.0;
  double eye_tracking_hz = 0.0;            // 0: no eye tracker
  double eye_tracking_accuracy_deg = 0.0;  // typical angular error of its tracker, 0 if none
  std::string source;                      // where the figures come from
  // Extension (gazelod, not Reddy 1998): pixels per degree at the lens centre where the maker
  // states it (lenses concentrate pixels there), 0 if unknown. xi_cpd() stays Reddy's
  // whole-view average; xi_center_cpd() gives the centre figure.
  double center_ppd = 0.0;
};

// xi: the highest displayable frequency in cycles/deg, per axis and combined
// (xi = max(hpix / (2 hfov), vpix / (2 vfov)), Reddy 1998 section 3.4). Implemented in display.cpp.
double xi_h_cpd(const ViewSpec& view);
double xi_v_cpd(const ViewSpec& view);
double xi_cpd(const ViewSpec& view);
double xi_cpd(const DisplaySpec& display);

// Presets by command-line name: desktop, iglasses, quest3, questpro, index, viveproeye,
// varjoxr4, visionpro, psvr2, pimaxcrystal. nullptr when unknown.
// Extensions (gazelod): field of view in degrees per axis, a symmetric FOV from degrees,
// the centre-of-lens xi (center_ppd / 2, one pixel is half a cycle; falls back to xi_cpd),
// and validation. validate_* return "" when valid, else a message naming the bad field
// (pixels must be > 0, each FOV axis in (0, 180) deg with finite angles in (-90, 90) deg).
double fov_h_deg(const ViewSpec& view);
double fov_v_deg(const ViewSpec& view);
FovRad symmetric_fov(double fov_h_deg, double fov_v_deg);
double xi_center_cpd(const DisplaySpec& display);
[[nodiscard]] std::string validate_view(const ViewSpec& view);
[[nodiscard]] std::string validate_display(const DisplaySpec& display);

// A field of view a user describes (a scenario's display, `gazelod thresholds --fov`): each
// axis in [kMinFovDeg, kMaxFovDeg] degrees, so xi stays finite and meaningful (at most
// 1e6 px / (2 * 0.001 deg) = 5e8 c/deg). validate_view's (0, 180) is for what a runtime reports.
inline constexpr double kMinFovDeg = 1e-3, kMaxFovDeg = 179.0;
// validate_view, then each FOV axis in [kMinFovDeg, kMaxFovDeg]; "" when valid.
[[nodiscard]] std::string validate_described_view(const ViewSpec& view);

const DisplaySpec* find_display_preset(std::string_view name);
std::span<const DisplaySpec> display_presets();

}  // namespace gazelod::lod
