// SPDX-License-Identifier: Apache-2.0
// The gaze conditioner's estimate at a display time (GazeConditioner::at): the newest fixation,
// pursuit or saccade estimate carried forward to the display, in the head at display time, with
// its uncertainty grown by its age.
#include "gaze/gaze_conditioner.hpp"

#include "auxiliary/angles.hpp"
#include "auxiliary/time.hpp"
#include "gaze/conditioner_math.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::gaze {

using detail::finite3;
using detail::normalized_dir;
using detail::normalized_quat;
using detail::sat_sub;

ConditionedGaze GazeConditioner::at(std::int64_t display_t_ns, const glm::dquat& head_at_display) noexcept {
  have_display_ = true;
  last_display_t_ns_ = display_t_ns;
  ConditionedGaze g;
  g.bad_samples = bad_samples_;
  g.fixation_restarts = fixation_restarts_;
  glm::dquat q;
  if (!normalized_quat(head_at_display, q)) q = last_head_;
  const glm::dquat q_inv = glm::conjugate(q);
  const glm::dvec3 ahead(0.0, 0.0, -1.0);

  if (!have_valid_ || !have_estimate_) {
    g.valid = false;
    g.motion = EyeMotion::loss;
    g.direction_head = ahead;
    if (!normalized_dir(q * ahead, g.direction_world)) g.direction_world = ahead;
    g.uncertainty_deg = config_.max_uncertainty_deg;
    return g;
  }

  g.sample_t_ns = last_valid_t_ns_;
  const std::int64_t age_ns = sat_sub(display_t_ns, last_valid_t_ns_);
  const double h_s = aux::seconds_from_ns(std::max<std::int64_t>(0, age_ns));
  const double cap_s = aux::seconds_from_ns(config_.prediction_horizon_max_ns);
  glm::dvec3 dir = est_world_;
  double speed_term_deg = 0.0;
  switch (motion_) {
    case EyeMotion::pursuit: {
      const double h_pred = std::min(h_s, cap_s);
      const double w = glm::length(omega_world_);
      if (std::isfinite(w) && w > 1e-12 && h_pred > 0.0) {
        const glm::dquat r = glm::angleAxis(w * h_pred, omega_world_ / w);
        glm::dvec3 next;
        if (normalized_dir(r * dir, next)) dir = next;
      }
      speed_term_deg = speed_deg_s_ * (config_.velocity_error_fraction * h_pred + (h_s - h_pred));
      break;
    }
    case EyeMotion::saccade:
      // Following: where the eye last was, and how far it may have gone since. Held: the
      // eye is already angle(held, newest) away and still moving.
      if (config_.saccade_follow_newest) {
        dir = last_raw_world_;
        speed_term_deg = speed_deg_s_ * h_s;
        // A saccade goes on along its path, not back: the cone over the path ahead, centred
        // half the distance on, with the margin for a curved path or an overshoot. The path is
        // no longer than a saccade lasts (max_saccade) nor than the oculomotor range
        // (max_uncertainty): a tracker that stops in flight does not send the cone away.
        double path_deg = std::min(speed_deg_s_ * std::min(h_s, aux::seconds_from_ns(config_.max_saccade_ns)),
                                   config_.max_uncertainty_deg);
        // No further ahead than a fraction of the path behind (saccade_ahead_of_travelled).
        if (config_.saccade_ahead_of_travelled > 0.0) {
          const double travelled_deg = aux::angle_between_rad(est_world_, last_raw_world_) * aux::kDegPerRad;
          const double cap_deg = config_.saccade_ahead_of_travelled * travelled_deg + kSaccadeAheadFloorDeg;
          if (std::isfinite(cap_deg)) path_deg = std::min(path_deg, cap_deg);
        }
        const double half_rad = 0.5 * path_deg * aux::kRadPerDeg;
        glm::dvec3 next;
        if (config_.saccade_cone_ahead && age_ns <= config_.loss_hold_max_ns && glm::length(saccade_axis_) > 0.5 &&
            std::isfinite(half_rad) && normalized_dir(glm::angleAxis(half_rad, saccade_axis_) * dir, next)) {
          dir = next;
          speed_term_deg = 0.5 * (1.0 + config_.saccade_path_margin) * path_deg;
        }
      } else {
        speed_term_deg = aux::angle_between_rad(est_world_, last_raw_world_) * aux::kDegPerRad + speed_deg_s_ * h_s;
      }
      break;
    case EyeMotion::fixation:
      // Carried: the eye holds its place in the head, which has turned since the sample.
      if (carried_) {
        glm::dvec3 next;
        if (normalized_dir(q * est_head_, next)) dir = next;
      }
      break;
    case EyeMotion::loss:
      break;
  }
  const double age_term_deg = config_.age_growth_deg_s * h_s;
  double unc = std::hypot(config_.accuracy_deg, std::hypot(age_term_deg, speed_term_deg));
  if (!std::isfinite(unc)) unc = config_.max_uncertainty_deg;
  g.uncertainty_deg = std::clamp(unc, config_.accuracy_deg, config_.max_uncertainty_deg);

  if (!normalized_dir(dir, g.direction_world)) g.direction_world = last_raw_world_;
  if (!normalized_dir(q_inv * g.direction_world, g.direction_head)) {
    g.direction_head = ahead;
    g.direction_world = q * ahead;
  }

  if (age_ns > config_.loss_hold_max_ns) {  // lost (or the source froze) too long
    g.valid = false;
    g.motion = EyeMotion::loss;
    g.suppressed = false;
    g.uncertainty_deg = config_.max_uncertainty_deg;
    return g;
  }
  g.valid = true;
  g.motion = motion_;
  if (motion_ == EyeMotion::pursuit && finite3(omega_world_)) g.angular_velocity_world_rad_s = omega_world_;
  // In a saccade between fixations that the head carried, the eye is taken to keep the habit
  // (carried_prior_fixations). Not in a blink: measured, it cost switches and degradations.
  if ((motion_ == EyeMotion::fixation && carried_) || (motion_ == EyeMotion::saccade && carried_habit())) {
    g.carried = true;
    // The head's rotation from the newest sample to the display time (exact poses, no noise).
    const glm::dquat dq = q * glm::conjugate(last_head_);
    const double s = glm::length(glm::dvec3(dq.x, dq.y, dq.z));
    const double angle = 2.0 * std::atan2(s, std::fabs(dq.w));
    if (h_s > 1e-3 && s > 1e-12 && std::isfinite(angle)) {
      const glm::dvec3 axis = glm::dvec3(dq.x, dq.y, dq.z) / s * (dq.w < 0.0 ? -1.0 : 1.0);
      g.angular_velocity_world_rad_s = axis * (angle / h_s);
    }
  }
  g.suppressed = motion_ == EyeMotion::saccade || motion_ == EyeMotion::loss ||
                 (have_saccade_ && sat_sub(display_t_ns, config_.post_saccade_from_landing ? saccade_landing_t_ns_
                                                                                           : saccade_last_t_ns_) <=
                                       config_.post_saccade_suppression_ns);
  return g;
}

}  // namespace gazelod::gaze
