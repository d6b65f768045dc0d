// SPDX-License-Identifier: Apache-2.0
#include "bake/terrain_mesh.hpp"

#include "bake/fractal_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace gazelod::bake {
namespace {

std::string num(double v) {
  char s[64];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

// Octaves from the largest hills down to two grid cells (finer ones would alias on the grid).
FractalNoiseOptions noise_options(const TerrainOptions& o) {
  FractalNoiseOptions n;
  n.seed = o.seed;
  const double spacing_m = o.size_m / static_cast<double>(terrain_quads_per_side(o));
  const double ratio = spacing_m > 0.0 ? o.wavelength_m / (2.0 * spacing_m) : 1.0;
  const double octaves = ratio > 1.0 ? std::floor(std::log2(ratio)) + 1.0 : 1.0;
  n.octaves = static_cast<int>(std::clamp(octaves, 1.0, 24.0));
  return n;
}

// 0 on the path, 1 beyond its blend, smoothstep between.
double path_weight(const TerrainOptions& o, double x_m) {
  const double d = std::abs(x_m) - o.path_half_width_m;
  if (o.path_half_width_m <= 0.0 || d >= o.path_blend_m) return 1.0;
  if (d <= 0.0) return 0.0;
  const double t = d / o.path_blend_m;  // path_blend_m > d > 0 here
  return t * t * (3.0 - 2.0 * t);
}

double height(const TerrainOptions& o, const FractalNoiseOptions& n, double x_m, double z_m) {
  return 0.5 * o.relief_m * path_weight(o, x_m) * fractal_noise(n, x_m / o.wavelength_m, z_m / o.wavelength_m);
}

}  // namespace

std::string terrain_options_error(const TerrainOptions& o) {
  if (o.triangles < 2 || o.triangles > kMaxGeneratedTriangles)
    return "--triangles: must be in [2, " + std::to_string(kMaxGeneratedTriangles) + "], got " +
           std::to_string(o.triangles);
  if (!(o.size_m >= 1.0 && o.size_m <= 1e5)) return "size: must be in [1, 100000] m, got " + num(o.size_m);
  if (!(o.relief_m >= 0.0 && o.relief_m <= 1e4)) return "relief: must be in [0, 10000] m, got " + num(o.relief_m);
  if (!(o.wavelength_m > 0.0 && o.wavelength_m <= 1e6))
    return "wavelength: must be in (0, 1e6] m, got " + num(o.wavelength_m);
  if (!(o.path_half_width_m >= 0.0 && o.path_half_width_m <= 1e6))
    return "path half width: must be in [0, 1e6] m, got " + num(o.path_half_width_m);
  if (!(o.path_blend_m >= 0.0 && o.path_blend_m <= 1e6))
    return "path blend: must be in [0, 1e6] m, got " + num(o.path_blend_m);
  if (o.tiles < 1 || o.tiles > 64) return "--tiles: must be in [1, 64], got " + std::to_string(o.tiles);
  return "";
}

std::uint32_t terrain_quads_per_side(const TerrainOptions& o) {
  const auto tiles = static_cast<std::uint64_t>(std::max(o.tiles, 1));
  auto n = static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(o.triangles) / 2.0)));
  while (2 * n * n < o.triangles) ++n;  // the square root's rounding
  n = std::max<std::uint64_t>(n, 1);
  n = (n + tiles - 1) / tiles * tiles;
  return static_cast<std::uint32_t>(n);
}

double terrain_height_m(const TerrainOptions& o, double x_m, double z_m) {
  return height(o, noise_options(o), x_m, z_m);
}

std::vector<GeneratedMesh> terrain_meshes(const TerrainOptions& o) {
  if (const std::string e = terrain_options_error(o); !e.empty()) throw std::invalid_argument(e);
  const FractalNoiseOptions noise = noise_options(o);
  const std::uint32_t n = terrain_quads_per_side(o);
  const auto tiles = static_cast<std::uint32_t>(o.tiles);
  const std::uint32_t per_tile = n / tiles;
  const double spacing_m = o.size_m / n;
  // Grid point (i, j) -> (x, z): from the global index, so seam vertices match bit for bit.
  auto coord = [&](std::uint32_t i) { return -0.5 * o.size_m + o.size_m * i / n; };

  std::vector<GeneratedMesh> meshes;
  meshes.reserve(std::size_t{tiles} * tiles);
  for (std::uint32_t row = 0; row < tiles; ++row)
    for (std::uint32_t col = 0; col < tiles; ++col) {
      GeneratedMesh m;
      m.name = tiles == 1 ? "terrain" : "terrain_" + std::to_string(row) + "_" + std::to_string(col);
      const std::uint32_t side = per_tile + 1;
      m.positions.reserve(std::size_t{side} * side * 3);
      m.normals.reserve(std::size_t{side} * side * 3);
      for (std::uint32_t jj = 0; jj <= per_tile; ++jj)
        for (std::uint32_t ii = 0; ii <= per_tile; ++ii) {
          const double x = coord(col * per_tile + ii), z = coord(row * per_tile + jj);
          const double y = height(o, noise, x, z);
          // Central differences one grid step wide: the surface the grid samples.
          const double dy_dx =
              (height(o, noise, x + spacing_m, z) - height(o, noise, x - spacing_m, z)) / (2.0 * spacing_m);
          const double dy_dz =
              (height(o, noise, x, z + spacing_m) - height(o, noise, x, z - spacing_m)) / (2.0 * spacing_m);
          const double len = std::sqrt(dy_dx * dy_dx + 1.0 + dy_dz * dy_dz);  // >= 1
          m.positions.insert(m.positions.end(), {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
          m.normals.insert(m.normals.end(), {static_cast<float>(-dy_dx / len), static_cast<float>(1.0 / len),
                                             static_cast<float>(-dy_dz / len)});
        }
      m.indices.reserve(std::size_t{per_tile} * per_tile * 6);
      for (std::uint32_t jj = 0; jj < per_tile; ++jj)
        for (std::uint32_t ii = 0; ii < per_tile; ++ii) {
          const std::uint32_t a = jj * side + ii, b = a + 1, c = a + side, d = c + 1;
          // Counter-clockwise seen from +Y (above).
          m.indices.insert(m.indices.end(), {a, c, d, a, d, b});
        }
      meshes.push_back(std::move(m));
    }
  return meshes;
}

}  // namespace gazelod::bake
