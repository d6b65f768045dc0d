// Benefit of drawing an object at one level of detail, in Funkhouser & Sequin's product form
// (1993 sec. 5): Size x Accuracy x Importance x Focus x Motion x Hysteresis. Focus and motion
// come from the perceptual model (Reddy 1998): the caller gives the acuity limit at the object
// (cycles/deg, already lowered for eccentricity and motion) and each level's removed detail;
// a level whose removed detail lies above the limit loses nothing.
#pragma once

namespace gazelod::lod {

struct BenefitInputs {
  double size_px = 0.0;          // projected area in pixels (F&S: the base value)
  double importance = 1.0;       // semantic importance in [0, 1]
  // Accuracy (F&S eq. in sec. 5): 1 - base_error / samples^m, samples = vertices (Gouraud,
  // m = 2) or polygons (flat, m = 1), never more than the pixels covered.
  double samples = 0.0;          // of this level; 0: the level draws nothing
  double full_samples = 0.0;     // of the full-detail level
  double interpolation_m = 2.0;
  double base_error = 0.5;
  // Perception: highest visible frequency at the object, and the highest frequency this level
  // removes (0 for full detail; coarser levels remove lower frequencies).
  double acuity_limit_cpd = 0.0;
  double removed_detail_cpd = 0.0;
  // Hysteresis: levels between this one and last frame's, and the penalty per level.
  double level_change = 0.0;
  double hysteresis_per_level = 0.1;
};

// F&S accuracy, in [0, 1): 0 when nothing is drawn.
double fs_accuracy(double samples, double pixels, double interpolation_m, double base_error);

// Visible share in [0, 1] of what a level removes: 1 - removed/limit, 0 at or above the limit
// (invisible), 1 when the level removes everything (removed detail 0 cpd) or the acuity limit is
// unknown/invalid would be unsafe, so a limit <= 0 counts as "nothing visible".
double visible_loss_share(double acuity_limit_cpd, double removed_detail_cpd);

// Hysteresis factor in [0, 1]: 1 - per_level * |level_change|.
double hysteresis_factor(double level_change, double per_level);

// The product. Perceived accuracy = A_full - (A_full - A_level) * visible_loss_share.
double benefit(const BenefitInputs& in);

}  // namespace gazelod::lod
