// SPDX-License-Identifier: Apache-2.0
// A scenario back to JSON (version 1), explicit: display fields in radians, generated objects
// listed one by one, so that load_scenario_json(scenario_to_json(s)) equals s.
#include "sim/simulator.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

namespace gazelod::sim {
namespace {

nlohmann::json vec(const glm::dvec3& v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

const char* delivery_name(GazeDelivery g) {
  switch (g) {
    case GazeDelivery::never_delivers:
      return "never_delivers";
    case GazeDelivery::sample_time_zero:
      return "sample_time_zero";
    case GazeDelivery::sample_time_is_request_time:
      return "sample_time_is_request_time";
    case GazeDelivery::normal:
      break;
  }
  return "normal";
}

}  // namespace

std::string scenario_to_json(const Scenario& sc) {
  const lod::DisplaySpec& d = sc.display;
  const lod::ViewSpec& v = d.views[0];
  nlohmann::json display = {{"name", d.name},
                            {"label", d.label},
                            {"views", d.view_count},
                            {"width_px", v.width_px},
                            {"height_px", v.height_px},
                            {"fov_rad",
                             {{"left", v.fov.angle_left_rad},
                              {"right", v.fov.angle_right_rad},
                              {"up", v.fov.angle_up_rad},
                              {"down", v.fov.angle_down_rad}}},
                            {"refresh_hz", d.refresh_hz},
                            {"eye_tracking_hz", d.eye_tracking_hz},
                            {"eye_tracking_accuracy_deg", d.eye_tracking_accuracy_deg},
                            {"center_ppd", d.center_ppd},
                            {"source", d.source}};
  nlohmann::json objects = nlohmann::json::array();
  for (const SceneObject& o : sc.objects) {
    nlohmann::json lods = nlohmann::json::array();
    for (const lod::LodLevel& l : o.lods)
      lods.push_back(
          {{"triangles", l.triangles},
           {"vertices", l.vertices},
           {"detail_kind",
            l.detail_kind == lod::DetailKind::geometric_error_m ? "geometric_error_m" : "removed_cycles_per_diameter"},
           {"detail", l.detail}});
    objects.push_back({{"name", o.name},
                       {"position_m", vec(o.position_m)},
                       {"velocity_m_s", vec(o.velocity_m_s)},
                       {"radius_m", o.radius_m},
                       {"importance", o.importance},
                       {"lods", lods}});
  }
  nlohmann::json effects = nlohmann::json::array();
  for (const EffectSpec& e : sc.effects) {
    nlohmann::json p = nlohmann::json::parse(e.params_json, nullptr, /*allow_exceptions=*/false);
    if (!p.is_object()) p = nlohmann::json::object();
    p["type"] = e.type;
    effects.push_back(std::move(p));
  }
  nlohmann::json j = {
      {"version", sc.version},
      {"name", sc.name},
      {"display", display},
      {"duration_s", sc.duration_s},
      {"frame_rate_hz", sc.frame_rate_hz},
      {"seed", sc.seed},
      {"scene",
       {{"objects", objects},
        {"head_path", {{"start_m", vec(sc.head_path.start_m)}, {"velocity_m_s", vec(sc.head_path.velocity_m_s)}}}}},
      {"effects", effects},
      {"runtime",
       {{"eye_gaze_supported", sc.runtime.eye_gaze_supported},
        {"gaze_delivery", delivery_name(sc.runtime.gaze_delivery)},
        {"paced", sc.runtime.paced}}}};
  return aux::json_text(j, 2) + "\n";
}

}  // namespace gazelod::sim
