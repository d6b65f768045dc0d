// SPDX-License-Identifier: Apache-2.0
// Helpers for the simulator tests: a small scenario with the given effects and objects.
#pragma once

#include "sim/simulator.hpp"

#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <string>

namespace gazelod::sim::test {

inline nlohmann::json base_scenario(nlohmann::json effects = nlohmann::json::array()) {
  return {{"version", 1},
          {"name", "test"},
          {"display", "questpro"},
          {"duration_s", 30},
          {"seed", 42},
          {"scene",
           {{"objects",
             {{{"name", "target"},
               {"position_m", {0.0, 0.0, -5.0}},
               {"velocity_m_s", {0.5, 0.0, 0.0}},
               {"radius_m", 0.3},
               {"lods", {{{"triangles", 1000}, {"detail", 0}}}}}}}}},
          {"effects", effects}};
}

inline Simulator make_sim(const nlohmann::json& j) {
  return Simulator(load_scenario_json(j.dump(), "test.json"));
}

inline double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / 3.14159265358979323846;
}

// Yaw (about +Y, positive left) and pitch of a direction, degrees: written out here rather
// than taken from auxiliary/yaw_pitch.hpp, so the tests check the convention independently.
inline double yaw_deg(const glm::dvec3& d) {
  return std::atan2(-d.x, -d.z) * 180.0 / 3.14159265358979323846;
}
inline double pitch_deg(const glm::dvec3& d) {
  return std::atan2(d.y, std::hypot(d.x, d.z)) * 180.0 / 3.14159265358979323846;
}

}  // namespace gazelod::sim::test
