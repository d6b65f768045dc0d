// SPDX-License-Identifier: Apache-2.0
// The level that an object's size and motion alone allow this frame, for the switch policy's
// release_by_motion (lod/switch_policy.hpp): select_lods with the eccentricity criterion off.
//
// Why this bound, and what it depends on. With eccentricity off the selection reads neither the
// gaze direction nor the tracker's error (lod/select.hpp: E = 0), so no gaze direction, in the
// tracker's error cone or outside it, makes the level finer: the retinal speed v = |(w_obj -
// w_eye) x c| is taken at the object's own direction c, never at the gaze's. It does depend on
// the eye's rotation w_eye = head + eye-in-head (the conditioner's estimate, 0 in the head for
// a fixation carried by the head): an eye that held a world point while the estimate said
// "carried" would see that point still, and the tracker tells the two apart a latency late.
// EyeHypotheses takes the finest level over other eye rotations too (at rest in the head, at
// rest in the world), so that a level is released only where every one of them blurs it.
// Measured (docs/evaluation.md, "Scenario family"): with the estimate alone the release breaks
// the degradation target; over all three it saves nothing under head sweeps, where the excess
// lies in objects that eccentricity and velocity limit together.
//
// Cost: only the objects the switch policy would hold (perceptual coarser than drawn) are
// gathered and selected, so a frame in which nothing coarsens costs one pass over two byte
// arrays (bench/plugin/bench_plugin.cpp measures begin_frame against select_lods alone).
//
// API: MotionBoundScratch scratch;  (caller-owned, reused: no allocation once it has grown)
//   std::string err = motion_bound_levels(viewer, objects, perceptual, drawn, scratch, out);
#pragma once

#include "lod/object_set.hpp"
#include "lod/select.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gazelod::lod {

// Gathered copies of the candidates' data and the selection's outputs (grown, never shrunk).
struct MotionBoundScratch {
  std::vector<std::uint32_t> index;
  std::vector<double> cx_m, cy_m, cz_m, radius_m, vx_m_s, vy_m_s, vz_m_s;
  std::vector<DetailKind> kind;
  std::vector<std::uint32_t> first;
  std::vector<std::uint8_t> count;
  std::vector<std::uint8_t> lod, limited, size_only, ecc_only, vel_only;
};

// out[i] = the level select_lods allows object i with the eccentricity criterion off, for every
// i with perceptual[i] > drawn[i]; 0 for the others (nothing coarsens there, so it is not read).
// Returns "" or, for an invalid viewer or spans whose lengths differ from the objects', a message,
// writing nothing.
// Eye rotations besides the viewer's estimate whose level out[i] must not exceed either (the
// finest over all is taken: a level every one of these eye motions blurs).
struct EyeHypotheses {
  bool at_rest_in_head = false;   // gaze_angular_velocity_in_head_rad_s = 0 (carried by the head)
  bool at_rest_in_world = false;  // gaze_angular_velocity_in_head_rad_s = -head (the world held still)
};
[[nodiscard]] std::string motion_bound_levels(const Viewer& viewer, const ObjectSet& objects,
                                              std::span<const std::uint8_t> perceptual,
                                              std::span<const std::uint8_t> drawn, MotionBoundScratch& scratch,
                                              std::span<std::uint8_t> out, EyeHypotheses also = {});

}  // namespace gazelod::lod
