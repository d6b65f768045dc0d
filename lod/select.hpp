// SPDX-License-Identifier: Apache-2.0
// Per-object LOD selection with Reddy's acuity model (Reddy 1998 sections 3.2, 3.4, 6): for each
// object, the least detailed level whose removed detail lies above the acuity limit.
//
// API (plain data in, caller-owned arrays out, no allocation):
//   Viewer viewer{...};                       // one per frame: eye, gaze, head motion, xi, s
//   ObjectSet objects = store.view();         // structure of arrays (lod/object_set.hpp)
//   Decisions out{lod, limited_by, size_only, ecc_only, vel_only};  // spans of n bytes
//   std::string err = select_lods(viewer, objects, out);           // "" on success
//
// A level k >= 1 with weight w_k (lod/object_set.hpp) removes detail of a size s_k (m) seen
// from the bounding sphere's nearest point, d_near = max(d - r, kNearestPointFloorM)
// (lod/lod_chain.hpp), at f_k = 1 / (2 (s_k / d_near) deg) cycles/deg:
//   removed cycles per diameter c: s = r / c, f = c / (2 (r / d_near) deg)  (Reddy 1998's
//                                 c / (2 alpha_deg) for d >> r, alpha the angular radius)
//   geometric error e (m):        s = e
// (small-angle: over-states the angle, so it errs towards keeping detail). The nearest point,
// not the centre or the angular radius: a large object the viewer stands in or next to shows
// its error at its near side (inside the sphere no level goes by size), as a cluster does
// (lod/cluster/cluster_select.hpp).
// and may be used when f_k > A = s * min(G(v) M(E), xi). E is the nearest point's eccentricity
// minus the tracker's error, v the retinal velocity (their scalar forms, the tests'
// reference: tests/lod/reference_criteria.hpp). The vectorised kernels
// (lod/select_kernel*.cpp) evaluate the same rule on squared quantities to avoid roots and
// divisions per level, and make the last comparison w_k^2 > (A p)^2 in float with each side
// rounded once: where the two sides lie within 6e-8 of each other that can keep a finer
// level than the exact rule, never a coarser one. The tests compare them with a direct
// reference in double.
// Switching a criterion off zeroes its input (Reddy 1998 section 6): E = 0, v = 0, and for size
// the object counts as no smaller than the size at which level 1 sits exactly at the foveal,
// static limit s * min(60, xi) (so size alone never drops a level). Switching off never lowers
// detail. Per object the output says the chosen level, which criterion set it, and the level
// each criterion alone would allow (the other two off).
// Validation: select_lods refuses an invalid Viewer or mismatched array lengths with a
// message (outputs untouched). A non-finite object (NaN centre, chain out of range) gets
// level 0 and Criterion::invalid_input; no NaN and no out-of-range level ever leaves.
#pragma once

#include "lod/criterion.hpp"
#include "lod/object_set.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>

namespace gazelod::lod {

struct Viewer {
  glm::dvec3 eye_position_m{0.0};
  glm::dvec3 eye_velocity_m_s{0.0};             // head translation
  glm::dvec3 gaze_direction{0.0, 0.0, -1.0};    // world, non-zero (normalised here)
  glm::dvec3 head_angular_velocity_rad_s{0.0};  // world axes
  // Eye-in-head rotation from the tracker (world axes); 0 without one (gaze fixed in head).
  glm::dvec3 gaze_angular_velocity_in_head_rad_s{0.0};
  double xi_cpd = 60.0;            // display limit, lod/display.hpp
  double tracker_error_deg = 0.0;  // inflates the foveal region: E -= error
  double scale = 1.0;              // Reddy's global s in (0, 1]
  bool use_size = true;
  bool use_eccentricity = true;
  bool use_velocity = true;
};

// "" when valid, else which field and why.
[[nodiscard]] std::string validate_viewer(const Viewer& viewer);

struct Decisions {
  std::span<std::uint8_t> lod;
  std::span<std::uint8_t> limited_by;  // Criterion
  std::span<std::uint8_t> lod_size_only;
  std::span<std::uint8_t> lod_eccentricity_only;
  std::span<std::uint8_t> lod_velocity_only;
  // Optional diagnostics (leave empty to skip): E after tracker error, v, angular radius.
  std::span<float> ecc_deg;
  std::span<float> vel_dps;
  std::span<float> angular_radius_deg;
};

// Thresholds and frame constants computed once per frame from a valid Viewer.
struct FrameConstants {
  glm::dvec3 eye{0.0}, eye_vel{0.0}, gaze_unit{0.0, 0.0, -1.0}, gaze_omega{0.0};
  double xi_cpd = 60.0, scale = 1.0, tracker_error_rad = 0.0;
  double acuity_static_cpd = 60.0;  // s * min(60, xi): size alone
  bool use_size = true, use_eccentricity = true, use_velocity = true;
};
FrameConstants prepare_frame(const Viewer& viewer);  // viewer must be valid

[[nodiscard]] std::string select_lods(const Viewer& viewer, const ObjectSet& objects, const Decisions& out);

}  // namespace gazelod::lod
