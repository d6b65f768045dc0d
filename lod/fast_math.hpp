// Branch-light atan2 and log10 for the per-object selection loop (lod/select.cpp), where the
// libm calls would cost more than the whole 10 ns/object budget. Both keep relative precision
// near zero (an angle of 1e-7 rad stays 1e-7 rad), unlike acos of a dot product.
// Accuracy: atan2 within 2e-10 rad, log10 within 1e-12 (tests/lod/fast_math_test.cpp).
#pragma once

#include <bit>
#include <cstdint>
#include <numbers>

namespace gazelod::lod::fast {

// atan(t) for t in [0, 1]. Reduced to |u| <= tan(pi/8) by atan(t) = pi/4 + atan((t-1)/(t+1)),
// then the odd Taylor series to u^21 (truncation < 1e-10).
inline double atan_unit(double t) {
  const bool big = t > 0.41421356237309503;
  const double u = big ? (t - 1.0) / (t + 1.0) : t;
  const double u2 = u * u;
  // atan u = u + u^3 Q(u^2), Q = -1/3 + u^2/5 - u^4/7 + ... + u^18/21.
  double q = 1.0 / 21.0;
  q = q * u2 - 1.0 / 19.0;
  q = q * u2 + 1.0 / 17.0;
  q = q * u2 - 1.0 / 15.0;
  q = q * u2 + 1.0 / 13.0;
  q = q * u2 - 1.0 / 11.0;
  q = q * u2 + 1.0 / 9.0;
  q = q * u2 - 1.0 / 7.0;
  q = q * u2 + 1.0 / 5.0;
  q = q * u2 - 1.0 / 3.0;
  const double r = u + u * u2 * q;
  return big ? std::numbers::pi / 4 + r : r;
}

// atan2(y, x) for y >= 0 (a sine from a cross product's length), in [0, pi]. 0 when both are 0.
inline double atan2_nonneg(double y, double x) {
  const double ax = x < 0.0 ? -x : x;
  const bool steep = y > ax;
  const double num = steep ? ax : y;
  const double den = steep ? y : ax;
  if (!(den > 0.0)) return 0.0;
  double a = atan_unit(num / den);
  if (steep) a = std::numbers::pi / 2 - a;
  if (x < 0.0) a = std::numbers::pi - a;
  return a;
}

// log10(x) for a positive, normal, finite x (callers guard: the selection calls it only for
// v > 0.825). ln m by the atanh series on m in [sqrt(1/2), sqrt(2)].
inline double log10_normal(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  double m = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  if (m > std::numbers::sqrt2) {
    m *= 0.5;
    ++e;
  }
  const double y = (m - 1.0) / (m + 1.0);
  const double y2 = y * y;
  const double s =
      1.0 + y2 * (1.0 / 3 + y2 * (1.0 / 5 + y2 * (1.0 / 7 + y2 * (1.0 / 9 + y2 * (1.0 / 11 + y2 / 13)))));
  const double ln = static_cast<double>(e) * std::numbers::ln2 + 2.0 * y * s;
  return ln * (1.0 / std::numbers::ln10);
}

}  // namespace gazelod::lod::fast
