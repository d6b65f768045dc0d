// SPDX-License-Identifier: Apache-2.0
// Time units: integer nanoseconds (every sample, frame and XrTime) to and from seconds and
// milliseconds as doubles. One definition of each conversion, so that every place rounds alike
// and the unit is in the name rather than in a literal (1e-9 or 1e9? ns or us?).
//
//   const double t_s = aux::seconds_from_ns(t_ns);        // ns * 1e-9
//   const std::int64_t d_ns = aux::ns_from_seconds(0.25);  // nearest ns, clamped
//
// Conversions to ns round to the nearest integer, halves away from zero (as std::llround), and
// clamp: a result beyond the int64 range is INT64_MIN or INT64_MAX, NaN is 0 (std::llround's
// result is unspecified for all three). Conversions from ns multiply by a power of ten's
// reciprocal (ns * 1e-9, not ns / 1e9): the two may differ in the last bit, and every number
// the project writes has been computed the first way. Exact up to 2^53 ns (104 days).
#pragma once

#include <cstdint>
#include <ctime>
#include <limits>

namespace gazelod::aux {

inline constexpr std::int64_t kNsPerSecond = 1'000'000'000;
inline constexpr std::int64_t kNsPerMs = 1'000'000;

// ---- from nanoseconds ---------------------------------------------------------------------

constexpr double seconds_from_ns(std::int64_t ns) {
  return static_cast<double>(ns) * 1e-9;
}
constexpr double ms_from_ns(std::int64_t ns) {
  return static_cast<double>(ns) * 1e-6;
}
// Whole milliseconds, truncated toward zero (integer division): for messages ("within 50 ms").
constexpr std::int64_t whole_ms_from_ns(std::int64_t ns) {
  return ns / kNsPerMs;
}

// ---- to nanoseconds -----------------------------------------------------------------------

// A count of nanoseconds held in a double, rounded and clamped as above. constexpr (std::llround
// is not until C++23), with llround's results: the truncation and the remainder are both exact.
constexpr std::int64_t ns_rounded(double ns) {
  constexpr double kTwoPow63 = 9223372036854775808.0;
  if (ns != ns) return 0;  // NaN
  if (ns >= kTwoPow63) return std::numeric_limits<std::int64_t>::max();
  if (ns <= -kTwoPow63) return std::numeric_limits<std::int64_t>::min();
  const auto whole = static_cast<std::int64_t>(ns);  // toward zero
  const double fraction = ns - static_cast<double>(whole);
  if (fraction >= 0.5) return whole + 1;
  if (fraction <= -0.5) return whole - 1;
  return whole;
}

constexpr std::int64_t ns_from_seconds(double s) {
  return ns_rounded(s * 1e9);
}
constexpr std::int64_t ns_from_ms(double ms) {
  return ns_rounded(ms * 1e6);
}
// The period of a rate, 1e9 / hz rounded (0 Hz: INT64_MAX).
constexpr std::int64_t period_ns_from_hz(double hz) {
  return ns_rounded(1e9 / hz);
}

// ---- between seconds and milliseconds -------------------------------------------------------

constexpr double seconds_from_ms(double ms) {
  return ms * 1e-3;
}
constexpr double ms_from_seconds(double s) {
  return s * 1e3;
}

// ---- struct timespec (clock_gettime, XR_KHR_convert_timespec_time) ---------------------------

constexpr std::int64_t ns_from_timespec(const std::timespec& ts) {
  return static_cast<std::int64_t>(ts.tv_sec) * kNsPerSecond + ts.tv_nsec;
}
// The inverse for ns >= 0; a negative count gives a negative tv_nsec (C++ division truncates),
// which callers refuse before converting.
constexpr std::timespec timespec_from_ns(std::int64_t ns) {
  std::timespec ts{};
  ts.tv_sec = static_cast<std::time_t>(ns / kNsPerSecond);
  ts.tv_nsec = static_cast<long>(ns % kNsPerSecond);
  return ts;
}

}  // namespace gazelod::aux
