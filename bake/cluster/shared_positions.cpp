// SPDX-License-Identifier: Apache-2.0
// shared_positions.hpp: one hash of world positions -> the first (primitive, instance) there.
#include "bake/cluster/shared_positions.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <unordered_map>

namespace gazelod::bake {
namespace {

using Key = std::array<std::uint32_t, 3>;  // float bits; -0 and +0 are made one first

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) + k[1] * 0xBF58476D1CE4E5B9ull;
    h ^= (h >> 31) + k[2] * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

Key world_key(std::span<const float> xyz, std::size_t v, const glm::dmat4& w) {
  const glm::dvec4 p = w * glm::dvec4(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0);
  Key k;
  for (int i = 0; i < 3; ++i)
    k[static_cast<std::size_t>(i)] = std::bit_cast<std::uint32_t>(static_cast<float>(p[i]) + 0.0f);
  return k;
}

struct Owner {
  std::uint32_t primitive, instance;
  bool shared;
};

// Per vertex: on an edge (welded by position) that the triangles do not use exactly twice.
std::vector<std::uint8_t> on_open_border(std::span<const float> xyz, std::span<const std::uint32_t> tris) {
  const std::size_t n = xyz.size() / 3;
  std::unordered_map<Key, std::uint32_t, KeyHash> first;
  first.reserve(n);
  std::vector<std::uint32_t> weld(n);
  for (std::size_t v = 0; v < n; ++v)
    weld[v] = first.try_emplace(world_key(xyz, v, glm::dmat4(1.0)), static_cast<std::uint32_t>(v)).first->second;
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(tris.size());
  for (std::size_t t = 0; t + 2 < tris.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = weld[tris[t + k]], b = weld[tris[t + (k + 1) % 3]];
      if (a != b) ++uses[(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b)];
    }
  std::vector<std::uint8_t> border_welded(n, 0);
  for (const auto& [edge, count] : uses)
    if (count != 2) border_welded[edge >> 32] = border_welded[edge & 0xFFFFFFFFu] = 1;
  std::vector<std::uint8_t> border(n);
  for (std::size_t v = 0; v < n; ++v) border[v] = border_welded[weld[v]];
  return border;
}

}  // namespace

std::vector<std::vector<std::uint8_t>> shared_positions(std::span<const PlacedPrimitive> prims) {
  std::vector<std::vector<std::uint8_t>> out(prims.size());
  std::size_t placed = 0, total = 0;
  for (std::size_t p = 0; p < prims.size(); ++p) {
    out[p].assign(prims[p].positions_xyz.size() / 3, 0);
    placed += prims[p].world.size();
    total += prims[p].world.size() * out[p].size();
  }
  if (placed < 2) return out;  // nothing to meet
  std::unordered_map<Key, Owner, KeyHash> owner;
  owner.reserve(total);
  for (std::size_t p = 0; p < prims.size(); ++p)
    for (std::size_t i = 0; i < prims[p].world.size(); ++i)
      for (std::size_t v = 0; v < out[p].size(); ++v) {
        const Owner me{static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(i), false};
        auto [it, fresh] = owner.try_emplace(world_key(prims[p].positions_xyz, v, prims[p].world[i]), me);
        if (!fresh && (it->second.primitive != me.primitive || it->second.instance != me.instance))
          it->second.shared = true;
      }
  for (std::size_t p = 0; p < prims.size(); ++p) {
    if (prims[p].world.empty()) continue;
    const std::vector<std::uint8_t> border = on_open_border(prims[p].positions_xyz, prims[p].indices);
    for (std::size_t i = 0; i < prims[p].world.size(); ++i)
      for (std::size_t v = 0; v < out[p].size(); ++v)
        if (border[v] && owner.at(world_key(prims[p].positions_xyz, v, prims[p].world[i])).shared) out[p][v] = 1;
  }
  return out;
}

}  // namespace gazelod::bake
