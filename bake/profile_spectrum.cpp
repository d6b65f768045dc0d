// SPDX-License-Identifier: Apache-2.0
// Separable radix-2 FFT and the radial energy distribution (profile_spectrum.hpp).
#include "bake/profile_spectrum.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gazelod::bake {

void fft_inplace(std::span<double> re, std::span<double> im) {
  const std::size_t n = re.size();
  if (n != im.size() || n == 0 || (n & (n - 1)) != 0)
    throw std::invalid_argument("fft: size " + std::to_string(n) + " is not a power of two");
  for (std::size_t i = 1, j = 0; i < n; ++i) {  // bit-reversal permutation
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(re[i], re[j]), std::swap(im[i], im[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double a = -2.0 * std::numbers::pi / static_cast<double>(len);
    for (std::size_t i = 0; i < n; i += len)
      for (std::size_t k = 0; k < len / 2; ++k) {
        const double wr = std::cos(a * static_cast<double>(k)), wi = std::sin(a * static_cast<double>(k));
        const std::size_t p = i + k, q = p + len / 2;
        const double tr = re[q] * wr - im[q] * wi, ti = re[q] * wi + im[q] * wr;
        re[q] = re[p] - tr, im[q] = im[p] - ti;
        re[p] += tr, im[p] += ti;
      }
  }
}

double energy_frequency_cycles_per_width(std::span<const float> diff, std::uint32_t size) {
  if (size < 2 || size > 4096 || (size & (size - 1)) != 0 || diff.size() != static_cast<std::size_t>(size) * size)
    throw std::invalid_argument(
        "profile spectrum: image must be size x size with size a power "
        "of two in [2, 4096], got size " +
        std::to_string(size) + " and " + std::to_string(diff.size()) + " values");
  const std::size_t n = size;
  std::vector<double> re(n * n), im(n * n, 0.0);
  bool any = false;
  for (std::size_t i = 0; i < n * n; ++i) {
    if (!std::isfinite(diff[i]))
      throw std::invalid_argument("profile spectrum: value " + std::to_string(i) + " is not finite");
    re[i] = std::abs(diff[i]) < kNoiseFloor ? 0.0 : diff[i];
    any = any || re[i] != 0.0;
  }
  if (!any) return -1.0;
  std::vector<double> r(n), c(n);
  for (std::size_t y = 0; y < n; ++y) fft_inplace({&re[y * n], n}, {&im[y * n], n});
  for (std::size_t x = 0; x < n; ++x) {  // columns through a scratch copy
    for (std::size_t y = 0; y < n; ++y) r[y] = re[y * n + x], c[y] = im[y * n + x];
    fft_inplace(r, c);
    for (std::size_t y = 0; y < n; ++y) re[y * n + x] = r[y], im[y * n + x] = c[y];
  }
  // Energy per radial bin of width 1/4 cycle per width (finer than the integer grid's spacing).
  const std::size_t bins = static_cast<std::size_t>(std::ceil(static_cast<double>(n) * std::numbers::sqrt2 * 2.0)) + 2;
  std::vector<double> energy(bins, 0.0);
  double total = 0.0;
  const auto signed_k = [n](std::size_t k) { return k < n / 2 ? double(k) : double(k) - double(n); };
  for (std::size_t y = 0; y < n; ++y)
    for (std::size_t x = 0; x < n; ++x) {
      const double e = re[y * n + x] * re[y * n + x] + im[y * n + x] * im[y * n + x];
      const double f = std::hypot(signed_k(x), signed_k(y));
      energy[static_cast<std::size_t>(f * 4.0)] += e;
      total += e;
    }
  if (!(total > 0.0)) return -1.0;
  double acc = 0.0;
  for (std::size_t b = 0; b < bins; ++b) {
    const double next = acc + energy[b];
    if (next >= kEnergyFraction * total) {  // interpolate inside the bin
      const double t = energy[b] > 0.0 ? (kEnergyFraction * total - acc) / energy[b] : 0.0;
      return (static_cast<double>(b) + t) / 4.0;
    }
    acc = next;
  }
  return static_cast<double>(bins) / 4.0;
}

}  // namespace gazelod::bake
