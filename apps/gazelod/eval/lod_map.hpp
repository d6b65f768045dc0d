// SPDX-License-Identifier: Apache-2.0
// The LOD-map thesis's policy (an acuity map plus a saliency map), an alternative to
// Reddy's thresholds (lod/select.hpp). Each object gets a detail value in [0, 1] from a weighted
// sum of criterion scores, each score in [0, 1] (1 = wants full detail):
//   size          projected angular radius / size_full_deg, clamped (thesis 3.2.2: the radius
//                 of the projected bounding sphere; the normalisation is ours, see below)
//   colour        1 when fewer than colour_salient_fraction of the objects share its colour
//                 group (thesis 3.2.4), else 0; not used when the scene has no colours
//   eccentricity  M(E) = 1 / (1 + 0.29 E) (thesis equation 4, M0 = 1)
//   motion        rises linearly to 1 at motion_peak_deg_s (20 deg/s), then falls linearly to
//                 0 at motion_max_deg_s (80 deg/s, Daly's maximum tracking speed) (3.2.3/3.3.1)
// with the study's weights (thesis 4.1.1): size 30%, colour 30%, eccentricity 14%,
// velocity/motion 26%. Weights of criteria that are not used are dropped and the rest
// renormalised to sum to 1. Detail d maps to a level uniformly along the chain:
// level = round((1 - d) (levels - 1)), so d = 1 is level 0 and d = 0 the coarsest.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace gazelod::lod {

struct LodMapWeights {
  double size = 0.30;
  double colour = 0.30;
  double eccentricity = 0.14;
  double motion = 0.26;
};

struct LodMapParams {
  LodMapWeights weights;
  double size_full_deg = 5.0;  // angular radius that scores 1 (our choice: the thesis
                               // leaves the pixel-size normalisation open)
  double motion_peak_deg_s = 20.0;
  double motion_max_deg_s = 80.0;
  double colour_salient_fraction = 0.20;
};

struct LodMapInput {
  double angular_radius_deg = 0.0;  // >= 0
  double eccentricity_deg = 0.0;    // >= 0, from the gaze
  double speed_deg_s = 0.0;         // >= 0, across the retina / screen
  int colour_group = -1;            // -1: no colour information
};

// Criterion scores, each clamped to [0, 1]; non-finite or negative inputs score as the
// least salient value (0 for size/motion, eccentricity treated as infinite -> 0).
double lod_map_size_score(double angular_radius_deg, const LodMapParams& p);
double lod_map_eccentricity_score(double eccentricity_deg);
double lod_map_motion_score(double speed_deg_s, const LodMapParams& p);

// Detail in [0, 1] of one object; `colour_salient` is ignored when `use_colour` is false.
double lod_map_detail(const LodMapInput& in, bool use_colour, bool colour_salient, const LodMapParams& p);

// Level in [0, levels - 1] for a detail value (levels >= 1; NaN gives level 0).
std::uint8_t lod_map_level(double detail, std::uint8_t levels);

// The whole map: colour salience from the groups (used only if some object has a group),
// then one level per object. Returns "" or a message on mismatched span sizes / params.
std::string lod_map_select(std::span<const LodMapInput> objects, std::span<const std::uint8_t> level_counts,
                           const LodMapParams& p, std::span<std::uint8_t> out_levels);

}  // namespace gazelod::lod
