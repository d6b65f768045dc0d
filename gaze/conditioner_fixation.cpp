// SPDX-License-Identifier: Apache-2.0
// The gaze conditioner's tests of where a phase begins and what it is (gaze_conditioner.hpp):
// is a fixation carried by the head rather than held in the world, has a fixation or a
// pursuit moved to a new place without the velocity test noticing (a step), and has a saccade
// landed, and when?
#include "gaze/gaze_conditioner.hpp"

#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "gaze/conditioner_math.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gazelod::gaze {

using detail::chi2_upper_999;
using detail::kCarriedWindowNs;
using detail::kLandingMinSpanNs;
using detail::kMinLandingSamples;
using detail::kMinPursuitSamples;
using detail::kStepOverLine;
using detail::kStepWindowNs;
using detail::normalized_dir;

double GazeConditioner::carried_evidence(std::size_t m, glm::dvec3& head_mean) const noexcept {
  m = std::min(m, segment_count_);
  if (m == 0) return 0.0;
  // Residual sum of squares about each frame's mean direction, in tangent-plane angles.
  const auto rss = [&](auto pick, glm::dvec3& mean) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < m; ++i) sum += pick(newest(i));
    if (!normalized_dir(sum, mean)) return std::numeric_limits<double>::infinity();
    glm::dvec3 e1, e2;
    aux::tangent_basis(mean, e1, e2);
    glm::dvec2 s(0.0), ss(0.0);
    for (std::size_t i = 0; i < m; ++i) {
      const glm::dvec2 a = aux::angular_offset_rad(pick(newest(i)), mean, e1, e2);
      s += a;
      ss += a * a;
    }
    const double n = static_cast<double>(m);
    return std::max(0.0, ss.x - s.x * s.x / n) + std::max(0.0, ss.y - s.y * s.y / n);
  };
  glm::dvec3 world_mean;
  const double in_world = rss([](const Entry& e) { return e.world; }, world_mean);
  const double in_head = rss([](const Entry& e) { return e.head; }, head_mean);
  if (m < kMinPursuitSamples) return 0.0;  // too few for residuals: no evidence either way
  const double var = std::max(noise_var_, 1e-12);
  const double evidence = (in_world - in_head) / var;
  return std::isfinite(evidence) ? evidence : 0.0;
}

// Still in the head rather than in the world (the eyes carried by a moving head)? The evidence
// grows with the phase, so it is taken over the whole fixation (up to kCarriedWindow). A
// fixation earns the carried reading from its own samples, or, with carried_prior_fixations,
// starts with it after a run of fixations that earned it (the viewer's habit) and keeps it
// until its samples favour the world. Taking the habit from one fixation was measured and kept
// reflex-held fixations of noisy trackers read as carried (docs/evaluation.md, "Scenario
// family").
void GazeConditioner::update_carried(EyeMotion prev, std::int64_t t_ns) noexcept {
  std::size_t w = 0;
  while (w < phase_count_ && t_ns - newest(w).t_ns <= kCarriedWindowNs) ++w;
  glm::dvec3 head_mean = est_head_;
  const double evidence = carried_evidence(w, head_mean);
  if (prev != EyeMotion::fixation) begin_fixation_reading();
  const bool tested = w >= kMinPursuitSamples;
  const bool earned_before = carried_ && !carried_by_prior_;
  bool carried = tested && evidence > config_.carried_evidence * (earned_before ? config_.pursuit_exit_fraction : 1.0);
  if (carried) {
    fixation_earned_carried_ = true;
    carried_by_prior_ = false;
  }
  if (tested && evidence < -config_.carried_evidence) fixation_held_world_ = true;
  if (carried_by_prior_) {
    if (tested && evidence < -config_.carried_prior_exit * config_.carried_evidence) {
      carried_by_prior_ = false;
    } else {
      carried = true;
    }
  }
  carried_ = carried;
  if (carried_) {
    est_head_ = head_mean;
    // The world estimate follows the head too, so that whatever reads it next (a blink's held
    // estimate, the fixation once it is no longer carried) starts where the eye is, not where
    // the fixation's running mean of a turning gaze lags behind.
    glm::dvec3 w_now;
    if (normalized_dir(last_head_ * est_head_, w_now)) est_world_ = w_now;
  }
}

void GazeConditioner::begin_fixation_reading() noexcept {
  // The fixation before (if any) joins or ends the run.
  if (fixation_earned_carried_) {
    ++carried_run_;
  } else if (fixation_held_world_) {
    carried_run_ = 0;
  }
  fixation_earned_carried_ = false;
  fixation_held_world_ = false;
  carried_by_prior_ =
      config_.carried_prior_fixations > 0.0 && static_cast<double>(carried_run_) >= config_.carried_prior_fixations;
  carried_ = carried_by_prior_;
}

bool GazeConditioner::carried_habit() const noexcept {
  if (!(config_.carried_prior_fixations > 0.0) || fixation_held_world_) return false;
  const int run = carried_run_ + (fixation_earned_carried_ ? 1 : 0);
  return static_cast<double>(run) >= config_.carried_prior_fixations;
}

bool GazeConditioner::fixation_step(std::int64_t t_ns) noexcept {
  if (!(config_.fixation_step_chi2 > 0.0)) return false;
  const std::size_t avail = std::min(phase_count_, segment_count_);
  std::size_t k = 0;
  while (k < avail && t_ns - newest(k).t_ns <= kStepWindowNs) ++k;
  // The samples before them in the fixation, up to the dispersion window: as many at least
  // (three: one outlier is no step).
  std::size_t m = k;
  while (m < avail && t_ns - newest(m).t_ns <= config_.dispersion_window_ns) ++m;
  if (k < 3 || m - k < k) return false;
  // A saccade moves the eye in the head and in the world alike; a carried eye moves only in
  // the world, a reflex-held one only in the head. So a step must show in both. And a step is
  // a jump, not a ramp: the two means must also fit the samples better than a line through
  // them, by kStepOverLine noise variances, or it is the start of a pursuit, which the
  // dispersion test will take.
  const std::int64_t t0_ns = newest(0).t_ns;
  const auto stepped = [&](auto pick, glm::dvec3& landing) {
    glm::dvec3 e1, e2;
    const glm::dvec3 ref = pick(newest(0));
    aux::tangent_basis(ref, e1, e2);
    glm::dvec2 ss_recent(0.0), sta_recent(0.0), s_recent(0.0), s_before(0.0), ss_before(0.0), sta_before(0.0), ss(0.0),
        sa(0.0), sta(0.0);
    double st = 0.0, stt = 0.0, st_before = 0.0, stt_before = 0.0, st_recent = 0.0, stt_recent = 0.0;
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < m; ++i) {
      const glm::dvec2 a = aux::angular_offset_rad(pick(newest(i)), ref, e1, e2);
      const double t = aux::seconds_from_ns(newest(i).t_ns - t0_ns);
      if (i < k) {
        s_recent += a;
        ss_recent += a * a;
        sta_recent += t * a;
        st_recent += t;
        stt_recent += t * t;
        sum += pick(newest(i));
      } else {
        s_before += a;
        ss_before += a * a;
        st_before += t;
        stt_before += t * t;
        sta_before += t * a;
      }
      ss += a * a;
      sa += a;
      st += t;
      stt += t * t;
      sta += t * a;
    }
    const double nk = static_cast<double>(k), nb = static_cast<double>(m - k), n = static_cast<double>(m);
    const auto sum2 = [](glm::dvec2 v) { return v.x + v.y; };
    // Residual sum of squares (both axes) of the least-squares line through `count` samples.
    const auto line_rss = [&](double count, glm::dvec2 s_a, glm::dvec2 ss_a, double s_t, double ss_t, glm::dvec2 s_ta) {
      const double ctt = ss_t - s_t * s_t / count;
      const glm::dvec2 cta = s_ta - s_t * s_a / count;
      return ctt > 0.0 ? sum2(ss_a) - sum2(s_a * s_a) / count - sum2(cta * cta) / ctt
                       : std::numeric_limits<double>::quiet_NaN();
    };
    // The noise level: the long-run one, or the earlier samples' own scatter about their line
    // where that is larger (the long-run level starts from a guess and is learnt over seconds;
    // an underestimate would read noise as steps; about a line, so that a reflex-held eye's
    // steady drift in the head is not counted as noise).
    const double scatter = line_rss(nb, s_before, ss_before, st_before, stt_before, sta_before) / (2.0 * (nb - 2.0));
    // The newest samples' scatter about their mean moving at the earlier samples' drift (a
    // reflex-held eye drifts in the head, a carried one in the world, at the head's rate).
    const auto recent_rss_about_drift = [&] {
      const double ctt_b = stt_before - st_before * st_before / nb;
      const glm::dvec2 drift = ctt_b > 0.0 ? (sta_before - st_before * s_before / nb) / ctt_b : glm::dvec2(0.0);
      const glm::dvec2 caa = ss_recent - s_recent * s_recent / nk;
      const glm::dvec2 cta = sta_recent - st_recent * s_recent / nk;
      const double ctt = stt_recent - st_recent * st_recent / nk;
      return sum2(caa - 2.0 * drift * cta + drift * drift * ctt);
    };
    const double var = std::max({noise_var_, std::isfinite(scatter) ? scatter : 0.0, 1e-12});
    // The newest samples must themselves hold still (their scatter about their mean, moving at
    // the earlier drift, within the noise, p = 0.001): in flight, a missed saccade's last
    // samples spread along its path, and a restart there would put the fixation between the
    // two places and leave the rest of the flight to the next line fit, read as a pursuit
    // (measured with a noise-free tracker: docs/evaluation.md, "Scenario family", item 8).
    if (!(recent_rss_about_drift() <= chi2_upper_999(2.0 * (nk - 1.0)) * var)) return false;
    const glm::dvec2 d = s_recent / nk - s_before / nb;
    if (!(glm::dot(d, d) / (var * (1.0 / nk + 1.0 / nb)) > config_.fixation_step_chi2)) return false;
    // Residual sums of squares (both axes) of the two means and of the least-squares line.
    const double rss_step = sum2(ss) - sum2(s_recent * s_recent) / nk - sum2(s_before * s_before) / nb;
    const double rss_line = line_rss(n, sa, ss, st, stt, sta);
    return (rss_line - rss_step) / var > kStepOverLine && normalized_dir(sum, landing);
  };
  glm::dvec3 world_landing, head_landing;
  if (!stepped([](const Entry& e) { return e.world; }, world_landing) ||
      !stepped([](const Entry& e) { return e.head; }, head_landing))
    return false;
  est_world_ = world_landing;
  est_head_ = head_landing;
  fixation_n_ = static_cast<double>(k);
  phase_count_ = k;          // the dispersion and carried tests start from the landing
  begin_fixation_reading();  // and the carried reading is earned anew (or taken from the habit)
  ++fixation_restarts_;
  return true;
}

// Walk back from the newest sample while each older one lies within the noise of the newer
// ones' mean (p = 0.001 for a chi-square of 2 degrees of freedom, widened by the mean's own
// error), the noise being the larger of the long-run level and the newer samples' own scatter,
// capped at four times the long-run variance (the long-run level is learnt over seconds and
// starts from a guess; too small a level would stop the walk at once and put the landing at
// the newest sample, the old answer; an uncapped scatter grows with each accepted sample of
// the flight's slow tail and let the walk run back into the flight). The
// flight's samples lie apart from the landing in both frames (a saccade turns the eye in the
// head and in the world alike); the landing holds still in the world (reflex) or in the head
// (carried), so either frame will do. Not before the saccade's first labelled sample: a
// saccade within the noise gives that, the earliest (shortest window) answer.
std::int64_t GazeConditioner::landing_time() const noexcept {
  if (segment_count_ == 0) return last_valid_t_ns_;
  struct Run {
    glm::dvec3 e1, e2;
    glm::dvec2 s{0.0}, ss{0.0};
  };
  Run world, head;
  aux::tangent_basis(newest(0).world, world.e1, world.e2);
  aux::tangent_basis(newest(0).head, head.e1, head.e2);
  const double floor_var = std::max(noise_var_, 1e-12);
  const double chi2 = 13.82;       // chi-square, 2 degrees of freedom, p = 0.001
  const double kScatterCap = 4.0;  // variances: twice the deviation
  const auto near = [&](const Run& r, const glm::dvec3& ref, const glm::dvec3& d, double n) {
    const glm::dvec2 a = aux::angular_offset_rad(d, ref, r.e1, r.e2);
    const glm::dvec2 mean = r.s / n;
    const double scatter = n >= 3.0 ? (r.ss.x + r.ss.y - n * glm::dot(mean, mean)) / (2.0 * (n - 1.0)) : 0.0;
    // At most twice the long-run deviation: each accepted sample of a slow flight's tail
    // widens the scatter, and an uncapped one let the walk run back to the saccade's start.
    const double var = std::max(floor_var, std::min(scatter, kScatterCap * floor_var));
    const glm::dvec2 off = a - mean;
    return glm::dot(off, off) <= chi2 * var * (1.0 + 1.0 / n);
  };
  const auto add = [](Run& r, const glm::dvec3& ref, const glm::dvec3& d) {
    const glm::dvec2 a = aux::angular_offset_rad(d, ref, r.e1, r.e2);
    r.s += a;
    r.ss += a * a;
  };
  const glm::dvec3 ref_world = newest(0).world, ref_head = newest(0).head;
  add(world, ref_world, ref_world);
  add(head, ref_head, ref_head);
  std::int64_t landing = newest(0).t_ns;
  for (std::size_t j = 1; j < segment_count_; ++j) {
    const Entry& e = newest(j);
    if (e.t_ns < saccade_start_t_ns_) break;
    const double n = static_cast<double>(j);
    if (!near(world, ref_world, e.world, n) && !near(head, ref_head, e.head, n)) break;
    add(world, ref_world, e.world);
    add(head, ref_head, e.head);
    landing = e.t_ns;
  }
  return landing;
}

bool GazeConditioner::saccade_landed(double limit_deg_s) noexcept {
  std::size_t k = 0;
  while (k < segment_count_ && newest(0).t_ns - newest(k).t_ns <= kStepWindowNs &&
         newest(k).t_ns >= saccade_start_t_ns_)
    ++k;
  if (k < kMinLandingSamples || newest(0).t_ns - newest(k - 1).t_ns < kLandingMinSpanNs) return false;
  const double limit_rad_s = limit_deg_s * aux::kRadPerDeg;
  const double var = std::max(noise_var_, 1e-12);
  // Still: no slope through them above the velocity test's threshold over its own, longer,
  // window (a limit from these few samples' own standard error would let a noisy tracker's
  // flight through at its peak speed), and their scatter about their mean within the noise
  // (p = 0.001).
  const auto still = [&](auto pick) {
    glm::dvec3 sum(0.0), mean;
    for (std::size_t i = 0; i < k; ++i) sum += pick(newest(i));
    if (!normalized_dir(sum, mean)) return false;
    glm::dvec3 e1, e2;
    aux::tangent_basis(mean, e1, e2);
    glm::dvec2 s(0.0), ss(0.0), sta(0.0);
    double st = 0.0, stt = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
      const glm::dvec2 a = aux::angular_offset_rad(pick(newest(i)), mean, e1, e2);
      const double t = aux::seconds_from_ns(newest(i).t_ns - newest(0).t_ns);
      s += a;
      ss += a * a;
      sta += t * a;
      st += t;
      stt += t * t;
    }
    const double n = static_cast<double>(k);
    const double ctt = stt - st * st / n;
    if (!(ctt > 0.0)) return false;
    const glm::dvec2 slope = (sta - st * s / n) / ctt;
    if (!(std::hypot(slope.x, slope.y) < limit_rad_s)) return false;
    const double rss = std::max(0.0, ss.x - s.x * s.x / n) + std::max(0.0, ss.y - s.y * s.y / n);
    return rss <= chi2_upper_999(2.0 * (n - 1.0)) * var;
  };
  if (!still([](const Entry& e) { return e.world; }) && !still([](const Entry& e) { return e.head; })) return false;
  velocity_floor_t_ns_ = newest(k - 1).t_ns;
  return true;
}

}  // namespace gazelod::gaze
