// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/scenario.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace gazelod::cli {
namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double uniform(std::uint64_t& state, double lo, double hi) {
  const double u = static_cast<double>(splitmix64(state) >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

struct Position {
  double x, y, z;
};

}  // namespace

std::string reddy_scenario_json(const ReddyScenario& s) {
  nlohmann::json lods = nlohmann::json::array();
  for (std::size_t k = 0; k < kReddyTriangles.size(); ++k) {
    const double t = kReddyTriangles[k];
    lods.push_back({{"triangles", kReddyTriangles[k]},
                    {"vertices", kReddyTriangles[k] / 2 + 2},
                    {"detail_kind", "removed_cycles_per_diameter"},
                    {"detail", k == 0 ? 0.0 : std::sqrt(t) / 2.0}});
  }
  // The field the observer flies into: 21.8 m of path in 5 s, objects out to 80 m ahead and
  // spread beyond the 43.6 x 33.4 deg frustum so the periphery is populated.
  std::uint64_t state = s.layout_seed * 0x2545F4914F6CDD1DULL + 17;
  nlohmann::json objects = nlohmann::json::array();
  for (int i = 0; i < s.objects; ++i) {
    Position p{uniform(state, -20, 20), uniform(state, -12, 12), uniform(state, -80, -5)};
    if (s.surround) {
      const double azimuth = uniform(state, 0.0, 6.283185307179586), dist = uniform(state, 5.0, 80.0);
      p = {dist * std::sin(azimuth), uniform(state, -12, 12), -dist * std::cos(azimuth)};
    }
    std::string name = "o";  // (not "o" + to_string: GCC 12's -Wrestrict false positive)
    name += std::to_string(i);
    objects.push_back({{"name", name},
                       {"position_m", {p.x, p.y, p.z}},
                       {"radius_m", s.radius_scale * uniform(state, 0.3, 1.5)},
                       {"lods", lods}});
  }
  nlohmann::json j = {
      {"version", 1},
      {"name", std::string("reddy_n")
                   .append(std::to_string(s.objects))
                   .append("_layout")
                   .append(std::to_string(s.layout_seed))},
      {"display",
       {{"name", "reddy-sgi"},
        {"width_px", s.width_px},
        {"height_px", s.height_px},
        {"fov_h_deg", 43.6},
        {"fov_v_deg", 33.4}}},
      {"duration_s", s.duration_s},
      {"frame_rate_hz", s.frame_rate_hz},
      {"seed", s.layout_seed},
      {"scene", {{"objects", objects}, {"head_path", {{"start_m", {0, 0, 0}}, {"velocity_m_s", {0, 0, -4.36}}}}}},
      {"effects", nlohmann::json::array()},
      {"runtime", {{"paced", false}}}};
  if (s.head_turn_deg_s != 0.0)
    j["effects"].push_back(
        {{"type", "head_turn"}, {"rate_deg_s", s.head_turn_deg_s}, {"start_s", 0.0}, {"duration_s", s.duration_s}});
  return aux::json_text(j, 1);
}

}  // namespace gazelod::cli
