// SPDX-License-Identifier: Apache-2.0
// find_folds (cluster_flips.hpp): vertex normals from the triangles before, one dot product
// per triangle after.
#include "bake/cluster_flips.hpp"

#include "bake/meshopt_lock.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::bake {
namespace {

void face_normal(std::span<const float> p, std::uint32_t a, std::uint32_t b, std::uint32_t c, double n[3]) {
  const double u[3] = {double(p[3 * b]) - p[3 * a], double(p[3 * b + 1]) - p[3 * a + 1],
                       double(p[3 * b + 2]) - p[3 * a + 2]};
  const double v[3] = {double(p[3 * c]) - p[3 * a], double(p[3 * c + 1]) - p[3 * a + 1],
                       double(p[3 * c + 2]) - p[3 * a + 2]};
  n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
}

}  // namespace

Folds find_folds(std::span<const float> p, std::span<const std::uint32_t> before, std::span<const std::uint32_t> after,
                 std::vector<float>& normals, std::vector<std::uint32_t>* folded_corners) {
  normals.assign(p.size(), 0.0f);
  for (std::size_t t = 0; t + 2 < before.size(); t += 3) {
    double n[3];
    face_normal(p, before[t], before[t + 1], before[t + 2], n);
    for (std::size_t k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) normals[3 * std::size_t{before[t + k]} + j] += static_cast<float>(n[j]);
  }
  Folds f;
  for (std::size_t t = 0; t + 2 < after.size(); t += 3) {
    double n[3], dot = 0.0;
    face_normal(p, after[t], after[t + 1], after[t + 2], n);
    for (std::size_t k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) dot += n[j] * normals[3 * std::size_t{after[t + k]} + j];
    if (dot >= 0.0) continue;
    ++f.triangles;
    if (folded_corners) folded_corners->insert(folded_corners->end(), {after[t], after[t + 1], after[t + 2]});
    // Its width in the surface it should lie in: projected on the plane across the corners'
    // normal (a sliver turned just past upright on a terrain covers almost nothing wrongly; a
    // panel turned over in a wall does), the smallest altitude, twice its area over its
    // longest edge.
    double r[3] = {0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) r[j] += normals[3 * std::size_t{after[t + k]} + j];
    const double r_len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (!(r_len > 0.0)) continue;
    for (double& x : r) x /= r_len;
    const double twice_area = std::fabs(n[0] * r[0] + n[1] * r[1] + n[2] * r[2]);
    double longest_sq = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t a = after[t + k], b = after[t + (k + 1) % 3];
      double e[3];
      for (int j = 0; j < 3; ++j) e[j] = double(p[3 * b + j]) - p[3 * a + j];
      const double along = e[0] * r[0] + e[1] * r[1] + e[2] * r[2];
      for (int j = 0; j < 3; ++j) e[j] -= along * r[j];
      longest_sq = std::max(longest_sq, e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    }
    if (longest_sq > 0.0) f.width_m = std::max(f.width_m, twice_area / std::sqrt(longest_sq));
  }
  return f;
}

std::size_t lock_around_folds(std::vector<float>& positions_xyz, std::size_t vertex_count,
                              std::span<const std::uint32_t> before, std::span<const std::uint32_t> corners,
                              std::vector<std::uint8_t>& marks) {
  marks.assign(vertex_count, 0);
  for (std::uint32_t v : corners) marks[v] = 1;  // 1: a corner; 2: touches one
  for (std::size_t t = 0; t + 2 < before.size(); t += 3)
    if ((marks[before[t]] | marks[before[t + 1]] | marks[before[t + 2]]) & 1)
      for (std::size_t k = 0; k < 3; ++k) marks[before[t + k]] |= 2;
  std::size_t locked = 0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (!marks[v]) continue;
    lock_position(positions_xyz, v);
    ++locked;
  }
  return locked;
}

}  // namespace gazelod::bake
