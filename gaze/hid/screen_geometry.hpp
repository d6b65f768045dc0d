// SPDX-License-Identifier: Apache-2.0
// From a screen-plane tracker's report (gaze point on the screen, eye positions in front of it)
// to a gaze direction in head space for the LOD core.
//
// Frames. The screen frame S has its origin at the centre of the calibrated screen, +x right,
// +y up, +z out of the screen towards the user; those are OpenXR's head axes when the head
// faces the screen (looking at the screen is -z). The gaze point arrives in micrometres from
// the screen's upper-left corner with +y down (reports.hpp) and is moved into S. Eye positions
// are read in S by default (the "user coordinate system" of screen-based trackers: origin at the
// screen/tracker centre, +y up, +z towards the user); EyeFrame lets a device with a different
// convention be configured.
//
// Desktop tracker: the head is assumed to face the screen squarely, so head space = S and the
// direction is exact only for a frontoparallel head (the reports' head direction has no unit
// we can rely on, see reports.hpp); the result is what the screen-plane geometry gives.
// HMD: an HMD tracker that exposes this page reports the gaze point on the display's (virtual)
// image plane, which is rigidly fixed in head space, so head space = S holds exactly; configure
// the plane's size (and, for eye positions relative to its corner, the EyeFrame).
#pragma once

#include "gaze/gaze_sample.hpp"
#include "gaze/hid/reports.hpp"

#include <string>

namespace gazelod::gaze::hid {

struct EyeFrame {
  bool origin_top_left = false;  // false: eye positions relative to the screen centre
  bool y_down = false;           // false: +y up
};

struct ScreenGeometry {
  double width_m = 0.0;  // calibrated screen (or image plane) size
  double height_m = 0.0;
  EyeFrame eye_frame;
};

// "" when usable, else why not (zero or non-finite size).
[[nodiscard]] std::string validate(const ScreenGeometry& g);

// Direction (unit, head space = S), origin (cyclopean eye relative to the head position when
// the report has one, else zero), validity and confidence (1 both eyes, 0.5 one eye). Not valid
// when no eye is in front of the screen (z <= 0, which is also how an all-zero "no data"
// report reads), the gaze point is far off the screen (more than half a screen beyond an edge),
// or eye and gaze point coincide. t_ns is left 0 for the caller.
GazeSample gaze_from_screen(const TrackingData& t, const ScreenGeometry& g);

}  // namespace gazelod::gaze::hid
