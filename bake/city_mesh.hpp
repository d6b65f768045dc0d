// SPDX-License-Identifier: Apache-2.0
// A generated city for large-mesh tests (`gazelod scene generate city`): square blocks of box
// buildings on a ground plane, +Y up, centred on the origin, deterministic by seed. Blocks of
// block_m lie on a grid with streets of street_m between them, the origin at a street
// crossing (so a walk along the Z axis follows a street: sim/scenarios/terrain-walk.json).
// Each block holds 2 x 2 lots with one building each (footprint and height drawn per lot);
// every wall and roof is a grid of panel_m panels (window bays), so the triangle count comes
// from the facades. Blocks are added in rings around the centre until the city has at least
// `triangles` triangles. One mesh per block ("block_ROW_COL", its buildings' faces with their
// own vertices and flat normals) plus one "ground" mesh.
#pragma once

#include "bake/generated_scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake {

struct CityOptions {
  std::uint64_t triangles = 1'000'000;  // at least this many, [2, kMaxGeneratedTriangles]
  std::uint64_t seed = 1;
  double block_m = 60.0;      // [10, 1000]
  double street_m = 16.0;     // [2, 1000]
  double panel_m = 1.5;       // facade panel size, [0.25, 100]
  double height_min_m = 8.0;  // building heights, [1, 1000], min <= max
  double height_max_m = 60.0;
};

// "" when the options are in range, else which option and why.
std::string city_options_error(const CityOptions& options);

// Blocks first (ring by ring, row-major within a ring), the ground last. Throws
// std::invalid_argument with city_options_error's message for bad options.
std::vector<GeneratedMesh> city_meshes(const CityOptions& options);

}  // namespace gazelod::bake
