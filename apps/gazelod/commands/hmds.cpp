// SPDX-License-Identifier: Apache-2.0
// gazelod hmds: the display presets with their figures and where the figures come from.
#include "lod/acuity.hpp"
#include "lod/display.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <memory>
#include <sstream>

namespace gazelod::cli {
namespace {

int run_hmds(bool json, Io io) {
  if (json) {
    nlohmann::json all = nlohmann::json::array();
    for (const lod::DisplaySpec& d : lod::display_presets()) {
      const lod::ViewSpec& v = d.views[0];
      const double xi = lod::xi_cpd(d);
      all.push_back({{"name", d.name},
                     {"label", d.label},
                     {"views", d.view_count},
                     {"pixels", {v.width_px, v.height_px}},
                     {"fov_deg", {lod::fov_h_deg(v), lod::fov_v_deg(v)}},
                     {"fov_rad",
                      {{"angle_left", v.fov.angle_left_rad},
                       {"angle_right", v.fov.angle_right_rad},
                       {"angle_up", v.fov.angle_up_rad},
                       {"angle_down", v.fov.angle_down_rad}}},
                     {"xi_cpd", xi},
                     {"xi_h_cpd", lod::xi_h_cpd(v)},
                     {"xi_v_cpd", lod::xi_v_cpd(v)},
                     {"center_ppd", d.center_ppd},
                     {"eccentricity_threshold_deg", lod::eccentricity_threshold_deg(xi)},
                     {"velocity_threshold_dps", lod::velocity_threshold_dps(xi)},
                     {"refresh_hz", d.refresh_hz},
                     {"eye_tracking_hz", d.eye_tracking_hz},
                     {"eye_tracking_accuracy_deg", d.eye_tracking_accuracy_deg},
                     {"source", d.source}});
    }
    io.out << aux::json_text(all, 2) << "\n";
    return 0;
  }
  io.out << std::left << std::setw(13) << "name" << std::setw(12) << "pixels/eye" << std::setw(14) << "FOV deg"
         << std::setw(8) << "xi c/d" << std::setw(8) << "E thr" << std::setw(8) << "v thr" << std::setw(7) << "Hz"
         << std::setw(9) << "ET Hz"
         << "ET err deg\n";
  io.out << std::fixed << std::setprecision(1);
  for (const lod::DisplaySpec& d : lod::display_presets()) {
    const lod::ViewSpec& v = d.views[0];
    const double xi = lod::xi_cpd(d);
    std::ostringstream px, fov;
    px << v.width_px << "x" << v.height_px;
    fov << std::fixed << std::setprecision(1) << lod::fov_h_deg(v) << "x" << lod::fov_v_deg(v);
    io.out << std::setw(13) << d.name << std::setw(12) << px.str() << std::setw(14) << fov.str() << std::setw(8) << xi
           << std::setw(8) << lod::eccentricity_threshold_deg(xi) << std::setw(8) << lod::velocity_threshold_dps(xi)
           << std::setw(7) << d.refresh_hz << std::setw(9) << d.eye_tracking_hz << d.eye_tracking_accuracy_deg << "\n";
  }
  io.out << "\nsources:\n";
  for (const lod::DisplaySpec& d : lod::display_presets()) io.out << "  " << d.name << ": " << d.source << "\n";
  return 0;
}

const Registrar registrar{"hmds", "List the display presets with their figures and sources",
                          [](CLI::App& sub) -> Action {
                            auto json = std::make_shared<bool>(false);
                            sub.add_flag("--json", *json, "print a JSON array");
                            return [json](Io io) { return run_hmds(*json, io); };
                          }};

}  // namespace
}  // namespace gazelod::cli
