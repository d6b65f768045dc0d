// SPDX-License-Identifier: Apache-2.0
// The thesis's LOD map (apps/gazelod/eval/lod_map.hpp) evaluated beside the plugin in `gazelod run`: per frame,
// the same objects, eye, gaze and head motion the plugin used, run through the map policy
// offline (nothing it picks is drawn), so reports can compare its triangles and average LOD
// with Reddy's criteria sets. Eccentricity, retinal speed and angular radius come from
// lod::select_lods' diagnostics, i.e. exactly the plugin's geometry.
#pragma once

#include "lod/lod_chain.hpp"
#include "lod/display.hpp"
#include "apps/gazelod/eval/lod_map.hpp"
#include "apps/gazelod/run/in_view.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::cli {

struct LodMapFrame {
  std::uint64_t triangles = 0;       // per eye
  std::uint64_t lod_sum = 0;         // sum of the chosen levels (average = lod_sum / objects)
  std::vector<std::uint8_t> levels;  // per object
};

// The map's choice for one frame. `objects` and `radii` are indexed like `chains`;
// `eye_velocity_m_s` is the head's translation (the simulator's truth). Objects the
// selection rejects (non-finite data) keep level 0.
LodMapFrame lod_map_frame(const std::vector<std::vector<lod::LodLevel>>& chains,
                          std::span<const sim::ObjectState> objects, std::span<const double> radii,
                          const FrameDiagnostics& d, const glm::dvec3& eye_velocity_m_s,
                          const lod::LodMapParams& params = {});

}  // namespace gazelod::cli
