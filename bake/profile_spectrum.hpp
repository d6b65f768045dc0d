// SPDX-License-Identifier: Apache-2.0
// The spatial frequency of a difference image (a level's render minus the full model's), the
// FFT stand-in for Reddy's feature analysis (Reddy 1998 section 3.3: region growing, then the
// length of each feature; a feature w pixels wide is half a cycle, 1 / (2 w) cycles/pixel).
// Why not "the highest frequency with any energy": rasterised edges put energy up to Nyquist
// in every difference, so that figure is the same for every level. Instead: the radial
// frequency below which kEnergyFraction of the difference's energy lies. For a bar w pixels
// wide that point is ~1 / (2 w) (the integral of sinc^2 up to half a cycle per width holds
// ~3/4 of the energy), i.e. Reddy's figure for a feature of that width; tests check it.
#pragma once

#include <cstdint>
#include <span>

namespace gazelod::bake {

inline constexpr double kEnergyFraction = 0.75;

// Differences smaller than this (8-bit steps of a 0..255 grey value) are quantisation noise.
inline constexpr double kNoiseFloor = 2.0;

// `diff`: size x size values (rows top to bottom), size a power of two in [2, 4096]. Returns
// the radial frequency in cycles per image width (0 .. size/sqrt(2)) below which
// kEnergyFraction of the energy lies (values with |d| < kNoiseFloor are zeroed first), or a
// negative number when nothing is left (the images agree). Throws std::invalid_argument for a
// bad size or a non-finite value.
double energy_frequency_cycles_per_width(std::span<const float> diff, std::uint32_t size);

// In-place radix-2 complex FFT of n = re.size() points (power of two). Exposed for tests.
void fft_inplace(std::span<double> re, std::span<double> im);

}  // namespace gazelod::bake
