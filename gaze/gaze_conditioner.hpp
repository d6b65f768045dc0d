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
// with saccade_cone_ahead; plus angle(held estimate, newest sample) when it is held);
// max_uncertainty when !valid. GazeSample::confidence is not used (sources mark
// unusable samples invalid).
//
// Fixed capacity, no allocation after construction: the history is a ring of kCapacity
// samples (windows are in time, so above kCapacity / dispersion_window = 1280 Hz the windows
// hold the newest kCapacity samples). Every output is finite and every direction unit length,
// whatever the input.
#pragma once

#include "auxiliary/time.hpp"
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

struct ConditionerConfig {
  // Source accuracy (systematic angular error), the floor of uncertainty_deg. HMD trackers
  // measure about 1 deg in the central field and worse toward the periphery (Schuetz &
  // Fiehler 2022, HTC Vive Pro Eye); 1.5 deg as the plugin's openxr_gaze_error_deg.
  double accuracy_deg = 1.5;
  // Initial guess of the tracker's noise (RMS angular distance of a sample from the true
  // direction, both axes together): the 0.5 deg of the issue this was written for. Only a
  // starting point: the level is re-measured from the residuals of fixation windows (an
  // adaptive noise estimate, as in Nyström & Holmqvist 2010) with a 2 s time constant.
  double precision_deg = 0.5;

  // I-VT stage (Salvucci & Goldberg 2000; the first stage of I-VDT, Komogortsev & Karpov
  // 2013). 70 deg/s rather than Olsen's (2012) 30 deg/s because HMD noise is larger: at
  // 0.5 deg RMS and 120 Hz the 50 ms fit has ~8 deg/s RMS of noise per axis (30 deg/s would
  // be crossed every few seconds, 70 practically never), while saccades of 2 deg and more
  // peak above 100 deg/s (Bahill, Clark & Stark 1975).
  double saccade_threshold_deg_s = 70.0;
  // ... and at least this many standard errors of the fitted speed under the measured noise
  // level (the same t test as pursuit_significance): a noisier tracker raises the effective
  // threshold, so noise alone does not read as saccades. At 1.4 deg and 227 Hz the 50 ms fit
  // has ~30 deg/s of noise per axis and crossed 70 deg/s several times a second (each false
  // saccade suppressing, re-centring and widening the estimate: measured with gazelod eval
  // family as level switches in fixations at five times the true gaze's own rate).
  double saccade_significance = 5.0;
  // Window of the saccade-velocity fit, widened to 3 samples at low rates. The velocity noise
  // of a least-squares slope is sigma * sqrt(12 / (n T^2)) (a Savitzky-Golay first derivative,
  // Savitzky & Golay 1964): Olsen's (2012) 20 ms gives ~30 deg/s per axis at 0.5 deg and
  // 120 Hz, 50 ms ~8 deg/s; a 10 deg saccade (43 ms, Carpenter 1988) is then detected ~25 ms
  // after its onset (tests/gaze/gaze_conditioner_test.cpp).
  std::int64_t velocity_window_ns = 50'000'000;
  // Dispersion stage (I-DT: Salvucci & Goldberg 2000 suggest 100-200 ms windows and a
  // dispersion of 0.5-1 deg): a window of 200 ms whose fitted line spreads over more than
  // 1 deg is pursuit, i.e. pursuit from 5 deg/s on (slower motion is treated as fixational
  // drift and followed by the fixation average).
  std::int64_t dispersion_window_ns = 200'000'000;
  double dispersion_threshold_deg = 1.0;
  // The slope must also exceed this many of its standard errors (from the window's residuals
  // or the long-run noise level, whichever is larger): a t test of the regression slope in
  // two dimensions; under noise alone |slope| / SE > 5 has probability ~exp(-5^2/2) = 4e-6
  // for many samples (heavier tails for few). In simulation at 90 Hz and 0.5 deg, 4 left
  // 6e-4 of the frames at rest in false pursuit, 5 none in 5 minutes.
  double pursuit_significance = 5.0;
  // Hysteresis: once in pursuit, both tests use this fraction of their thresholds, so noise
  // near the limits does not toggle pursuit and fixation every frame (chosen here, by
  // simulation of 10 deg/s pursuit at 60-120 Hz; no literature value).
  double pursuit_exit_fraction = 0.7;
  // A fixation is carried by the head when the samples' spread about a constant world
  // direction exceeds their spread about a constant eye-in-head direction by this many noise
  // variances (per axis): twice the log-likelihood ratio of the two models with Gaussian
  // noise, so 12 means odds of e^6 (~400:1). A head still within the noise leaves the two
  // equal and the fixation in the world (the safer reading: no retinal slip assumed). Left at
  // pursuit_exit_fraction of it once carried.
  double carried_evidence = 12.0;
  // A line in the world faster than this whose eye-in-head directions move at most half as
  // fast is the head carrying the eye through a turn, neither a saccade (which turns the eye in
  // the head) nor a pursuit: it is read as a fixation, carried once carried_evidence says so,
  // so the gaze follows the head's current motion rather than the line's velocity, which the
  // tracker reports a latency late (after a 138 deg/s turn stopped, the plugin took the world
  // to sweep across the retina at that rate for ~100 ms: family seed 2047). While a fixation is
  // read as carried, the same holds at any speed (the line through the end of a turn slows
  // down with the head). Pursuit tracks targets up to ~30 deg/s and saturates near 60-100 deg/s
  // (Meyer, Lasker & Robinson 1985); below this a line the head follows is taken for a pursuit
  // whose target keeps its velocity. 40, 60 and 90 measured alike on the family's tuning seeds
  // (docs/evaluation.md, "Scenario family", item 9). 0: off.
  double carried_shift_deg_s = 60.0;
  // The viewer's habit: after this many fixations in a row that earned the carried reading
  // (carried_evidence), the saccade that ends the last of them and the next fixation are read
  // as carried too (the eye moves with the head rather than holding the world), until the new
  // fixation's samples favour the world by carried_prior_exit times carried_evidence. A
  // fixation whose samples favour the world by carried_evidence ends the run. Without it each
  // fixation starts held in the world and earns the reading 40-70 ms after the tracker shows
  // its landing, too late for the switch policy's hold before the next saccade, so the eyes
  // carried through a head sweep were drawn at up to 2-3x the oracle's triangles. 3 and 1:
  // chosen on the scenario family's seeds 1000-1099; 1 and 2 fixations took noisy trackers'
  // reflex-held fixations for carried (docs/evaluation.md, "Scenario family", item 10).
  // 0: off (each fixation earns the reading anew).
  double carried_prior_fixations = 3.0;
  double carried_prior_exit = 1.0;
  // A larger gap between samples splits the history (no fit spans it): Olsen's (2012) gap
  // fill-in limit of 75 ms, shorter than a blink; 30 Hz with one sample skipped still fits.
  std::int64_t max_gap_ns = 75'000'000;

  // Fixation smoothing: the mean of the fixation's world directions, becoming an exponential
  // average with this time constant once the fixation is older (so a long fixation follows
  // slow drift). Most fixations last 200-300 ms (Rayner 1998), so they are averaged whole; at
  // 120 Hz the steady state averages ~60 samples (0.5 deg noise -> ~0.07 deg).
  std::int64_t fixation_smoothing_tau_ns = 250'000'000;
  // A step in a fixation or a pursuit: the newest samples (25 ms, at least 3) hold still
  // (their scatter within the noise, p = 0.001) and their mean lies apart from the mean of the
  // phase's samples before them (up to dispersion_window, at least as many) by more than this
  // chi-square of 2 degrees of freedom under the noise (the long-run level, or the earlier
  // samples' own spread where larger: the long-run level is learnt), in the world and in the
  // head alike (a carried eye moves only in the world, a reflex-held one only in the head), and
  // the two means fit those samples better than a line by 9 noise variances (a ramp is a
  // pursuit, the dispersion test's case). It is a saccade the velocity test missed (a noisy
  // tracker raises that test's threshold, saccade_significance: at 1.4 deg and 227 Hz to ~130
  // deg/s, above many small saccades; a clean one read once a frame at 120 Hz has three or four
  // samples of a 2-3 deg saccade); a fixation restarts at those samples instead of dragging
  // its mean there at 1/n a sample. Run before the dispersion test, so the jump is not read as
  // a pursuit, and in a pursuit too, so that a jump read as one in flight ends as a fixation
  // once its landing holds still. 16: noise alone passes the first
  // test with p = 3e-4; 9 and 12 (tried, with 25, 40 and off, on the family's tuning seeds,
  // docs/evaluation.md "Scenario family") restarted settled fixations on noise. 0: off.
  double fixation_step_chi2 = 16.0;
  // Exponential smoothing of the pursuit angular velocity on top of the least-squares fit
  // (the fit's slope changes by noise from sample to sample); 50 ms, well under the ~100 ms
  // latency with which pursuit itself follows a change of target velocity (Lisberger, Morris
  // & Tychsen 1987).
  std::int64_t pursuit_velocity_tau_ns = 50'000'000;

  // Prediction at most this far past the newest sample; further, the estimate stops moving.
  // Eye-to-image latencies above ~50-70 ms become visible in foveated rendering anyway
  // (Albert, Patney, Luebke & Kim 2017).
  std::int64_t prediction_horizon_max_ns = 50'000'000;
  // How long after the saccade's end (its landing with post_saccade_from_landing, else its
  // last saccade-labelled sample; in the eye's time) `suppressed` stays on, at the display
  // time. Vision stays suppressed for ~50 ms after a saccade ends (Volkmann 1986; Ross,
  // Morrone, Goldberg & Burr 2001) and display changes up to ~60 ms after one go unnoticed
  // (Loschky & Wolverton 2007); gaze-contingent updates within 50-70 ms of total eye-to-image
  // latency are tolerated (Albert, Patney, Luebke & Kim 2017). 70 ms, with the window from
  // the landing, on seeds 1000-1099 of the scenario family: 50 ms left 74 seeds within the
  // triangle target against 80, 90 ms 88 within the switch target against 94
  // (docs/evaluation.md, "Scenario family", item 11).
  std::int64_t post_saccade_suppression_ns = 70'000'000;
  // Count post_saccade_suppression_ns from the saccade's landing: walking back from the
  // newest sample while each older one lies within the noise of the newer ones' mean, in the
  // world or in the head. The last saccade-labelled sample comes 20-45 ms after the landing
  // (the velocity fit's window must first let the flight out), and a window counted from it
  // took coarsenings 90-115 ms after the landing, when vision was back, for hidden.
  bool post_saccade_from_landing = true;
  // End a saccade as soon as its newest samples (25 ms, at least 3 over 15 ms) hold still in
  // the world or in the head: no slope through them above the velocity test's own threshold,
  // their scatter within the noise (p = 0.001). The next velocity fit then starts at the
  // landing and needs a whole velocity_window. Without it a saccade ends when the velocity
  // fit's window has let most of the flight out.
  bool saccade_ends_at_landing = true;
  // A movement above the saccade threshold that lasts longer than this is no saccade: saccades
  // last ~2.2 ms/deg * A + 21 ms (Carpenter 1988), under 130 ms even for 50 deg. It is a smooth
  // gaze shift at saccadic speed (the eyes carried by a fast head turn, or a very fast
  // pursuit) and is classified as pursuit, with its velocity, not suppressed.
  std::int64_t max_saccade_ns = 150'000'000;
  // Invalid samples (blink, loss) hold the last estimate, suppressed (blink suppression:
  // Volkmann, Riggs & Moore 1980), for at most this long after the last valid sample; then
  // valid = false. Spontaneous blinks close the lid for ~100-300 ms (Caffier, Erdmann &
  // Ullsperger 2003). A source that stops sending (frozen) also ends valid after this.
  std::int64_t loss_hold_max_ns = 300'000'000;

  // Uncertainty growth with the age of the estimate (display time - sample time), deg/s: the
  // mean rate at which gaze moves, saccades included: ~3-4 fixations a second (Rayner 1998)
  // joined by saccades mostly under 15 deg and typically ~5 deg (Bahill, Adler & Stark 1975),
  // i.e. 10-20 deg/s. 10 was chosen from 10 and 15 with scripts/tune_family.py on the
  // scenario family's tuning seeds (docs/evaluation.md, "Scenario family"; a 0.1 % difference).
  double age_growth_deg_s = 10.0;
  // Relative error assumed for the pursuit velocity when predicting: a margin over the fit's
  // measured ~5-10% (tests/gaze/gaze_conditioner_test.cpp) for velocity changes within the
  // horizon (chosen here, as in the earlier GazePredictor).
  double velocity_error_fraction = 0.25;
  // In a saccade, centre the estimate on the newest sample (where the eye last was, nearer the
  // landing) with the distance it may still travel (speed x age) as the speed term, rather
  // than holding the estimate from before the saccade widened by the whole distance travelled.
  // Measured with gazelod eval family on the tuning seeds (1000-1039): the held, widened cone
  // refined every object within the saccade's amplitude of its start and coarsened them again
  // after it, mostly outside the true suppression with a late tracker (switches p90 1.14 ->
  // 0.86 per object-second, median triangles / oracle 1.26 -> 1.23, degradations unchanged).
  bool saccade_follow_newest = true;
  // ... and put that cone over the path ahead: the eye goes on along the saccade's direction
  // (saccades are nearly straight and do not turn back), so the landing lies between the
  // newest sample and the distance d it may still travel. The cone is centred d/2 ahead with
  // radius (1 + saccade_path_margin) d / 2 instead of d around the newest sample. A smaller
  // cone refines fewer objects in flight that must coarsen after the landing (with a late
  // tracker, outside the true suppression, or held through the next fixation). Measured with
  // gazelod eval family (docs/evaluation.md, "Scenario family", item 7).
  bool saccade_cone_ahead = true;
  // The margin for a curved path or an overshoot, as a fraction of d. Chosen with
  // saccade_ends_at_landing from 0, 0.25, 0.5 and 0.75 on seeds 1000-1099 (docs/evaluation.md,
  // "Scenario family", item 11): 0 brought the worst seed's degradations to 0.47 %, near the
  // 0.5 % target. (Before saccades ended at their landing, the cone had to last through the
  // velocity fit's lag, and 0.6 and below let the worst tuning seed reach 0.5 %: item 7.)
  double saccade_path_margin = 0.25;
  // Cap: the eye-in-head oculomotor range is about +-50 deg (Guitton & Volle 1987), so
  // beyond that the estimate carries no information.
  double max_uncertainty_deg = 50.0;
  // A sample stamped this far after the latest display time asked for is refused as bad (a
  // corrupt clock would otherwise make every later sample look backwards).
  std::int64_t max_sample_lead_ns = aux::ns_from_seconds(1.0);
};

// "" when every setting is usable, else the first bad one (in declaration order) by name, with
// its value and the rule: "pursuit_exit_fraction must be in [0, 1], got 1.5". Times and
// thresholds must be finite and >= 0 (windows, thresholds, the gap and the lead > 0),
// max_uncertainty_deg >= accuracy_deg.
[[nodiscard]] std::string validate_conditioner_config(const ConditionerConfig& config);

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
