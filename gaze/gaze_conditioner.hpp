// SPDX-License-Identifier: Apache-2.0
// Gaze conditioning for the frame loop: raw tracker samples in, one clean gaze estimate per
// frame out (docs/gaze.md, "Conditioning").
//
// Each sample is taken to the world (head orientation at the sample composed with the
// eye-in-head direction) and classified live, I-VDT style (Komogortsev & Karpov 2013):
//  1. saccade when the least-squares slope of the world direction over a short window
//     (velocity_window, at least 3 samples and half the window, never across a gap or an
//     invalid sample) exceeds saccade_threshold; during pursuit the slope is taken relative
//     to the pursuit velocity (so fast pursuit plus noise is no saccade). A saccade ends when
//     its newest samples hold still (saccade_ends_at_landing), and the next window then starts
//     at the landing and must be whole;
//  2. otherwise a dispersion test over the samples since the last saccade / gap / loss, at
//     most dispersion_window long and at least velocity_window, separates pursuit from
//     fixation. The dispersion is that of the least-squares line through the window
//     (|slope| x span: the spread the window would have without tracker noise, which at HMD
//     noise levels would otherwise exceed any useful threshold), and the slope must also
//     exceed pursuit_significance standard errors, from the window's residuals or the
//     long-run noise level in fixation, whichever is larger, so noise alone does not read as
//     pursuit. Once in pursuit, both tests use pursuit_exit_fraction of their thresholds.
// A fixation on a world point held through a head turn (vestibulo-ocular reflex) is therefore
// a fixation. A fixation whose samples hold still in the head rather than in the world (the
// eyes carried by a moving head) is told apart by comparing the two models' residuals over
// the phase (a likelihood ratio against the noise level, carried_evidence): it is then
// `carried`, its direction the mean eye-in-head direction turned by the head at the display
// time. A fast line in the world that barely moves in the head is such a fixation too, not a
// saccade or a pursuit (carried_shift_deg_s). After a run of carried fixations the next
// saccade and fixation start carried (the habit, carried_prior_fixations) until the new
// fixation's samples favour the world. Invalid samples are a blink / loss.
//
// Output: fixation -> the running mean of the fixation's world directions (exponential once
// older than fixation_smoothing_tau), held to the display time; pursuit -> the fitted line at
// the newest sample, predicted to the display time at the fitted angular velocity (at most
// prediction_horizon_max ahead); carried fixation -> the eye-in-head mean turned by the head
// at the display time; saccade -> the newest sample (saccade_follow_newest; else the estimate
// from before the saccade, held; the newest sample is moved speed * h / 2 on along the
// saccade's direction with saccade_cone_ahead), suppressed, and ended as soon as its newest
// samples hold still (saccade_ends_at_landing); loss -> held, suppressed, valid for at most
// loss_hold_max after the last valid sample. The angular velocity is non-zero only in pursuit,
// carried fixations and saccades read as carried by the habit. With h = display time - newest
// valid sample (>= 0) and H = prediction_horizon_max, the uncertainty is
//   clamp(sqrt(accuracy^2 + (age_growth * h)^2 + s^2), accuracy, max_uncertainty)
// with the speed term s = 0 in fixation and loss, |omega| (velocity_error_fraction * min(h, H)
// + max(0, h - H)) in pursuit, and speed * h in a saccade ((1 + saccade_path_margin) / 2 of it
// with saccade_cone_ahead, the path at most saccade_ahead_of_travelled of the path so far
// plus kSaccadeAheadFloorDeg; plus angle(held estimate, newest sample) when it is held);
// max_uncertainty when !valid. GazeSample::confidence is not used (sources mark
// unusable samples invalid).
//
// Fixed capacity, no allocation after construction: the history is a ring of kCapacity
// samples (windows are in time, so above kCapacity / dispersion_window = 1280 Hz the windows
// hold the newest kCapacity samples). Every output is finite and every direction unit length,
// whatever the input.
#pragma once

#include "auxiliary/time.hpp"
#include "gaze/conditioner_config.hpp"
#include "gaze/gaze_sample.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace gazelod::gaze {

enum class EyeMotion : std::uint8_t { fixation, saccade, pursuit, loss };
const char* to_string(EyeMotion motion);

struct ConditionedGaze {
  bool valid = false;  // false: no usable gaze (never seen, lost too long, or all input bad)
  EyeMotion motion = EyeMotion::loss;
  glm::dvec3 direction_world{0, 0, -1};  // predicted to the display time, unit
  glm::dvec3 direction_head{0, 0, -1};   // the same in the head at the display time (head_at_display^-1 * world)
  glm::dvec3 angular_velocity_world_rad_s{0.0};  // eye-in-world; 0 in a fixation held in the world
  // A fixation of the eye in the head while the head moves (fixation, carried), or a saccade
  // between such fixations (carried_prior_fixations): the gaze moves with the head, apart from
  // the saccade's own jump; the eye-in-head velocity is taken as 0. angular_velocity_world is
  // then the head's rotation from the newest sample to the display time.
  bool carried = false;
  double uncertainty_deg = 0.0;  // angular uncertainty of direction_world (accuracy, age, speed), capped
  std::int64_t sample_t_ns = 0;  // newest valid sample used (0: none)
  bool suppressed =
      false;  // in a saccade or blink/loss, or within post_saccade_suppression after a saccade (false when !valid)
  std::int64_t bad_samples = 0;        // NaN / zero / non-finite / backwards / far-future samples refused so far
  std::int64_t fixation_restarts = 0;  // fixations restarted by the step test so far (fixation_step_chi2)
};

class GazeConditioner {
 public:
  static constexpr std::size_t kCapacity = 256;

  // Throws std::invalid_argument with validate_conditioner_config's reason for a bad setting
  // (construction is where configuration is refused; nothing is replaced by a default).
  explicit GazeConditioner(ConditionerConfig config = {});
  // The newest sample of the source and the head's world orientation (head-to-world) at the
  // sample's time. A sample with the same t_ns as the previous one is a repeat and ignored;
  // invalid samples mean blink/loss; NaN/zero/backwards samples (and a non-finite or zero
  // quaternion with a valid sample) are refused and counted. No allocation.
  void push(const GazeSample& sample, const glm::dquat& head_at_sample) noexcept;
  // The gaze at the display time, with the head orientation at that time (a non-finite or zero
  // quaternion falls back to the head at the newest sample). No allocation.
  ConditionedGaze at(std::int64_t display_t_ns, const glm::dquat& head_at_display) noexcept;
  void reset() noexcept;  // source change: forget history (bad_samples is kept)
  std::int64_t bad_samples() const noexcept { return bad_samples_; }  // refused so far

  const ConditionerConfig& config() const { return config_; }

 private:
  struct Entry {
    std::int64_t t_ns = 0;
    glm::dvec3 world{0.0, 0.0, -1.0};
    glm::dvec3 head{0.0, 0.0, -1.0};  // the eye-in-head direction of the same sample
  };
  struct Fit;
  // In the world, or with in_head the eye-in-head directions.
  Fit fit_newest(std::size_t count, bool in_head = false) const noexcept;
  const Entry& newest(std::size_t back) const noexcept;
  void push_valid(std::int64_t t_ns, const glm::dvec3& world, const glm::dvec3& head) noexcept;
  // Twice the log-likelihood ratio of "still in the head" over "still in the world" for the
  // newest m samples, in noise variances; and the eye-in-head mean
  // (gaze/conditioner_fixation.cpp).
  double carried_evidence(std::size_t m, glm::dvec3& head_mean) const noexcept;
  // In a fixation or a pursuit: restarts a fixation at the newest samples when they hold still
  // apart from the phase's earlier ones (fixation_step_chi2); true if it did.
  bool fixation_step(std::int64_t t_ns) noexcept;
  // The world line `world` through the newest n samples is the head carrying the eye
  // (carried_shift_deg_s).
  bool carried_line(const Fit& world, std::size_t n) const noexcept;
  // The run of carried fixations up to now, the current (or just ended) fixation included;
  // true when it reaches carried_prior_fixations.
  bool carried_habit() const noexcept;
  // A new fixation (after a saccade, a pursuit, a loss, or a step): the one before joins or
  // ends the run, and the new one starts carried if the run is long enough.
  void begin_fixation_reading() noexcept;
  // When a saccade just ended, the time of its landing: the oldest sample since it began from
  // which on every sample lies within the noise of the newer ones' mean, in the world or in the
  // head (gaze/conditioner_fixation.cpp).
  std::int64_t landing_time() const noexcept;
  // In a saccade: its newest samples (kStepWindowNs, at least kMinLandingSamples over
  // kLandingMinSpanNs, all since it began) hold still, in the world or in the head, with no
  // slope above limit_deg_s (the velocity test's threshold over its own window) through them:
  // it has landed. Sets velocity_floor_t_ns_. (The fixation still starts from the newest
  // sample: the run's oldest samples may be the flight's slow tail, and starting the phase
  // with them biased the carried test: measured, ConditionerHabit.)
  bool saccade_landed(double limit_deg_s) noexcept;
  // The carried test of a fixation sample (carried_evidence, the habit).
  void update_carried(EyeMotion prev, std::int64_t t_ns) noexcept;
  void push_invalid(std::int64_t t_ns) noexcept;

  ConditionerConfig config_;
  std::array<Entry, kCapacity> ring_{};
  std::size_t head_ = 0;           // index of the next write
  std::size_t segment_count_ = 0;  // newest samples since the last gap / invalid sample / reset
  std::size_t phase_count_ = 0;    // newest samples since the current fixation/pursuit phase began

  bool have_seen_ = false;  // any sample pushed (for repeats)
  std::int64_t last_seen_t_ns_ = 0;
  bool have_time_ = false;      // any sample accepted (valid or not)
  std::int64_t last_t_ns_ = 0;  // newest accepted sample (valid or not)
  bool have_valid_ = false;     // a valid sample since the last reset
  std::int64_t last_valid_t_ns_ = 0;
  glm::dvec3 last_raw_world_{0.0, 0.0, -1.0};
  glm::dquat last_head_{1.0, 0.0, 0.0, 0.0};
  bool have_display_ = false;
  std::int64_t last_display_t_ns_ = 0;

  EyeMotion motion_ = EyeMotion::loss;
  bool have_estimate_ = false;
  // The estimate at the newest valid sample: fixation mean, pursuit fit, or held.
  glm::dvec3 est_world_{0.0, 0.0, -1.0};
  glm::dvec3 omega_world_{0.0};           // pursuit only
  bool carried_ = false;                  // fixation: still in the head, not in the world
  bool carried_by_prior_ = false;         // ... taken from the run before it, not yet earned
  bool fixation_earned_carried_ = false;  // this fixation's samples earned the carried reading
  bool fixation_held_world_ = false;      // ... or favoured the world by carried_evidence
  int carried_run_ = 0;                   // fixations in a row before this one that earned it
  glm::dvec3 est_head_{0.0, 0.0, -1.0};   // carried: the eye-in-head mean
  double speed_deg_s_ = 0.0;              // eye-in-world speed of the current motion (0 in fixation)
  glm::dvec3 saccade_axis_{0.0};          // saccade: the unit rotation axis of its motion (0: unknown)
  double fixation_n_ = 0.0;               // samples in the fixation mean so far
  double noise_var_ = 0.0;  // long-run residual variance per axis in fixation, rad^2 (from precision_deg at first)
  bool have_saccade_ = false;
  std::int64_t saccade_last_t_ns_ = 0;     // newest saccade-labelled sample
  std::int64_t saccade_start_t_ns_ = 0;    // first sample of the saccade in progress
  std::int64_t saccade_landing_t_ns_ = 0;  // the last saccade's landing (landing_time), eye time
  // The velocity fit takes no sample older than this (a landing seen by saccade_landed).
  std::int64_t velocity_floor_t_ns_ = std::numeric_limits<std::int64_t>::min();
  std::int64_t bad_samples_ = 0;
  std::int64_t fixation_restarts_ = 0;  // kept across reset(), like bad_samples_
};

}  // namespace gazelod::gaze
