// SPDX-License-Identifier: Apache-2.0
#include "render/sphere_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::render {

SphereResolution sphere_resolution(std::uint32_t target_triangles) {
  const double target = std::clamp<double>(target_triangles, 6.0, kMaxSphereTriangles);
  // Near-square cells: slices ~ 2 * stacks gives 4 * stacks * (stacks - 1) triangles.
  const double stacks_d = 0.5 * (1.0 + std::sqrt(1.0 + target));
  SphereResolution r;
  r.stacks = std::max<std::uint32_t>(2u, static_cast<std::uint32_t>(std::lround(stacks_d)));
  // Then the slice count that brings the total closest to the target.
  const double slices_d = target / (2.0 * (r.stacks - 1.0));
  r.slices = std::max<std::uint32_t>(3u, static_cast<std::uint32_t>(std::lround(slices_d)));
  while (r.triangles() > kMaxSphereTriangles && r.slices > 3u) --r.slices;
  return r;
}

MeshData make_sphere(SphereResolution r) {
  r.stacks = std::max(r.stacks, 2u);
  r.slices = std::max(r.slices, 3u);
  MeshData m;
  const std::uint32_t rings = r.stacks - 1u;  // latitude rings between the poles
  m.positions.reserve(2u + rings * r.slices);
  m.positions.emplace_back(0.0f, 1.0f, 0.0f);  // north pole: index 0
  for (std::uint32_t i = 1; i <= rings; ++i) {
    const double polar = std::numbers::pi * i / r.stacks;
    for (std::uint32_t j = 0; j < r.slices; ++j) {
      const double azimuth = 2.0 * std::numbers::pi * j / r.slices;
      m.positions.emplace_back(static_cast<float>(std::sin(polar) * std::cos(azimuth)),
                               static_cast<float>(std::cos(polar)),
                               static_cast<float>(-std::sin(polar) * std::sin(azimuth)));
    }
  }
  const auto south = static_cast<std::uint32_t>(m.positions.size());
  m.positions.emplace_back(0.0f, -1.0f, 0.0f);

  auto ring = [&](std::uint32_t i, std::uint32_t j) { return 1u + (i - 1u) * r.slices + j % r.slices; };
  m.indices.reserve(3u * r.triangles());
  // Azimuth runs counter-clockwise seen from above (+y), so (pole, ring j, ring j+1) faces out.
  for (std::uint32_t j = 0; j < r.slices; ++j) m.indices.insert(m.indices.end(), {0u, ring(1, j), ring(1, j + 1)});
  for (std::uint32_t i = 1; i < rings; ++i)
    for (std::uint32_t j = 0; j < r.slices; ++j) {
      const std::uint32_t a = ring(i, j), b = ring(i, j + 1), c = ring(i + 1, j), d = ring(i + 1, j + 1);
      m.indices.insert(m.indices.end(), {a, c, d, a, d, b});
    }
  for (std::uint32_t j = 0; j < r.slices; ++j)
    m.indices.insert(m.indices.end(), {south, ring(rings, j + 1), ring(rings, j)});
  return m;
}

}  // namespace gazelod::render
