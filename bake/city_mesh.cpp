// SPDX-License-Identifier: Apache-2.0
#include "bake/city_mesh.hpp"

#include "auxiliary/random.hpp"
#include "bake/terrain_mesh.hpp"  // kMaxGeneratedTriangles

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

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

std::uint32_t panels(double length_m, double panel_m) {
  return static_cast<std::uint32_t>(std::max(1.0, std::ceil(length_m / panel_m)));
}

// A planar grid of nu x nv panels from `origin` along u and v; u x v points outward, and the
// triangles wind counter-clockwise around it.
void add_face(GeneratedMesh& m, const glm::dvec3& origin, const glm::dvec3& u, const glm::dvec3& v, std::uint32_t nu,
              std::uint32_t nv) {
  const glm::dvec3 c = glm::cross(u, v);
  const double len = glm::length(c);
  const glm::dvec3 n = len > 0.0 ? c / len : glm::dvec3(0.0, 1.0, 0.0);
  const auto first = static_cast<std::uint32_t>(m.positions.size() / 3);
  for (std::uint32_t j = 0; j <= nv; ++j)
    for (std::uint32_t i = 0; i <= nu; ++i) {
      const glm::dvec3 p = origin + u * (static_cast<double>(i) / nu) + v * (static_cast<double>(j) / nv);
      m.positions.insert(m.positions.end(),
                         {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
      m.normals.insert(m.normals.end(), {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)});
    }
  for (std::uint32_t j = 0; j < nv; ++j)
    for (std::uint32_t i = 0; i < nu; ++i) {
      const std::uint32_t a = first + j * (nu + 1) + i, b = a + 1, d = a + nu + 2, e = a + nu + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, e});
    }
}

// A box on the ground: four walls and a roof (no floor), x in [x0, x1], z in [z0, z1].
void add_building(GeneratedMesh& m, double x0, double x1, double z0, double z1, double h, double panel) {
  const glm::dvec3 up(0.0, h, 0.0);
  const std::uint32_t nx = panels(x1 - x0, panel), nz = panels(z1 - z0, panel), ny = panels(h, panel);
  add_face(m, {x0, 0.0, z1}, {x1 - x0, 0.0, 0.0}, up, nx, ny);                 // +Z wall
  add_face(m, {x1, 0.0, z0}, {x0 - x1, 0.0, 0.0}, up, nx, ny);                 // -Z wall
  add_face(m, {x1, 0.0, z1}, {0.0, 0.0, z0 - z1}, up, nz, ny);                 // +X wall
  add_face(m, {x0, 0.0, z0}, {0.0, 0.0, z1 - z0}, up, nz, ny);                 // -X wall
  add_face(m, {x0, h, z0}, {0.0, 0.0, z1 - z0}, {x1 - x0, 0.0, 0.0}, nz, nx);  // roof
}

// Block (bx, bz): 2 x 2 lots, one building each, drawn from the block's own random stream.
GeneratedMesh make_block(const CityOptions& o, int bx, int bz) {
  GeneratedMesh m;
  m.name = "block_" + std::to_string(bz) + "_" + std::to_string(bx);
  const double pitch = o.block_m + o.street_m;
  const double bx0 = bx * pitch + 0.5 * o.street_m, bz0 = bz * pitch + 0.5 * o.street_m;
  const double lot = 0.5 * o.block_m;
  const aux::CounterRng rng{o.seed, aux::mix64(static_cast<std::uint64_t>(static_cast<std::int64_t>(bx)) * 0x10001ULL) ^
                                        static_cast<std::uint64_t>(static_cast<std::int64_t>(bz))};
  for (std::uint64_t k = 0; k < 4; ++k) {
    const double lx = bx0 + lot * static_cast<double>(k % 2), lz = bz0 + lot * static_cast<double>(k / 2);
    // A setback of 5 % to 25 % of the lot on each side, and the height.
    const double max_in = 0.25 * lot, min_in = 0.05 * lot;
    const double x0 = lx + rng.uniform(5 * k, min_in, max_in), x1 = lx + lot - rng.uniform(5 * k + 1, min_in, max_in);
    const double z0 = lz + rng.uniform(5 * k + 2, min_in, max_in),
                 z1 = lz + lot - rng.uniform(5 * k + 3, min_in, max_in);
    const double h = rng.uniform(5 * k + 4, o.height_min_m, o.height_max_m);
    add_building(m, x0, x1, z0, z1, h, o.panel_m);
  }
  return m;
}

}  // namespace

std::string city_options_error(const CityOptions& o) {
  if (o.triangles < 2 || o.triangles > kMaxGeneratedTriangles)
    return "--triangles: must be in [2, " + std::to_string(kMaxGeneratedTriangles) + "], got " +
           std::to_string(o.triangles);
  if (!(o.block_m >= 10.0 && o.block_m <= 1000.0)) return "block: must be in [10, 1000] m, got " + num(o.block_m);
  if (!(o.street_m >= 2.0 && o.street_m <= 1000.0)) return "street: must be in [2, 1000] m, got " + num(o.street_m);
  if (!(o.panel_m >= 0.25 && o.panel_m <= 100.0)) return "panel: must be in [0.25, 100] m, got " + num(o.panel_m);
  if (!(o.height_min_m >= 1.0 && o.height_max_m <= 1000.0 && o.height_min_m <= o.height_max_m))
    return "heights: need 1 <= min <= max <= 1000 m, got " + num(o.height_min_m) + ".." + num(o.height_max_m);
  return "";
}

std::vector<GeneratedMesh> city_meshes(const CityOptions& o) {
  if (const std::string e = city_options_error(o); !e.empty()) throw std::invalid_argument(e);
  std::vector<GeneratedMesh> meshes;
  std::uint64_t total = 0;
  int rings = 0;
  // Ring r holds the blocks with bx, bz in [-r, r - 1] not in ring r - 1. The loop ends: every
  // block adds at least 4 x 5 x 2 triangles.
  while (total < o.triangles) {
    ++rings;
    const int r = rings;
    for (int bz = -r; bz < r && total < o.triangles; ++bz)
      for (int bx = -r; bx < r && total < o.triangles; ++bx) {
        const bool inner = bx >= -(r - 1) && bx < r - 1 && bz >= -(r - 1) && bz < r - 1;
        if (inner) continue;
        meshes.push_back(make_block(o, bx, bz));
        total += meshes.back().triangles();
      }
  }
  // The ground under every ring, in cells of a quarter block.
  const double half = rings * (o.block_m + o.street_m);
  GeneratedMesh ground;
  ground.name = "ground";
  const std::uint32_t cells = panels(2.0 * half, 0.25 * o.block_m);
  add_face(ground, {-half, 0.0, -half}, {0.0, 0.0, 2.0 * half}, {2.0 * half, 0.0, 0.0}, cells, cells);
  meshes.push_back(std::move(ground));
  return meshes;
}

}  // namespace gazelod::bake
