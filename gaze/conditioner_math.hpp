// SPDX-License-Identifier: Apache-2.0
// Small numeric guards and constants the gaze conditioner's files share (gaze_conditioner.cpp:
// samples in; conditioner_fixation.cpp: the fixation's tests; conditioner_predict.cpp: the
// estimate at the display time). Internal to gaze/.
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace gazelod::gaze::detail {

inline constexpr std::size_t kMinPursuitSamples = 5;  // residuals need a few degrees of freedom
inline constexpr std::size_t kMinLandingSamples = 3;  // a landing's scatter from fewer says little
// ... nor from less time than this: a landing holds still for longer than a few fast samples
// of a flight do.
inline constexpr std::int64_t kLandingMinSpanNs = 15'000'000;
// The carried test's window: most fixations are shorter (Rayner 1998); a long one is judged on
// its latest second, so a head that stops moving is noticed.
inline constexpr std::int64_t kCarriedWindowNs = 1'000'000'000;
// The step test's window: about half of a small saccade's duration (21 ms + 2.2 ms/deg,
// Carpenter 1988), so a landing is judged on the samples after it.
inline constexpr std::int64_t kStepWindowNs = 25'000'000;
// ... and by how much (noise variances, both axes) two means must fit the samples better than a
// line for a step. 9 (a chi-square of 2 degrees of freedom at p = 0.011): at the frame rate a
// landing has only ~3 samples in the step window, and a line through the few samples after a
// 5-7 deg jump and the many before explains part of it (16 missed the jump of family seed
// 1001 that made a reflex-held fixation read as carried); 4 restarted still fixations on
// noise (docs/evaluation.md, "Scenario family", item 5).
inline constexpr double kStepOverLine = 9.0;

// The chi-square distribution's 0.999 quantile for `dof` > 0 degrees of freedom, by Wilson &
// Hilferty's (1931) cube-root approximation (within 2 % from 4 degrees of freedom on); 0 for
// dof <= 0.
inline double chi2_upper_999(double dof) {
  if (!(dof > 0.0)) return 0.0;
  constexpr double kZ = 3.090;  // the standard normal's 0.999 quantile
  const double c = 2.0 / (9.0 * dof);
  const double r = 1.0 - c + kZ * std::sqrt(c);
  return dof * r * r * r;
}

inline bool finite3(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Unit quaternion, or false when q is not finite or (near) zero.
inline bool normalized_quat(const glm::dquat& q, glm::dquat& out) {
  const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  if (!std::isfinite(n2) || !(n2 > 1e-18)) return false;
  const double n = std::sqrt(n2);
  out = glm::dquat(q.w / n, q.x / n, q.y / n, q.z / n);
  return std::isfinite(out.w) && std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z);
}

// Unit vector, or false when v is not finite or (near) zero.
inline bool normalized_dir(const glm::dvec3& v, glm::dvec3& out) {
  if (!finite3(v)) return false;
  const double n = glm::length(v);
  if (!std::isfinite(n) || !(n > 1e-9)) return false;
  out = v / n;
  return finite3(out);
}

// a - b without overflow (saturating).
inline std::int64_t sat_sub(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_sub_overflow(a, b, &r))
    return a > b ? std::numeric_limits<std::int64_t>::max() : std::numeric_limits<std::int64_t>::min();
  return r;
}

// Smoothing factor of an exponential average with time constant tau over a step dt (1 when
// tau is zero: no smoothing).
inline double ema_alpha(double dt_s, double tau_s) {
  if (!(tau_s > 0.0)) return 1.0;
  if (!(dt_s > 0.0)) return 0.0;
  return 1.0 - std::exp(-dt_s / tau_s);
}

}  // namespace gazelod::gaze::detail
