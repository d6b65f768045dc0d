// SPDX-License-Identifier: Apache-2.0
// Float forms of lod/fast_math.hpp's branch-free atan2 and log10, for the per-cluster kernel
// (lod/cluster/cluster_select_kernel.cpp): 16 lanes per AVX-512 vector instead of 8, which the cluster
// budget (5 ns for two records) needs. Same reductions as the double versions (half-angle
// atan2, pi/8 argument reduction, exponent split of the log), with polynomials fitted for float
// (interpolation at Chebyshev nodes, as scripts/fit_fast_math.py does for the double ones):
//   atan_small:    |error| < 3e-8 rad in exact arithmetic (degree 3 in u^2);
//   log10_normal:  |error| < 2e-7 (log2 by a degree-6 polynomial in m - 1, no division).
// Evaluated in float, each adds a few ulps of its result; the kernel's slack constants
// (cluster_select_kernel.hpp) bound the total and tests/lod/cluster_select_math_test.cpp
// measures it.
#pragma once

#include <bit>
#include <cstdint>
#include <numbers>

namespace gazelod::lod::fastf {

// atan(u) for 0 <= u <= tan(pi/8): u + u^3 Q(u^2).
[[gnu::always_inline]] inline float atan_small(float u) {
  const float x = u * u;
  const float q01 = -0.333332866f + x * 0.199912377f;
  const float q23 = -0.140241428f + x * 0.0852049204f;
  const float q = q01 + (x * x) * q23;
  return u + u * x * q;
}

// atan(num / den) for 0 <= num <= den, den > 0: in [0, pi/4], one division.
[[gnu::always_inline]] inline float atan_unit_ratio(float num, float den) {
  constexpr float kTanPi8 = 0.414213562f;
  const float big = num > kTanPi8 * den ? 1.0f : 0.0f;  // a factor, not a blend (one division)
  const float top = num - big * den;
  const float bottom = den + big * num;
  return big * (std::numbers::pi_v<float> / 4) + atan_small(top / bottom);
}

// atan2(y, x) for y >= 0 given n = |(x, y)|: 2 atan(y / (n + |x|)), mirrored for x < 0.
// In [0, pi]; an n off by a relative delta moves the result by at most pi |delta|.
[[gnu::always_inline]] inline float atan2_with_norm(float y, float x, float n) {
  const float half = atan_unit_ratio(y, n + (x < 0.0f ? -x : x));
  return x < 0.0f ? std::numbers::pi_v<float> - 2.0f * half : 2.0f * half;
}

// log10(x) for a positive, normal, finite x (callers clamp). x = 2^(e + 1/2) m with m in
// [sqrt(1/2), sqrt(2)) (the fold by a multiplication, as fast::log10_normal), log2 m = t P(t),
// t = m - 1. Exponent by an int32 conversion (SSE2 has it for float lanes).
[[gnu::always_inline]] inline float log10_normal(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  const float e = static_cast<float>(static_cast<std::int32_t>(bits >> 23) - 127) + 0.5f;
  const float m_raw = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);
  const float t = m_raw * (1.0f / std::numbers::sqrt2_v<float>)-1.0f;
  const float t2 = t * t, t4 = t2 * t2;
  const float p01 = 1.44269652f + t * -0.721360179f;
  const float p23 = 0.480613125f + t * -0.359524455f;
  const float p45 = 0.296119557f + t * -0.267963871f;
  const float p = (p01 + t2 * p23) + t4 * (p45 + t2 * 0.168186591f);
  return (e + t * p) * (std::numbers::ln2_v<float> / std::numbers::ln10_v<float>);
}

}  // namespace gazelod::lod::fastf
