// SPDX-License-Identifier: Apache-2.0
// xi per view and per display (Reddy 1998 equation 4) and display validation.
#include "auxiliary/angles.hpp"
#include "lod/display.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace gazelod::lod {
namespace {

// pixels / (2 fov): one pixel is half a contrast cycle. 0 for an invalid axis, never NaN/inf.
double half_cycles_per_deg(int pixels, double fov_deg) {
  if (pixels <= 0 || !(fov_deg > 0.0) || !std::isfinite(fov_deg)) return 0.0;
  return static_cast<double>(pixels) / (2.0 * fov_deg);
}

[[nodiscard]] std::string check_angle(const char* name, double rad) {
  std::ostringstream m;
  if (!std::isfinite(rad) || std::abs(rad) >= std::numbers::pi / 2)
    m << name << " must be a finite angle in (-90, 90) deg, got " << rad * aux::kDegPerRad << " deg";
  return m.str();
}

}  // namespace

double fov_h_deg(const ViewSpec& view) {
  return (view.fov.angle_right_rad - view.fov.angle_left_rad) * aux::kDegPerRad;
}
double fov_v_deg(const ViewSpec& view) {
  return (view.fov.angle_up_rad - view.fov.angle_down_rad) * aux::kDegPerRad;
}

FovRad symmetric_fov(double h_deg, double v_deg) {
  const double h = h_deg / aux::kDegPerRad / 2.0;
  const double v = v_deg / aux::kDegPerRad / 2.0;
  return FovRad{-h, h, v, -v};
}

double xi_h_cpd(const ViewSpec& view) {
  return half_cycles_per_deg(view.width_px, fov_h_deg(view));
}
double xi_v_cpd(const ViewSpec& view) {
  return half_cycles_per_deg(view.height_px, fov_v_deg(view));
}
double xi_cpd(const ViewSpec& view) {
  return std::max(xi_h_cpd(view), xi_v_cpd(view));
}

// The best view: xi is the highest frequency the display can show anywhere.
double xi_cpd(const DisplaySpec& display) {
  double xi = 0.0;
  const int n = std::clamp(display.view_count, 0, 2);
  for (int i = 0; i < n; ++i) xi = std::max(xi, xi_cpd(display.views[i]));
  return xi;
}

double xi_center_cpd(const DisplaySpec& display) {
  if (display.center_ppd > 0.0 && std::isfinite(display.center_ppd)) return display.center_ppd / 2.0;
  return xi_cpd(display);
}

std::string validate_view(const ViewSpec& view) {
  std::ostringstream m;
  if (view.width_px <= 0 || view.height_px <= 0) {
    m << "pixels must be > 0 on both axes, got " << view.width_px << "x" << view.height_px;
    return m.str();
  }
  for (auto [name, rad] :
       {std::pair{"angleLeft", view.fov.angle_left_rad}, std::pair{"angleRight", view.fov.angle_right_rad},
        std::pair{"angleUp", view.fov.angle_up_rad}, std::pair{"angleDown", view.fov.angle_down_rad}}) {
    std::string e = check_angle(name, rad);
    if (!e.empty()) return e;
  }
  const double h = fov_h_deg(view), v = fov_v_deg(view);
  if (!(h > 0.0 && h < 180.0)) {
    m << "horizontal FOV (angleRight - angleLeft) must be in (0, 180) deg, got " << h;
    return m.str();
  }
  if (!(v > 0.0 && v < 180.0)) {
    m << "vertical FOV (angleUp - angleDown) must be in (0, 180) deg, got " << v;
    return m.str();
  }
  return {};
}

std::string validate_described_view(const ViewSpec& view) {
  if (view.width_px <= 0 || view.height_px <= 0) return validate_view(view);
  std::ostringstream m;
  for (auto [axis, deg] : {std::pair{"horizontal", fov_h_deg(view)}, std::pair{"vertical", fov_v_deg(view)}}) {
    // A relative 1e-12: degrees -> radians -> degrees must not move a limit outside itself.
    if (!(deg >= kMinFovDeg * (1.0 - 1e-12) && deg <= kMaxFovDeg * (1.0 + 1e-12))) {
      m << axis << " FOV must be in [" << kMinFovDeg << ", " << kMaxFovDeg << "] deg, got " << deg;
      return m.str();
    }
  }
  return validate_view(view);
}

std::string validate_display(const DisplaySpec& display) {
  std::ostringstream m;
  if (display.view_count < 1 || display.view_count > 2) {
    m << "view_count must be 1 or 2, got " << display.view_count;
    return m.str();
  }
  for (int i = 0; i < display.view_count; ++i) {
    std::string e = validate_view(display.views[i]);
    if (!e.empty()) return "view " + std::to_string(i) + ": " + e;
  }
  if (!(display.refresh_hz > 0.0 && std::isfinite(display.refresh_hz))) {
    m << "refresh_hz must be > 0, got " << display.refresh_hz;
    return m.str();
  }
  if (!(display.eye_tracking_hz >= 0.0 && std::isfinite(display.eye_tracking_hz))) {
    m << "eye_tracking_hz must be >= 0, got " << display.eye_tracking_hz;
    return m.str();
  }
  if (!(display.eye_tracking_accuracy_deg >= 0.0 && display.eye_tracking_accuracy_deg < 90.0)) {
    m << "eye_tracking_accuracy_deg must be in [0, 90), got " << display.eye_tracking_accuracy_deg;
    return m.str();
  }
  return {};
}

}  // namespace gazelod::lod
