// SPDX-License-Identifier: Apache-2.0
// Time units (auxiliary/time.hpp): conversions to ns round as std::llround did at every call
// site they replace, clamp instead of overflowing, and the conversions from ns are the
// multiplications the project has always written (bit for bit).
#include "auxiliary/time.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace gazelod::aux {
namespace {

static_assert(ns_from_seconds(1.0) == kNsPerSecond);
static_assert(ns_from_ms(1.0) == kNsPerMs);
static_assert(ns_rounded(0.5) == 1 && ns_rounded(-0.5) == -1 && ns_rounded(0.25) == 0);  // halves away from zero
static_assert(seconds_from_ns(1'500'000'000) == 1.5);
static_assert(whole_ms_from_ns(1'999'999) == 1 && whole_ms_from_ns(-1'999'999) == -1);

TEST(Time, RoundingIsLlroundsEverywhereInRange) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-12.0, 9.0);
  for (int i = 0; i < 100000; ++i) {
    const double s = std::pow(10.0, exponent(rng)) * (i % 2 ? 1.0 : -1.0);
    ASSERT_EQ(ns_from_seconds(s), std::llround(s * 1e9)) << s;
    ASSERT_EQ(ns_from_ms(s), std::llround(s * 1e6)) << s;
  }
  for (double x : {0.5, 1.5, 2.5, -0.5, -2.5, 0.49999999999999994, 4503599627370495.5, 4503599627370497.0})
    EXPECT_EQ(ns_rounded(x), std::llround(x)) << x;
}

TEST(Time, OutOfRangeClampsAndNanIsZero) {
  constexpr auto kMax = std::numeric_limits<std::int64_t>::max(), kMin = std::numeric_limits<std::int64_t>::min();
  EXPECT_EQ(ns_from_seconds(1e10), kMax);
  EXPECT_EQ(ns_from_seconds(-1e10), kMin);
  EXPECT_EQ(ns_from_seconds(std::numeric_limits<double>::infinity()), kMax);
  EXPECT_EQ(ns_from_seconds(std::nan("")), 0);
  EXPECT_EQ(period_ns_from_hz(0.0), kMax);
  EXPECT_EQ(period_ns_from_hz(90.0), 11'111'111);
  EXPECT_EQ(ns_rounded(9223372036854774784.0), 9223372036854774784);  // the largest double below 2^63
}

TEST(Time, FromNsIsTheMultiplication) {
  for (std::int64_t ns : {std::int64_t{1}, std::int64_t{3}, std::int64_t{11'111'111}, std::int64_t{-7'000'000'001}}) {
    EXPECT_EQ(seconds_from_ns(ns), static_cast<double>(ns) * 1e-9);
    EXPECT_EQ(ms_from_ns(ns), static_cast<double>(ns) * 1e-6);
  }
  EXPECT_EQ(seconds_from_ms(250.0), 250.0 * 1e-3);
  EXPECT_EQ(ms_from_seconds(0.25), 250.0);
}

TEST(Time, TimespecRoundTrips) {
  const std::int64_t ns = 1'234'567'890'123;
  const std::timespec ts = timespec_from_ns(ns);
  EXPECT_EQ(ts.tv_sec, 1234);
  EXPECT_EQ(ts.tv_nsec, 567'890'123);
  EXPECT_EQ(ns_from_timespec(ts), ns);
}

}  // namespace
}  // namespace gazelod::aux
