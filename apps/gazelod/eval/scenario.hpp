// SPDX-License-Identifier: Apache-2.0
// The scenarios of `gazelod eval`: Reddy 1998's test environment (section 5) as a gazelod
// scenario. Randomly placed objects with the paper's four LODs (3928, 834, 254, 76 triangles),
// a 43.6 x 33.4 deg display, the observer flying forward at 4.36 m/s for 5 s, a still head and
// centred gaze (Reddy had no eye tracker), optionally a constant-rate head turn (yaw).
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace gazelod::cli {

inline constexpr std::array<std::uint32_t, 4> kReddyTriangles{3928, 834, 254, 76};

struct ReddyScenario {
  int objects = 100;
  std::uint64_t layout_seed = 1;  // the random positions and sizes
  double frame_rate_hz = 72.0;    // the SGI's video refresh; lower = fewer frames, same path
  double head_turn_deg_s = 0.0;   // 0: still head
  // Objects all around the observer (uniform azimuth, 5-80 m) instead of a field ahead, so a
  // head turning for 5 s keeps seeing a statistically unchanged scene.
  bool surround = false;
  double radius_scale = 1.0;  // multiplies the 0.3 to 1.5 m radii (a sensitivity check)
  double duration_s = 5.0;
  int width_px = 1280;  // assumed (the paper gives only the FOV)
  int height_px = 1024;
};

// The scenario as JSON text (sim/scenarios/README.md format, explicit objects). Object i's
// level k removes sqrt(triangles_k) / 2 cycles per diameter (the random_field convention).
// Positions are a pure function of layout_seed (splitmix64), so a layout is reproducible.
std::string reddy_scenario_json(const ReddyScenario& s);

}  // namespace gazelod::cli
