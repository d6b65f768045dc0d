// SPDX-License-Identifier: Apache-2.0
#include "gaze/gaze_conditioner.hpp"

#include "gaze/conditioner_math.hpp"

#include "auxiliary/time.hpp"
#include "auxiliary/angles.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace gazelod::gaze {

using detail::ema_alpha;
using detail::finite3;
using detail::kMinPursuitSamples;
using detail::normalized_dir;
using detail::normalized_quat;
using detail::sat_sub;

namespace {

constexpr std::size_t kMinVelocitySamples = 3;  // a slope from fewer is a two-sample difference
constexpr double kNoiseTau_s = 2.0;             // averaging time of the long-run noise level

// The constructor's check: a bad setting is refused with its name and value, never replaced
// by a default (docs/error-policy.md).
ConditionerConfig checked(ConditionerConfig c) {
  if (std::string e = validate_conditioner_config(c); !e.empty()) throw std::invalid_argument("gaze conditioner: " + e);
  return c;
}

}  // namespace

const char* to_string(EyeMotion motion) {
  switch (motion) {
    case EyeMotion::fixation:
      return "fixation";
    case EyeMotion::saccade:
      return "saccade";
    case EyeMotion::pursuit:
      return "pursuit";
    case EyeMotion::loss:
      return "loss";
  }
  return "unknown";
}

// Least-squares line through the newest `n` world directions, in tangent-plane angles
// (atan2, radians) about the newest direction, against time in seconds from the newest sample.
struct GazeConditioner::Fit {
  std::size_t n = 0;
  double span_s = 0.0;  // newest - oldest sample time
  glm::dvec3 ref{0.0, 0.0, -1.0}, e1{1.0, 0.0, 0.0}, e2{0.0, 1.0, 0.0};
  glm::dvec2 slope{0.0};                                      // rad/s along e1, e2
  glm::dvec2 at_newest{0.0};                                  // fitted angles at the newest sample's time, rad
  double ctt = 0.0;                                           // sum of squared time deviations, s^2
  double resid_var = 0.0;                                     // residual variance per component, rad^2 (0 unless n > 2)
  double slope_se = std::numeric_limits<double>::infinity();  // standard error per component
  bool ok = false;

  double speed_rad_s() const { return std::hypot(slope.x, slope.y); }
  // The fitted direction at the newest sample's time (unit).
  glm::dvec3 direction() const {
    if (!(std::fabs(at_newest.x) < 1.4 && std::fabs(at_newest.y) < 1.4)) return ref;
    glm::dvec3 d;
    if (!normalized_dir(ref + e1 * std::tan(at_newest.x) + e2 * std::tan(at_newest.y), d)) return ref;
    return d;
  }
  // Angular velocity vector (rad/s, world): omega x d = d(d)/dt at the reference direction.
  glm::dvec3 omega() const { return glm::cross(ref, e1 * slope.x + e2 * slope.y); }
};

const GazeConditioner::Entry& GazeConditioner::newest(std::size_t back) const noexcept {
  return ring_[(head_ + kCapacity - 1 - back) % kCapacity];
}

GazeConditioner::Fit GazeConditioner::fit_newest(std::size_t count, bool in_head) const noexcept {
  const auto dir = [in_head](const Entry& e) -> const glm::dvec3& { return in_head ? e.head : e.world; };
  Fit f;
  count = std::min(count, segment_count_);
  f.n = count;
  if (count == 0) return f;
  const Entry& last = newest(0);
  f.ref = dir(last);
  aux::tangent_basis(f.ref, f.e1, f.e2);
  if (count < 2) return f;
  double st = 0, sx = 0, sy = 0, stt = 0, stx = 0, sty = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Entry& e = newest(i);
    const double t = aux::seconds_from_ns(e.t_ns - last.t_ns);
    const glm::dvec2 a = aux::angular_offset_rad(dir(e), f.ref, f.e1, f.e2);
    st += t;
    sx += a.x;
    sy += a.y;
    stt += t * t;
    stx += t * a.x;
    sty += t * a.y;
    sxx += a.x * a.x;
    syy += a.y * a.y;
  }
  const double n = static_cast<double>(count);
  const double mt = st / n, mx = sx / n, my = sy / n;
  const double ctt = stt - st * mt;
  if (!(ctt > 1e-16)) return f;  // all samples at (nearly) one time
  const double ctx = stx - st * mx, cty = sty - st * my;
  const double cxx = sxx - sx * mx, cyy = syy - sy * my;
  f.ctt = ctt;
  f.slope = {ctx / ctt, cty / ctt};
  f.at_newest = {mx - f.slope.x * mt, my - f.slope.y * mt};
  f.span_s = aux::seconds_from_ns(last.t_ns - newest(count - 1).t_ns);
  if (count > 2) {
    const double rss = std::max(0.0, cxx - f.slope.x * ctx) + std::max(0.0, cyy - f.slope.y * cty);
    f.resid_var = std::max(0.0, rss / (2.0 * (n - 2.0)));
    f.slope_se = std::sqrt(f.resid_var / ctt);
  }
  f.ok = std::isfinite(f.slope.x) && std::isfinite(f.slope.y) && std::isfinite(f.at_newest.x) &&
         std::isfinite(f.at_newest.y) && std::isfinite(f.span_s);
  if (!f.ok) {
    f.slope = glm::dvec2(0.0);
    f.at_newest = glm::dvec2(0.0);
  }
  return f;
}

// A line through the newest n samples (fitted in the world: `world`) whose eye-in-head
// directions move at most half as fast: the head carries the eye. Faster than
// carried_shift_deg_s, or at any speed while the eye is read as carried (the line then ends in
// the head's own stop, not a pursuit's).
bool GazeConditioner::carried_line(const Fit& world, std::size_t n) const noexcept {
  if (!(config_.carried_shift_deg_s > 0.0) || !world.ok) return false;
  const double speed = world.speed_rad_s();
  const bool carried_now = motion_ == EyeMotion::fixation && carried_;
  if (!carried_now && !(speed * aux::kDegPerRad > config_.carried_shift_deg_s)) return false;
  const Fit in_head = fit_newest(n, true);
  return in_head.ok && in_head.speed_rad_s() < 0.5 * speed;
}

GazeConditioner::GazeConditioner(ConditionerConfig config)
    : config_(checked(std::move(config))),
      noise_var_(0.5 * (config_.precision_deg * aux::kRadPerDeg) * (config_.precision_deg * aux::kRadPerDeg)) {}

void GazeConditioner::reset() noexcept {
  const std::int64_t bad = bad_samples_, restarts = fixation_restarts_;
  const bool have_display = have_display_;
  const std::int64_t display = last_display_t_ns_;
  const ConditionerConfig config = config_;
  *this = GazeConditioner(config);  // config_ passed the constructor's check: cannot throw here
  bad_samples_ = bad;
  fixation_restarts_ = restarts;
  have_display_ = have_display;
  last_display_t_ns_ = display;
}

void GazeConditioner::push(const GazeSample& sample, const glm::dquat& head_at_sample) noexcept {
  // Repeats: the plugin polls the source once a frame and often sees the same sample again.
  if (have_seen_ && sample.t_ns == last_seen_t_ns_) return;
  if (have_time_ && sample.t_ns == last_t_ns_) return;  // the accepted one again, after a refused one
  have_seen_ = true;
  last_seen_t_ns_ = sample.t_ns;
  if (have_time_ && sample.t_ns < last_t_ns_) {
    ++bad_samples_;  // backwards in time
    return;
  }
  if (have_display_ && sat_sub(sample.t_ns, last_display_t_ns_) > config_.max_sample_lead_ns) {
    ++bad_samples_;  // implausibly far in the future
    return;
  }
  if (!sample.valid) {
    push_invalid(sample.t_ns);
    return;
  }
  glm::dvec3 d;
  glm::dquat q;
  if (!normalized_dir(sample.direction, d) || !normalized_quat(head_at_sample, q)) {
    ++bad_samples_;
    return;
  }
  glm::dvec3 world;
  if (!normalized_dir(q * d, world)) {
    ++bad_samples_;
    return;
  }
  last_head_ = q;
  push_valid(sample.t_ns, world, d);
}

void GazeConditioner::push_invalid(std::int64_t t_ns) noexcept {
  have_time_ = true;
  last_t_ns_ = t_ns;
  segment_count_ = 0;
  phase_count_ = 0;
  fixation_n_ = 0.0;
  motion_ = EyeMotion::loss;  // est_world_ is held
  omega_world_ = glm::dvec3(0.0);
  speed_deg_s_ = 0.0;
  carried_ = false;
}

void GazeConditioner::push_valid(std::int64_t t_ns, const glm::dvec3& world, const glm::dvec3& head) noexcept {
  if (have_time_ && sat_sub(t_ns, last_t_ns_) > config_.max_gap_ns) {
    // A gap: no fit spans it, and the eye may have moved meanwhile (as after a loss).
    segment_count_ = 0;
    phase_count_ = 0;
    fixation_n_ = 0.0;
    motion_ = EyeMotion::loss;
    omega_world_ = glm::dvec3(0.0);
    carried_ = false;
  }
  const double dt_s = segment_count_ > 0 ? aux::seconds_from_ns(sat_sub(t_ns, newest(0).t_ns)) : 0.0;
  ring_[head_] = Entry{t_ns, world, head};
  head_ = (head_ + 1) % kCapacity;
  segment_count_ = std::min(segment_count_ + 1, kCapacity);
  phase_count_ = std::min(phase_count_ + 1, kCapacity);
  have_time_ = true;
  last_t_ns_ = t_ns;
  have_valid_ = true;
  last_valid_t_ns_ = t_ns;
  last_raw_world_ = world;
  const EyeMotion prev = motion_;

  // 1. I-VT: the least-squares speed over the velocity window (at least 3 samples).
  std::size_t k = 0;
  bool after_landing = false;  // the fit starts at a landing (saccade_landed)
  while (k < segment_count_) {
    const std::int64_t age = t_ns - newest(k).t_ns;
    if (age > config_.dispersion_window_ns) break;
    if (newest(k).t_ns < velocity_floor_t_ns_) {
      after_landing = true;
      break;
    }
    if (k >= kMinVelocitySamples && age > config_.velocity_window_ns) break;
    ++k;
  }
  const Fit fv = fit_newest(k);
  // Relative to the pursuit in progress (a saccade on a moving background: catch-up saccades
  // are saccades, fast pursuit with noise is not).
  glm::dvec2 rel = fv.slope;
  if (prev == EyeMotion::pursuit) {
    const glm::dvec3 u = glm::cross(omega_world_, fv.ref);  // pursuit tangent velocity at ref
    rel -= glm::dvec2(glm::dot(u, fv.e1), glm::dot(u, fv.e2));
  }
  const double v_deg_s = std::hypot(rel.x, rel.y) * aux::kDegPerRad;
  // A fit over much less than the window (a young segment at a high rate) is too noisy.
  const double v_window_s = aux::seconds_from_ns(config_.velocity_window_ns);
  // The fitted speed's standard error per axis under the long-run noise level.
  const double v_se_deg_s = fv.ctt > 0.0 ? std::sqrt(noise_var_ / fv.ctt) * aux::kDegPerRad : 0.0;
  const double v_threshold = std::max(config_.saccade_threshold_deg_s, config_.saccade_significance * v_se_deg_s);
  // Fast in the world but not in the head: the head carrying the eye through a turn
  // (carried_shift_deg_s), not a saccade, which turns the eye in the head.
  const bool carried_shift = carried_line(fv, k);
  const bool landed = prev == EyeMotion::saccade && config_.saccade_ends_at_landing && saccade_landed(v_threshold);
  // After a landing, a whole window of samples: the next saccade is rarely that soon, and a
  // shorter fit over the landing's first samples reads the flight's last drift and the noise as
  // a new saccade.
  const double min_span_s = (after_landing ? 1.0 : 0.5) * v_window_s;
  if (!landed && fv.ok && fv.n >= kMinVelocitySamples && fv.span_s >= min_span_s && v_deg_s > v_threshold &&
      !carried_shift) {
    carried_ = false;
    // No estimate yet (the stream began in a saccade): the oldest sample of the fit, where
    // the saccade started from.
    if (prev != EyeMotion::saccade) saccade_start_t_ns_ = t_ns;
    if (t_ns - saccade_start_t_ns_ > config_.max_saccade_ns && fv.ok) {
      // Too long for a saccade: a smooth gaze shift at saccadic speed.
      omega_world_ = fv.omega();
      if (!finite3(omega_world_)) omega_world_ = glm::dvec3(0.0);
      est_world_ = fv.direction();
      have_estimate_ = true;
      motion_ = EyeMotion::pursuit;
      speed_deg_s_ = glm::length(omega_world_) * aux::kDegPerRad;
      fixation_n_ = 0.0;
      phase_count_ = fv.n;  // the pursuit's phase: the samples of this fit
      return;
    }
    if (!have_estimate_) est_world_ = newest(k - 1).world;
    have_estimate_ = true;
    motion_ = EyeMotion::saccade;  // est_world_ (the estimate before the saccade) is held
    omega_world_ = glm::dvec3(0.0);
    speed_deg_s_ = fv.speed_rad_s() * aux::kDegPerRad;
    {
      const glm::dvec3 om = fv.omega();
      const double w = glm::length(om);
      saccade_axis_ = std::isfinite(w) && w > 1e-9 ? om / w : glm::dvec3(0.0);
    }
    have_saccade_ = true;
    saccade_last_t_ns_ = t_ns;
    saccade_landing_t_ns_ = t_ns;  // until it is seen to end
    phase_count_ = 0;              // the next phase begins after the saccade
    fixation_n_ = 0.0;
    return;
  }

  // The saccade has ended: the velocity fit, over a window, falls below the threshold only
  // once most of the flight has left it, tens of ms after the landing.
  if (prev == EyeMotion::saccade) saccade_landing_t_ns_ = landing_time();

  // 2. A fixation that stepped to a new place (a saccade the velocity test missed) restarts
  // there first, so the dispersion test below does not read the jump as a pursuit. In a
  // pursuit too: a jump read as one while in flight (the line through the samples before and
  // after it is steep) ends as soon as its landing holds still, rather than when the jump
  // leaves the dispersion window; a real pursuit's samples lie on a line, which two means do
  // not fit better.
  const bool stepped = (prev == EyeMotion::fixation || prev == EyeMotion::pursuit) && fixation_step(t_ns);
  // 3. Dispersion over the phase so far (since the saccade / gap / loss / step), at most the
  // window.
  std::size_t m = 0;
  while (m < phase_count_ && t_ns - newest(m).t_ns <= config_.dispersion_window_ns) ++m;
  const Fit fd = fit_newest(m);
  const double speed = fd.speed_rad_s();
  // Hysteresis: a pursuit in progress continues down to pursuit_exit_fraction of both tests.
  const double f = prev == EyeMotion::pursuit ? config_.pursuit_exit_fraction : 1.0;
  // The slope's standard error from this window's residuals, but never below the one the
  // long-run noise level gives (a window of few samples can have small residuals by chance).
  const double se = fd.ok && fd.ctt > 0.0 ? std::sqrt(std::max(fd.resid_var, noise_var_) / fd.ctt)
                                          : std::numeric_limits<double>::infinity();
  bool pursuit = fd.ok && fd.n >= kMinPursuitSamples && fd.span_s >= v_window_s &&
                 speed * fd.span_s * aux::kDegPerRad >= f * config_.dispersion_threshold_deg &&
                 speed > f * config_.pursuit_significance * se;
  // Faster than a pursuit goes (or the eye already carried) and not moving in the head: the
  // head carries the eye through a turn. Read as a pursuit, its speed would outlast the turn by
  // the tracker's latency (the plugin would take the world to slip across the retina at the
  // turn's rate after the head stopped); read as a carried fixation, the eye follows the
  // head's own, current, motion.
  if (pursuit && carried_line(fd, m)) pursuit = false;
  if (pursuit) {
    carried_ = false;
    const glm::dvec3 om = fd.omega();
    if (prev != EyeMotion::pursuit) {
      omega_world_ = om;
    } else {
      const double a = ema_alpha(dt_s, aux::seconds_from_ns(config_.pursuit_velocity_tau_ns));
      omega_world_ += a * (om - omega_world_);
    }
    if (!finite3(omega_world_)) omega_world_ = glm::dvec3(0.0);
    est_world_ = fd.direction();
    motion_ = EyeMotion::pursuit;
    speed_deg_s_ = glm::length(omega_world_) * aux::kDegPerRad;
    fixation_n_ = 0.0;
  } else {
    if (stepped) {
      // Restarted at the landing (fixation_step).
    } else if (prev != EyeMotion::fixation) {
      if (prev == EyeMotion::pursuit && fd.ok) {
        // From pursuit: start at the fitted position, weighted like a quarter of its samples.
        est_world_ = fd.direction();
        fixation_n_ = std::max(1.0, static_cast<double>(fd.n) / 4.0);
      } else {
        est_world_ = world;
        fixation_n_ = 1.0;
      }
    } else {
      fixation_n_ += 1.0;
      const double a =
          std::max(1.0 / fixation_n_, ema_alpha(dt_s, aux::seconds_from_ns(config_.fixation_smoothing_tau_ns)));
      glm::dvec3 next;
      if (normalized_dir(aux::slerp_direction(est_world_, world, std::clamp(a, 0.0, 1.0)), next)) est_world_ = next;
    }
    update_carried(prev, t_ns);
    motion_ = EyeMotion::fixation;
    omega_world_ = glm::dvec3(0.0);
    speed_deg_s_ = 0.0;
    // Long-run noise level (the adaptive noise estimate of Nyström & Holmqvist 2010, here
    // from the fixation windows' residuals: about the line in the head while carried, where
    // the world line bends with the head's motion and its scatter is not noise).
    const Fit fn = carried_ ? fit_newest(m, true) : fd;
    if (!stepped && fn.ok && fn.n >= kMinPursuitSamples && std::isfinite(fn.resid_var))
      noise_var_ += ema_alpha(dt_s, kNoiseTau_s) * (fn.resid_var - noise_var_);
  }
  if (!finite3(est_world_)) est_world_ = world;
  have_estimate_ = true;
}

}  // namespace gazelod::gaze
