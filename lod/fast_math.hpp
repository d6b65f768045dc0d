// Branch-free atan2 and log10 for the per-object selection kernel (lod/select_kernel.cpp),
// where libm calls would cost more than the whole 10 ns/object budget. Written with
// ternaries only (no early return, no data-dependent branch) so that GCC vectorises the loops
// that inline them. Both keep relative precision near zero (an angle of 1e-7 rad stays
// 1e-7 rad), unlike acos of a dot product.
// Accuracy: atan2 within 2e-10 rad, log10 within 1e-12 (tests/lod/fast_math_test.cpp).
#pragma once

#include <bit>
#include <cstdint>
#include <numbers>

namespace gazelod::lod::fast {

// atan(u) for |u| <= tan(pi/8): the odd Taylor series to u^21 (truncation < 1e-10).
// atan u = u + u^3 Q(u^2), Q = -1/3 + x/5 - x^2/7 + ... + x^9/21 (x = u^2), evaluated by
// Estrin's scheme: four dependent FMA steps instead of Horner's nine, which matters because
// the vectorised selection loop is bound by this dependency chain, not by throughput.
[[gnu::always_inline]] inline double atan_small(double u) {
  const double x = u * u, x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  const double p01 = -1.0 / 3.0 + x * (1.0 / 5.0);
  const double p23 = -1.0 / 7.0 + x * (1.0 / 9.0);
  const double p45 = -1.0 / 11.0 + x * (1.0 / 13.0);
  const double p67 = -1.0 / 15.0 + x * (1.0 / 17.0);
  const double p89 = -1.0 / 19.0 + x * (1.0 / 21.0);
  const double p03 = p01 + x2 * p23, p47 = p45 + x2 * p67;
  const double q = (p03 + x4 * p47) + x8 * p89;
  return u + u * x * q;
}

// atan2(y, x) for y >= 0 (a sine from a cross product's length), in [0, pi]. 0 when both are 0.
// One division: with num <= den (octant folding), atan(num/den) is reduced by
// atan(t) = pi/4 + atan((t-1)/(t+1)) = pi/4 + atan((num-den)/(num+den)) for t > tan(pi/8).
[[gnu::always_inline]] inline double atan2_nonneg(double y, double x) {
  constexpr double kTanPi8 = 0.41421356237309503;
  const double ax = x < 0.0 ? -x : x;
  const bool steep = y > ax;
  const double num = steep ? ax : y;
  const double den = steep ? y : ax;
  // As a 0/1 factor, not a blend of the operands: GCC would otherwise push the blend past
  // the division and divide twice.
  const double big = num > kTanPi8 * den ? 1.0 : 0.0;
  // den == 0 implies num == 0 (num <= den): 0 / 1 gives angle 0 without a 0/0.
  const double top = num - big * den;
  const double bottom = (den > 0.0 ? den : 1.0) + big * num;
  const double r = atan_small(top / bottom);
  const double a = big * (std::numbers::pi / 4) + r;
  const double a_steep = steep ? std::numbers::pi / 2 - a : a;
  return x < 0.0 ? std::numbers::pi - a_steep : a_steep;
}

// log10(x) for a positive, normal, finite x (callers clamp: the selection calls it on
// v clamped to [0.825, 200]). ln m by the atanh series on m in [sqrt(1/2), sqrt(2)]. The
// exponent is turned into a double by the 2^52 trick (no int64 -> double conversion, which
// AVX2 lacks), so the function vectorises.
[[gnu::always_inline]] inline double log10_normal(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  // bit pattern of 2^52 + biased exponent, as a double, minus 2^52 + 1023.
  const double e_raw =
      std::bit_cast<double>((bits >> 52) | 0x4330000000000000ULL) - (4503599627370496.0 + 1023.0);
  const double m_raw = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  const bool fold = m_raw > std::numbers::sqrt2;
  const double m = fold ? m_raw * 0.5 : m_raw;
  const double e = fold ? e_raw + 1.0 : e_raw;
  const double y = (m - 1.0) / (m + 1.0);
  // atanh series 1 + z/3 + z^2/5 + ... + z^6/13 (z = y^2) by Estrin's scheme (short chain).
  const double z = y * y, z2 = z * z, z4 = z2 * z2;
  const double s01 = 1.0 + z * (1.0 / 3), s23 = 1.0 / 5 + z * (1.0 / 7),
               s45 = 1.0 / 9 + z * (1.0 / 11);
  const double s = (s01 + z2 * s23) + z4 * (s45 + z2 * (1.0 / 13));
  const double ln = e * std::numbers::ln2 + 2.0 * y * s;
  return ln * (1.0 / std::numbers::ln10);
}

}  // namespace gazelod::lod::fast
