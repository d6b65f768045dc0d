// SPDX-License-Identifier: Apache-2.0
// The gaze conditioner's settings (gaze/gaze_conditioner.hpp), each with its source or how it
// was chosen, and the check the conditioner runs on them (gaze/conditioner_config.cpp).
#pragma once

#include "auxiliary/time.hpp"

#include <cstdint>
#include <string>

namespace gazelod::gaze {

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
  // ... and take d as at most this fraction of the path already travelled (from the estimate
  // held before the saccade to the newest sample) plus kSaccadeAheadFloorDeg. speed x age
  // assumes the eye still flies at the fitted speed for the whole age of the sample; with a
  // late tracker that spans most of a saccade, and the cone then refined objects up to tens of
  // degrees ahead that stayed fine after the landing (the switch policy holds a coarsening),
  // while the frames it covered were mostly within the true suppression (a latency after the
  // newest sample, the eye is still in flight or landed less than ~50 ms before). Chosen on
  // seeds 1000-1099 of the scenario family from 0.25, 0.5, 0.75, 1, 2 and off, and at 0.5 with
  // floors of 0 and 2 deg too (docs/evaluation.md, "Scenario family", item 14): 0.5-0.75 gave
  // 86-87 seeds within all three targets against 82 without; 0.25, and the floor alone, let
  // seed 1080 pass 0.5 % degradations. 0: off (not the floor alone).
  double saccade_ahead_of_travelled = 0.5;
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

// The floor of saccade_ahead_of_travelled's cap, deg (the path ahead is the lesser of speed x
// age and the cap): about the tracker's accuracy, so a saccade just detected, with little
// path behind it, still gets a cone over its next samples.
inline constexpr double kSaccadeAheadFloorDeg = 1.0;

}  // namespace gazelod::gaze
