// SPDX-License-Identifier: Apache-2.0
// The objects both sides of the peer benchmark select LODs for: Reddy 1998's test environment
// (four LODs of 3928, 834, 254, 76 triangles; removed detail sqrt(triangles) / 2 cycles per
// diameter), randomly placed ahead of a viewer on a 1280x1024, 43.6 x 33.4 deg display.
// The same generator as `gazelod eval`'s layouts (apps/gazelod/eval/scenario.cpp), inlined so
// the benchmark needs only gazelod_lod.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gazelod::peer {

inline constexpr std::array<std::uint32_t, 4> kTriangles{3928, 834, 254, 76};
inline constexpr int kWidthPx = 1280, kHeightPx = 1024;
inline constexpr double kFovHDeg = 43.6, kFovVDeg = 33.4;

struct PeerObject {
  double x, y, z, radius;
};

inline std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

inline double uniform(std::uint64_t& s, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(splitmix64(s) >> 11) * 0x1.0p-53;
}

inline std::vector<PeerObject> peer_objects(std::size_t n, std::uint64_t seed = 1) {
  std::uint64_t state = seed * 0x2545F4914F6CDD1DULL + 17;
  std::vector<PeerObject> out(n);
  for (PeerObject& o : out) {
    o.x = uniform(state, -20, 20);
    o.y = uniform(state, -12, 12);
    o.z = uniform(state, -80, -5);
    o.radius = uniform(state, 0.3, 1.5);
  }
  return out;
}

// Removed cycles per diameter of level k >= 1.
inline double removed_cycles(std::size_t level) {
  return std::sqrt(static_cast<double>(kTriangles[level])) / 2.0;
}

// The pixel diameter below which level k >= 1 is invisible for a still, foveal object by
// Reddy 1998's size criterion (a pixel is half a cycle, so c cycles need 2c pixels): this is
// what osg::LOD's PIXEL_SIZE_ON_SCREEN ranges are set from, so both sides implement the
// same rule and differ only in how they evaluate it.
inline double level_max_pixels(std::size_t level) {
  return 2.0 * removed_cycles(level);
}

}  // namespace gazelod::peer
