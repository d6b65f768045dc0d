// SPDX-License-Identifier: Apache-2.0
// Fractal gradient noise in 2D for generated test terrain (bake/terrain_mesh.hpp): Perlin's
// gradient noise with his quintic fade (Perlin 2002) summed over octaves as fractional
// Brownian motion (Musgrave, in Ebert et al. 2003). Deterministic by seed: lattice gradients
// come from a fixed set of eight directions picked by a splitmix64 hash of (seed, octave,
// lattice point), and the arithmetic is plain IEEE double, so a seed gives the same heights on
// every platform.
#pragma once

#include <cstdint>
#include <string>

namespace gazelod::bake {

struct FractalNoiseOptions {
  std::uint64_t seed = 1;
  int octaves = 8;          // [1, 24]
  double lacunarity = 2.0;  // frequency factor per octave, [1.5, 4]
  double gain = 0.5;        // amplitude factor per octave, (0, 1)
};

// "" when the options are in range, else which field and why.
std::string fractal_noise_error(const FractalNoiseOptions& options);

// One octave at (x, y) in lattice units (one lattice cell per unit): 0 at lattice points, in
// [-1, 1]. `stream` separates independent noise fields of one seed (e.g. the octaves).
double gradient_noise(double x, double y, std::uint64_t seed, std::uint64_t stream);

// The octaves summed (octave k at frequency lacunarity^k, amplitude gain^k, each its own
// stream, offset so lattice points do not line up) and divided by the sum of the amplitudes:
// in [-1, 1]. Options must be valid (fractal_noise_error).
double fractal_noise(const FractalNoiseOptions& options, double x, double y);

}  // namespace gazelod::bake
