// SPDX-License-Identifier: Apache-2.0
// Branch-free atan2 and log10 for the per-object selection kernel (lod/select_kernel.cpp),
// where libm calls would cost more than the whole 10 ns/object budget. Written with
// ternaries only (no early return, no data-dependent branch) so that GCC vectorises the loops
// that inline them. Both keep relative precision near zero (an angle of 1e-7 rad stays
// 1e-7 rad), unlike acos of a dot product.
// Accuracy: atan within 1e-10 rad, log10 within 1e-12 (tests/lod/fast_math_test.cpp).
#pragma once

#include <bit>
#include <cstdint>
#include <numbers>

namespace gazelod::lod::fast {

// atan(u) for |u| <= tan(pi/8): atan u = u + u^3 Q(u^2), Q a degree-5 polynomial in x = u^2
// interpolating (atan u - u) / u^3 at the Chebyshev nodes of [0, tan^2(pi/8)] (near-minimax:
// |error| < 4e-11 rad, where the Taylor series needs degree 9 for 1e-11;
// scripts/fit_fast_math.py). Estrin's scheme: three dependent FMA steps instead of Horner's
// five, and fewer operations, which is what bounds the vectorised selection loop.
[[gnu::always_inline]] inline double atan_small(double u) {
  const double x = u * u, x2 = x * x, x4 = x2 * x2;
  const double p01 = -0.33333333279254806 + x * 0.19999977258688625;
  const double p23 = -0.14284151193630637 + x * 0.11071365021834943;
  const double p45 = -0.0862467614446554 + x * 0.05048138509265249;
  const double q = (p01 + x2 * p23) + x4 * p45;
  return u + u * x * q;
}

// atan(num / den) for 0 <= num <= den, den > 0 (NaN at den = 0): in [0, pi/4]. One
// division: above tan(pi/8) the ratio t is reduced by atan t = pi/4 + atan((t-1)/(t+1)),
// formed from num and den before dividing.
[[gnu::always_inline]] inline double atan_unit_ratio(double num, double den) {
  constexpr double kTanPi8 = 0.41421356237309503;
  // As a 0/1 factor, not a blend of the operands: GCC would otherwise push the blend past
  // the division and divide twice.
  const double big = num > kTanPi8 * den ? 1.0 : 0.0;
  const double top = num - big * den;
  const double bottom = den + big * num;
  return big * (std::numbers::pi / 4) + atan_small(top / bottom);
}

// atan2(y, x) for y >= 0 when the length n = |(x, y)| is known: by the half-angle formula
// atan2(y, x) = 2 atan(y / (n + x)) for x >= 0 and pi - 2 atan(y / (n - x)) for x < 0, both
// ratios in [0, 1] and both sums free of cancellation, so no octant swap is needed. In
// [0, pi]; NaN when n = 0. Keeps relative precision near zero (1e-7 rad stays 1e-7 rad).
[[gnu::always_inline]] inline double atan2_with_norm(double y, double x, double n) {
  const double half = atan_unit_ratio(y, n + (x < 0.0 ? -x : x));
  return x < 0.0 ? std::numbers::pi - 2.0 * half : 2.0 * half;
}

// log10(x) for a positive, normal, finite x (callers clamp: the selection calls it on
// v^2 clamped to [0.825^2, 200^2]). x = 2^e m with m in [sqrt(1/2), sqrt(2)), and
// ln m = 2 y S(y^2), y = (m - 1) / (m + 1), S(z) = atanh(y) / y = 1 + z/3 + z^2/5 + ...
// replaced by a degree-4 polynomial interpolating it at the Chebyshev nodes of
// [0, ((sqrt2 - 1) / (sqrt2 + 1))^2] (|error in log10| < 7e-13; scripts/fit_fast_math.py).
// The exponent is turned into a double by the 2^52 trick (no int64 -> double conversion,
// which AVX2 lacks), so the function vectorises.
[[gnu::always_inline]] inline double log10_normal(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  // bit pattern of 2^52 + biased exponent, as a double, minus 2^52 + 1023.
  const double e_raw = std::bit_cast<double>((bits >> 52) | 0x4330000000000000ULL) - (4503599627370496.0 + 1023.0);
  const double m_raw = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  // x = 2^(e + 1/2) (m_raw / sqrt2): m in [sqrt(1/2), sqrt(2)) without a comparison (a
  // fold by a blend makes GCC run the series twice, once per side).
  const double m = m_raw * (1.0 / std::numbers::sqrt2);
  const double e = e_raw + 0.5;
  const double y = (m - 1.0) / (m + 1.0);
  // 2 S(z) / ln 10 by Estrin's scheme (a short dependency chain).
  constexpr double k = 2.0 / std::numbers::ln10;
  const double z = y * y, z2 = z * z;
  const double s01 = k * 1.0000000000041798 + z * (k * 0.33333332623741235);
  const double s23 = k * 0.20000192336301803 + z * (k * 0.14267525530381753);
  const double s = (s01 + z2 * s23) + (z2 * z2) * (k * 0.11808179100683015);
  return e * (std::numbers::ln2 / std::numbers::ln10) + y * s;
}

}  // namespace gazelod::lod::fast
