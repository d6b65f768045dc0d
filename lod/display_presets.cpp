// SPDX-License-Identifier: Apache-2.0
// Named display presets. Per-eye pixels, FOV, refresh and eye tracking as published; where a
// maker gives only a total/diagonal FOV it is applied per eye and symmetric, which the
// source string says. Figures marked "assumed" are not published; they are placeholders the
// caller may override (the runtime's xrLocateViews FOV always wins in the plugin).
#include "lod/display.hpp"
#include "auxiliary/angles.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace gazelod::lod {
namespace {

DisplaySpec make(const char* name, const char* label, int w, int h, double fov_h, double fov_v, int views, double hz,
                 double et_hz, double et_acc_deg, double center_ppd, const char* source) {
  DisplaySpec d;
  d.name = name;
  d.label = label;
  d.view_count = views;
  for (ViewSpec& v : d.views) v = ViewSpec{w, h, symmetric_fov(fov_h, fov_v)};
  d.refresh_hz = hz;
  d.eye_tracking_hz = et_hz;
  d.eye_tracking_accuracy_deg = et_acc_deg;
  d.center_ppd = center_ppd;
  d.source = source;
  return d;
}

// 40 x 30 cm screen seen from 40 cm: FOV = 2 atan(half size / distance) (Reddy 1995, footnote 3).
double desktop_fov_deg(double size_cm) {
  return 2.0 * std::atan(size_cm / 2.0 / 40.0) * aux::kDegPerRad;
}

const std::array<DisplaySpec, 10>& presets() {
  static const std::array<DisplaySpec, 10> all = {
      make("desktop", "Desktop monitor 40x30 cm at 40 cm (Reddy 1998)", 1280, 1024, desktop_fov_deg(40.0),
           desktop_fov_deg(30.0), 1, 60.0, 0.0, 0.0, 0.0,
           "Reddy 1998 section 4.1: 1280x1024, 53.1x41.1 deg; 60 Hz assumed"),
      make("iglasses", "Virtual i-O i-glasses! (Reddy 1998)", 263, 230, 30.0, 24.0, 2, 60.0, 0.0, 0.0, 0.0,
           "Reddy 1998 section 4.2: 263x230, 30x24 deg; 60 Hz assumed"),
      make("quest3", "Meta Quest 3", 2064, 2208, 110.0, 96.0, 2, 120.0, 0.0, 0.0, 25.0,
           "Meta Quest 3 tech specs (meta.com, 2023): 2064x2208 per eye, 110 H x 96 V deg "
           "(total, applied per eye), 72/90/120 Hz, 25 PPD centre; no eye tracking"),
      make("questpro", "Meta Quest Pro", 1800, 1920, 106.0, 96.0, 2, 90.0, 90.0, 1.652, 22.0,
           "Meta Quest Pro tech specs (meta.com, 2022): 1800x1920 per eye, 106 H x 96 V deg "
           "(total, applied per eye), 72/90 Hz, 22 PPD centre; eye tracker rate assumed = 90 Hz; "
           "accuracy 1.652 deg measured by Wei et al. 2023"),
      make("index", "Valve Index", 1440, 1600, 108.0, 104.0, 2, 144.0, 0.0, 0.0, 0.0,
           "Valve Index specs (valvesoftware.com, 2019): 1440x1600 per eye, 80-144 Hz, FOV "
           "'up to 130 deg'; per-axis 108 x 104 deg approximate (user measurements); no eye tracking"),
      make("viveproeye", "HTC Vive Pro Eye", 1440, 1600, 110.0, 110.0, 2, 90.0, 120.0, 1.1, 0.0,
           "HTC Vive Pro Eye specs (vive.com, 2019): 1440x1600 per eye, 90 Hz, 110 deg (applied "
           "to both axes); Tobii eye tracking 120 Hz output, accuracy 0.5-1.1 deg (upper used)"),
      make("varjoxr4", "Varjo XR-4", 3840, 3744, 120.0, 105.0, 2, 90.0, 200.0, 1.0, 51.0,
           "Varjo XR-4 specs (varjo.com, 2023): 3840x3744 per eye, 120 H x 105 V deg, 90 Hz, "
           "51 PPD centre; eye tracking 200 Hz; accuracy 1.0 deg assumed (maker: sub-degree)"),
      make("visionpro", "Apple Vision Pro", 3660, 3200, 100.0, 90.0, 2, 100.0, 90.0, 1.0, 0.0,
           "Apple Vision Pro (apple.com, 2024): 23 M pixels total, 90/96/100 Hz; 3660x3200 per eye "
           "and ~100 x 90 deg FOV are third-party estimates; eye tracker rate and accuracy not "
           "published (90 Hz, 1.0 deg assumed)"),
      make("psvr2", "Sony PlayStation VR2", 2000, 2040, 110.0, 110.0, 2, 120.0, 120.0, 1.0, 0.0,
           "PlayStation VR2 specs (playstation.com, 2023): 2000x2040 per eye, 90/120 Hz, approx. "
           "110 deg (applied to both axes); Tobii eye tracking, rate and accuracy not published "
           "(120 Hz, 1.0 deg assumed)"),
      make("pimaxcrystal", "Pimax Crystal", 2880, 2880, 115.0, 105.0, 2, 120.0, 120.0, 1.0, 35.0,
           "Pimax Crystal specs (pimax.com, 2023): 2880x2880 per eye, 72/90/120 Hz, 35 PPD centre, "
           "115 H deg; 105 V deg approximate; Tobii eye tracking 120 Hz, accuracy 1.0 deg assumed"),
  };
  return all;
}

}  // namespace

const DisplaySpec* find_display_preset(std::string_view name) {
  for (const DisplaySpec& d : presets())
    if (d.name == name) return &d;
  return nullptr;
}

std::span<const DisplaySpec> display_presets() {
  return presets();
}

}  // namespace gazelod::lod
