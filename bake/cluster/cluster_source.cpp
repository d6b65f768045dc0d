// SPDX-License-Identifier: Apache-2.0
// Welding and source chunks for the cluster hierarchy build (cluster_source.hpp).
#include "bake/cluster/cluster_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace gazelod::bake {
namespace {

constexpr std::uint32_t kNone = ~0u;

// Source triangles in chunks of about this many, split into clusters in parallel; a chunk is a
// run of cells along a Morton curve, so clusters rarely need to cross one.
constexpr std::size_t kChunkTriangles = 65536;
constexpr unsigned kCellBits = 5;  // per axis

}  // namespace

// vertex -> the first vertex with bit-identical position (-0 counted as +0): the topology the
// grouping and the degenerate test see, as meshopt_simplify welds seams for its own topology.
std::vector<std::uint32_t> weld_positions(std::span<const float> pos) {
  const std::size_t n = pos.size() / 3;
  std::size_t size = 16;
  while (size < 2 * n) size *= 2;
  std::vector<std::uint32_t> table(size, kNone), weld(n);
  auto key = [&](std::size_t v, int k) {
    const float f = pos[3 * v + k] == 0.0f ? 0.0f : pos[3 * v + k];
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    return bits;
  };
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t x = key(v, 0), y = key(v, 1), z = key(v, 2);
    std::size_t h = (x * 73856093u) ^ (y * 19349663u) ^ (z * 83492791u);
    for (h &= size - 1;; h = (h + 1) & (size - 1)) {
      const std::uint32_t t = table[h];
      if (t == kNone) {
        table[h] = weld[v] = static_cast<std::uint32_t>(v);
        break;
      }
      if (key(t, 0) == x && key(t, 1) == y && key(t, 2) == z) {
        weld[v] = t;
        break;
      }
    }
  }
  return weld;
}

// Triangle ids in Morton order of their centroid's cell, cut into chunks at cell boundaries.
std::vector<std::vector<std::uint32_t>> source_chunks(std::span<const float> pos, std::span<const std::uint32_t> tris) {
  const std::size_t n = tris.size() / 3;
  std::vector<std::vector<std::uint32_t>> chunks;
  if (n <= kChunkTriangles) {
    chunks.emplace_back(n);
    for (std::size_t t = 0; t < n; ++t) chunks[0][t] = static_cast<std::uint32_t>(t);
    return chunks;
  }
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::uint32_t v : tris)
    for (int k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], double(pos[3 * v + k])), hi[k] = std::max(hi[k], double(pos[3 * v + k]));
  constexpr std::uint32_t side = 1u << kCellBits;
  std::vector<std::uint32_t> cell(n), first(std::size_t{side} * side * side + 1, 0);
  for (std::size_t t = 0; t < n; ++t) {
    std::uint32_t q[3];
    for (int k = 0; k < 3; ++k) {
      const double c =
          (double(pos[3 * tris[3 * t] + k]) + pos[3 * tris[3 * t + 1] + k] + pos[3 * tris[3 * t + 2] + k]) / 3.0;
      const double u = hi[k] > lo[k] ? (c - lo[k]) / (hi[k] - lo[k]) : 0.0;
      q[k] = std::min(side - 1, static_cast<std::uint32_t>(std::max(0.0, u) * side));
    }
    std::uint32_t code = 0;
    for (int b = kCellBits - 1; b >= 0; --b)
      code = (code << 3) | ((q[0] >> b & 1u) << 2) | ((q[1] >> b & 1u) << 1) | (q[2] >> b & 1u);
    cell[t] = code;
    ++first[code + 1];
  }
  for (std::size_t c = 1; c < first.size(); ++c) first[c] += first[c - 1];
  std::vector<std::uint32_t> order(n), fill(first.begin(), first.end() - 1);
  for (std::size_t t = 0; t < n; ++t) order[fill[cell[t]]++] = static_cast<std::uint32_t>(t);
  for (std::size_t a = 0; a < n;) {
    std::size_t b = std::min(n, a + kChunkTriangles);
    while (b < n && cell[order[b]] == cell[order[b - 1]]) ++b;
    chunks.emplace_back(order.begin() + static_cast<std::ptrdiff_t>(a), order.begin() + static_cast<std::ptrdiff_t>(b));
    a = b;
  }
  return chunks;
}

}  // namespace gazelod::bake
