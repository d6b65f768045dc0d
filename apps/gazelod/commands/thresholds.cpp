// SPDX-License-Identifier: Apache-2.0
// gazelod thresholds: a display's xi and the eccentricity / velocity beyond which LOD may drop
// (Reddy 1998 sections 4.1-4.2, Figures 2 and 3), for a preset HMD or pixels + FOV.
#include "lod/acuity.hpp"
#include "lod/display.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <memory>
#include <optional>
#include <string>

namespace gazelod::cli {
namespace {

struct Options {
  std::string hmd, pixels, fov, at_ecc;
  bool json = false;
};

std::string fixed2(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

// "WxH" -> two numbers, each checked by the caller.
std::pair<std::string, std::string> split_x(const std::string& option, const std::string& text) {
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos || text.find_first_of("xX", x + 1) != std::string::npos)
    throw UsageError(option + ": expected AxB (e.g. 1280x1024), got '" + text + "'");
  return {text.substr(0, x), text.substr(x + 1)};
}

lod::ViewSpec custom_view(const Options& o) {
  auto [ws, hs] = split_x("--pixels", o.pixels);
  const double w = parse_number("--pixels", ws), h = parse_number("--pixels", hs);
  for (double p : {w, h})
    if (!(p >= 1.0) || p > 1.0e6 || p != std::floor(p))
      throw UsageError("--pixels: each side must be a whole number in [1, 1000000], got '" + o.pixels + "'");
  auto [fhs, fvs] = split_x("--fov", o.fov);
  const double fh = parse_number("--fov", fhs), fv = parse_number("--fov", fvs);
  // The rule scenario files follow too: each axis in [lod::kMinFovDeg, lod::kMaxFovDeg].
  lod::ViewSpec v{static_cast<int>(w), static_cast<int>(h), lod::symmetric_fov(fh, fv)};
  if (std::string e = lod::validate_described_view(v); !e.empty()) throw UsageError("--fov: " + e);
  return v;
}

int run_thresholds(const Options& o, Io io) {
  const bool custom = !o.pixels.empty() || !o.fov.empty();
  if (!o.hmd.empty() && custom) throw UsageError("--hmd: give either --hmd or --pixels with --fov, not both");
  if (o.hmd.empty() && !custom) throw UsageError("give --hmd NAME or --pixels WxH --fov HxV (try gazelod hmds)");
  if (custom && (o.pixels.empty() || o.fov.empty()))
    throw UsageError(o.pixels.empty() ? "--pixels: required with --fov" : "--fov: required with --pixels");

  lod::DisplaySpec display;
  if (!o.hmd.empty()) {
    const lod::DisplaySpec* d = lod::find_display_preset(o.hmd);
    if (!d) throw UsageError("--hmd: unknown HMD '" + o.hmd + "' (see gazelod hmds)");
    display = *d;
  } else {
    display.name = "custom";
    display.label = "custom display";
    display.view_count = 1;
    display.views[0] = custom_view(o);
  }
  std::optional<double> at_ecc;
  if (!o.at_ecc.empty()) {
    at_ecc = parse_number("--at-eccentricity", o.at_ecc);
    if (*at_ecc < 0.0 || *at_ecc > 180.0)
      throw UsageError("--at-eccentricity: must be in [0, 180] degrees, got '" + o.at_ecc + "'");
  }

  const lod::ViewSpec& view = display.views[0];
  const double xi = lod::xi_cpd(display);
  const double ecc_thr = lod::eccentricity_threshold_deg(xi, 0.0);
  const double vel_thr = lod::velocity_threshold_dps(xi, 0.0);

  if (o.json) {
    nlohmann::json j;
    j["display"] = display.name;
    j["pixels"] = {view.width_px, view.height_px};
    j["fov_deg"] = {lod::fov_h_deg(view), lod::fov_v_deg(view)};
    j["xi_cpd"] = xi;
    j["xi_h_cpd"] = lod::xi_h_cpd(view);
    j["xi_v_cpd"] = lod::xi_v_cpd(view);
    j["xi_center_cpd"] = lod::xi_center_cpd(display);
    // null: none within 180 deg (JSON has no infinity).
    j["eccentricity_threshold_deg"] = std::isfinite(ecc_thr) ? nlohmann::json(ecc_thr) : nlohmann::json(nullptr);
    j["velocity_threshold_dps"] = vel_thr;
    if (at_ecc) {
      j["at_eccentricity_deg"] = *at_ecc;
      j["velocity_threshold_at_eccentricity_dps"] = lod::velocity_threshold_dps(xi, *at_ecc);
    }
    io.out << aux::json_text(j, 2) << "\n";
    return 0;
  }
  io.out << std::fixed << std::setprecision(2);
  io.out << "display                         " << display.name
         << (display.label.empty() ? "" : " (" + display.label + ")") << "\n"
         << "pixels per view                 " << view.width_px << " x " << view.height_px << "\n"
         << "field of view (deg)             " << lod::fov_h_deg(view) << " x " << lod::fov_v_deg(view) << "\n"
         << "xi horizontal x vertical (c/deg) " << lod::xi_h_cpd(view) << " x " << lod::xi_v_cpd(view) << "\n"
         << "xi (c/deg)                      " << xi << "\n";
  if (display.center_ppd > 0.0) io.out << "xi at lens centre (c/deg)       " << lod::xi_center_cpd(display) << "\n";
  io.out << "eccentricity threshold (v = 0)  "
         << (std::isfinite(ecc_thr) ? fixed2(ecc_thr) + " deg" : std::string("none within 180 deg (H stays above xi)"))
         << "\n"
         << "velocity threshold (E = 0)      " << vel_thr << " deg/s\n";
  if (at_ecc)
    io.out << "velocity threshold at E = " << *at_ecc << " deg: " << lod::velocity_threshold_dps(xi, *at_ecc)
           << " deg/s\n";
  return 0;
}

const Registrar registrar{"thresholds",
                          "Highest displayable frequency xi and the eccentricity / velocity where LOD may drop "
                          "(Reddy 1998)",
                          [](CLI::App& sub) -> Action {
                            auto o = std::make_shared<Options>();
                            sub.add_option("--hmd", o->hmd, "display preset (gazelod hmds lists them)");
                            sub.add_option("--pixels", o->pixels, "pixels per view, WxH (with --fov)");
                            sub.add_option("--fov", o->fov, "field of view in degrees, HxV (with --pixels)");
                            sub.add_option("--at-eccentricity", o->at_ecc,
                                           "also the velocity threshold at this eccentricity (deg)");
                            sub.add_flag("--json", o->json, "print one JSON object");
                            return [o](Io io) { return run_thresholds(*o, io); };
                          }};

}  // namespace
}  // namespace gazelod::cli
