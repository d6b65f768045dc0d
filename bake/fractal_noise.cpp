// SPDX-License-Identifier: Apache-2.0
#include "bake/fractal_noise.hpp"

#include "auxiliary/random.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::bake {
namespace {

// Perlin 2002's fade 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at the lattice,
// so the summed terrain has no creases along cell edges.
double fade(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

// The eight lattice gradients: axes and diagonals, all of unit length.
constexpr double kDiag = 0.70710678118654752440;
constexpr double kGradX[8] = {1.0, -1.0, 0.0, 0.0, kDiag, -kDiag, kDiag, -kDiag};
constexpr double kGradY[8] = {0.0, 0.0, 1.0, -1.0, kDiag, kDiag, -kDiag, -kDiag};

double corner(std::int64_t ix, std::int64_t iy, double dx, double dy, std::uint64_t seed, std::uint64_t stream) {
  const std::uint64_t h =
      aux::mix64(aux::hash3(seed, stream, static_cast<std::uint64_t>(ix)) ^ static_cast<std::uint64_t>(iy));
  const std::size_t g = static_cast<std::size_t>(h >> 61);  // top 3 bits: 0..7
  return kGradX[g] * dx + kGradY[g] * dy;
}

}  // namespace

std::string fractal_noise_error(const FractalNoiseOptions& o) {
  if (o.octaves < 1 || o.octaves > 24) return "octaves: must be in [1, 24], got " + std::to_string(o.octaves);
  if (!(o.lacunarity >= 1.5 && o.lacunarity <= 4.0))
    return "lacunarity: must be in [1.5, 4], got " + std::to_string(o.lacunarity);
  if (!(o.gain > 0.0 && o.gain < 1.0)) return "gain: must be in (0, 1), got " + std::to_string(o.gain);
  return "";
}

double gradient_noise(double x, double y, std::uint64_t seed, std::uint64_t stream) {
  if (!std::isfinite(x) || !std::isfinite(y)) return 0.0;
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double dx = x - fx, dy = y - fy;
  const double n00 = corner(ix, iy, dx, dy, seed, stream);
  const double n10 = corner(ix + 1, iy, dx - 1.0, dy, seed, stream);
  const double n01 = corner(ix, iy + 1, dx, dy - 1.0, seed, stream);
  const double n11 = corner(ix + 1, iy + 1, dx - 1.0, dy - 1.0, seed, stream);
  const double u = fade(dx), v = fade(dy);
  const double a = n00 + u * (n10 - n00), b = n01 + u * (n11 - n01);
  // With unit gradients 2D gradient noise stays within sqrt(2)/2; scaled to [-1, 1].
  return std::clamp((a + v * (b - a)) * 1.41421356237309504880, -1.0, 1.0);
}

double fractal_noise(const FractalNoiseOptions& o, double x, double y) {
  double sum = 0.0, amplitude = 1.0, amplitudes = 0.0, frequency = 1.0;
  for (int k = 0; k < o.octaves; ++k) {
    // An irrational offset per octave so the octaves' lattice points never coincide.
    const double offset = 0.618033988749895 * (k + 1);
    sum += amplitude *
           gradient_noise(x * frequency + offset, y * frequency - offset, o.seed, static_cast<std::uint64_t>(k));
    amplitudes += amplitude;
    amplitude *= o.gain;
    frequency *= o.lacunarity;
  }
  return amplitudes > 0.0 ? std::clamp(sum / amplitudes, -1.0, 1.0) : 0.0;
}

}  // namespace gazelod::bake
