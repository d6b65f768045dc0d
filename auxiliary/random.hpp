// SPDX-License-Identifier: Apache-2.0
// Seeded, counter-based randomness (the simulator's effects, generated scenes and meshes):
// every random number is a pure function of (seed, stream, counter), so a stream does not
// depend on the order of queries and the same seed gives the same numbers (splitmix64
// finaliser, Steele et al. 2014; Box-Muller for Gaussians).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace gazelod::aux {

// splitmix64's output function: a bijective 64-bit mix with good avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// One 64-bit value per (seed, stream, counter); stream is usually the effect's index.
constexpr std::uint64_t hash3(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  return mix64(mix64(mix64(seed) ^ stream) ^ counter);
}

// Uniform in [0, 1): the top 53 bits.
constexpr double to_unit(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

struct CounterRng {
  std::uint64_t seed = 0;
  std::uint64_t stream = 0;

  double uniform(std::uint64_t counter) const { return to_unit(hash3(seed, stream, counter)); }
  double uniform(std::uint64_t counter, double lo, double hi) const { return lo + (hi - lo) * uniform(counter); }
  // Two independent standard normals from counters 2c and 2c+1 (Box-Muller); u1 in (0, 1].
  void normal2(std::uint64_t counter, double& a, double& b) const {
    const double u1 = 1.0 - uniform(2 * counter);
    const double u2 = uniform(2 * counter + 1);
    const double r = std::sqrt(-2.0 * std::log(u1));
    a = r * std::cos(2.0 * std::numbers::pi * u2);
    b = r * std::sin(2.0 * std::numbers::pi * u2);
  }
};

}  // namespace gazelod::aux
