// SPDX-License-Identifier: Apache-2.0
// A generated terrain for large-mesh tests (`gazelod scene generate terrain`): a regular
// height-field grid over a square centred on the origin, +Y up, heights from fractal gradient
// noise (bake/fractal_noise.hpp) deterministic by seed. A flat path runs along the Z axis at
// height 0 (|x| under path_half_width_m, blending into the hills over path_blend_m), so a
// viewer walking along it at a constant eye height stays that high above the ground
// (sim/scenarios/terrain-walk.json).
//
// The grid has n x n quads, two triangles each, with n = ceil(sqrt(triangles / 2)) rounded up
// to a multiple of `tiles`: at least `triangles` triangles. tiles > 1 splits it into tiles x
// tiles meshes (named "terrain_ROW_COL"; one mesh "terrain" otherwise), each with its own
// vertices; vertices on a seam are computed from the same grid point, so they are
// bit-identical on both sides (per-object LOD baselines get one object per tile).
#pragma once

#include "bake/generated_scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::bake {

inline constexpr std::uint64_t kMaxGeneratedTriangles = 20'000'000;

struct TerrainOptions {
  std::uint64_t triangles = 1'000'000;  // at least this many, [2, kMaxGeneratedTriangles]
  std::uint64_t seed = 1;
  double size_m = 300.0;           // side of the square, [1, 100000]
  double relief_m = 40.0;          // heights lie in [-relief/2, relief/2], [0, 10000]
  double wavelength_m = 120.0;     // the largest hills' lattice cell, (0, 1e6]
  double path_half_width_m = 3.0;  // the flat path along Z, >= 0 (0: no path)
  double path_blend_m = 15.0;      // from the path to the full hills, >= 0
  int tiles = 1;                   // meshes per side, [1, 64]
};

// "" when the options are in range, else which option and why (--triangles: ...).
std::string terrain_options_error(const TerrainOptions& options);

// The grid's quads per side for these options.
std::uint32_t terrain_quads_per_side(const TerrainOptions& options);

// Height of the ground at (x, z), metres. Options must be valid.
double terrain_height_m(const TerrainOptions& options, double x_m, double z_m);

// The meshes, row-major over tiles (row along +Z). Throws std::invalid_argument with
// terrain_options_error's message for bad options.
std::vector<GeneratedMesh> terrain_meshes(const TerrainOptions& options);

}  // namespace gazelod::bake
