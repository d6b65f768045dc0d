// SPDX-License-Identifier: Apache-2.0
// The vectorised parts of select_lods (lod/select.cpp), per block of objects, on
// block-local arrays:
//   rows,    select_kernel_rows_regular (or select.cpp, object by object, for other
//            layouts): each object's kind and its levels' squared weights, as rows;
//   phase 1, select_kernel_geometry: E, v, alpha, G(v), M(E), the threshold factor p^2 of
//            the object's kind, and each criterion's squared threshold A^2 p^2 (straight-line
//            arithmetic in double, no branch);
//   phase 2, select_kernel_levels: per object and criterion, how many coarser levels
//            clear the threshold, and which criterion limits the combined choice.
// select.cpp handles what the fast path leaves out (chains out of range, chains longer than
// kRowLevels + 1 levels).
//
// Why split: a data-dependent trip count, gathers and byte-wide data keep GCC from
// vectorising; the phases avoid all three. Each is compiled for baseline x86-64, x86-64-v3
// (AVX2 + FMA) and x86-64-v4 (AVX-512) and picked at load time (GCC target_clones, an
// ifunc), so the portable build still uses the wide units where the CPU has them.
//
// Thresholds: level k (weight w_k, lod/object_set.hpp) is allowed by a criterion with acuity
// limit A when f_k = w_k / p > A, i.e. w_k > A p, with p = 1 / q the degrees per cycle per
// unit weight, seen from the bounding sphere's nearest point at d_near = max(d - r,
// kNearestPointFloorM) (lod/lod_chain.hpp): p = 360 r / (pi d_near) (removed cycles per
// diameter: half a cycle is r / c metres) or 360 / (pi d_near) (geometric error). Both sides
// are >= 0, so the comparison is done squared, w_k^2 > A^2 p^2: no division is left per level. Phase 2 compares in
// float: w_k^2 and A^2 p^2 are each rounded to float once, and rounding is monotone, so float(a) > float(b) implies a >
// b; where the two lie within float rounding (6e-8 relative) the float comparison may keep a finer level than the exact
// rule, never a coarser one.
#pragma once

#include "lod/lod_chain.hpp"

#include <cstddef>
#include <cstdint>

namespace gazelod::lod::detail {

// The loops' inputs are the caller's arrays and their outputs block-local: they never overlap,
// but the runtime alias checks would be more than GCC emits, so the loops say so. (Clang, used
// only for the fuzzing builds, gets nothing: its vectorizer is not what those builds are for.)
#if defined(__GNUC__) && !defined(__clang__)
#define GAZELOD_IVDEP _Pragma("GCC ivdep")
#else
#define GAZELOD_IVDEP
#endif

inline constexpr std::size_t kSelectBlock = 128;  // objects per block: arrays stay in L1
inline constexpr std::size_t kRowLevels = 7;      // coarser levels handled by phase 2

// Frame constants, already derived from a valid Viewer (plain doubles: no glm in the kernel,
// so nothing hides a call).
struct KernelFrame {
  double eye_m[3], eye_vel_m_s[3], gaze_unit[3], gaze_omega_rad_s[3];
  double tracker_error_rad;
  double xi_cpd, scale;
  double acuity_static_cpd;  // s min(60, xi): size alone
  bool use_size, use_eccentricity, use_velocity;
  bool diagnostics;  // phase 1 stores ecc_deg, vel2_dps2 and alpha_deg (else unspecified)
};

// Structure-of-arrays input, indexed [begin, begin + count). vel_* all null: static objects.
struct KernelInput {
  const double *center_x_m, *center_y_m, *center_z_m, *radius_m;
  const double *vel_x_m_s, *vel_y_m_s, *vel_z_m_s;
};

// Size switched off (Reddy 1998 section 6): the object counts as no smaller than the size at
// which level 1 sits exactly at the static limit a0, i.e. p >= w_1 / a0. The factor puts the
// floor a few ulps above, so rounding never lets level 1 pass at A = a0 by size-off alone.
inline constexpr double kSizeOffMargin = 1.0 + 4e-15;

// w_1^2 for the size-off floor, from the stored (rounded-down) float weight w_1: taken one
// float step up, so that it is never below the exact w_1^2 and the floor never lower than
// the exact one (a lower floor could let a level pass that the exact rule keeps).
inline double size_off_w1_sq(float w1) {
  const double up = static_cast<double>(w1) * (1.0 + 0x1p-23);  // exact in double
  return up * up;
}

struct KernelBlock {
  // Rows, filled first (select_kernel_rows_regular or select.cpp): kind_error is non-zero
  // for a geometric-error chain, else 0; w1_sq is w_1^2 (0 without a coarser level), for
  // phase 1's size-off floor; row k - 1 holds each object's w_k^2 rounded to float, 0 past
  // the end of its chain (0 is never above a threshold).
  double kind_error[kSelectBlock];
  double w1_sq[kSelectBlock];
  float weight[kRowLevels][kSelectBlock];
  // Phase 1: each criterion's squared threshold A^2 p^2 (+inf, or NaN where A = 0 and
  // p = +inf: nothing passes either way; phase 2 rounds them to float), and 1 for an invalid
  // object (non-finite data or a negative radius: thresholds +inf,
  // Criterion::invalid_input), else 0. Doubles, so that phase 1 has one element width (a
  // float output would make GCC run it 16 objects wide, in twice the registers).
  double t_size[kSelectBlock], t_ecc[kSelectBlock], t_vel[kSelectBlock], t_comb[kSelectBlock];
  double invalid[kSelectBlock];
  // Phase 1's scratch between its two loops: (size per weight / nearest-point distance)^2.
  double near_ratio_sq[kSelectBlock];
  // Phase 1, only with KernelFrame::diagnostics (else unspecified); 0 for an invalid object.
  double ecc_deg[kSelectBlock];    // nearest point's eccentricity minus tracker error, >= 0
  double vel2_dps2[kSelectBlock];  // retinal velocity squared, >= 0 (may be +inf)
  double alpha_deg[kSelectBlock];  // angular radius, [0, 90]
};

// Phase 1 for objects [begin, begin + count) into out[0, count); count <= kSelectBlock.
// The rows (kind_error, w1_sq) must be filled first.
void select_kernel_geometry(const KernelFrame& frame, const KernelInput& in, std::size_t begin, std::size_t count,
                            KernelBlock& out);

// Each object's chain (lod/object_set.hpp), for filling the rows.
struct ChainInput {
  const std::uint32_t* lod_first;
  const std::uint8_t* lod_count;
  const DetailKind* detail_kind;
  const float* level_weight;
  std::size_t n_weights;
};

// Fills kind_error and the weight rows for objects [begin, begin + count) when their chains
// lie back to back with one length of 1 .. kRowLevels + 1 levels (ObjectStore's layout for
// uniform chains) and returns the row count; returns 0, filling nothing, otherwise (then
// select.cpp fills them object by object).
std::size_t select_kernel_rows_regular(const ChainInput& in, std::size_t begin, std::size_t count, KernelBlock& blk);

// Where phase 2 writes the block's decisions (select.hpp's Decisions, offset to the block).
struct LevelOutput {
  std::uint8_t *lod, *limited_by, *size_only, *eccentricity_only, *velocity_only;
};

// Phase 2 over blk[0, count), rows 0 .. rows - 1 of weight (1 <= rows <= kRowLevels).
void select_kernel_levels(const KernelFrame& frame, std::size_t count, std::size_t rows, const KernelBlock& blk,
                          const LevelOutput& out);

}  // namespace gazelod::lod::detail
