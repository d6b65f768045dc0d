// The vectorised parts of select_lods (lod/select.cpp), per block of objects, on
// block-local arrays:
//   phase 1, select_kernel_geometry: E, v^2, alpha, the threshold factors p^2, 1 / M(E)
//            and G(v) of every object (straight-line arithmetic, no branch);
//   phase 2, select_kernel_levels: per object and criterion, how many coarser levels
//            clear the acuity limit, and which criterion limits the combined choice.
// Between the two, select_kernel_rows_regular (or select.cpp, object by object, for other
// layouts) gathers the levels' squared weights into rows; select.cpp handles what the fast
// path leaves out (chains out of range, chains longer than kRowLevels + 1 levels).
//
// Why split: a data-dependent trip count, gathers and byte-wide data keep GCC from
// vectorising; the phases avoid all three. Each is compiled for baseline x86-64, x86-64-v3
// (AVX2 + FMA) and x86-64-v4 (AVX-512) and picked at load time (GCC target_clones, an
// ifunc), so the portable build still uses the wide units where the CPU has them.
//
// Thresholds: level k (weight w_k, lod/object_set.hpp) is allowed by a criterion with acuity
// limit A when f_k = w_k / p > A, i.e. w_k > A p, with p = 1 / q the degrees per cycle per
// unit weight: p = 2 alpha_deg (removed cycles per diameter) or 360 / (pi d) (geometric
// error; +inf at d = 0, where no level is ever allowed). Both sides are >= 0, so the
// comparison is done squared, w_k^2 > A^2 p^2: p^2 = 1 / d^2 needs no square root. For the
// limits that contain M(E) both sides are multiplied by 1 / M: A / M = s min(G, xi / M).
// No division per object or level after phase 1.
#pragma once

#include "lod/lod_chain.hpp"

#include <cstddef>
#include <cstdint>

namespace gazelod::lod::detail {

inline constexpr std::size_t kSelectBlock = 128;  // objects per block: arrays stay in L1
inline constexpr std::size_t kRowLevels = 7;      // coarser levels handled by phase 2

// Frame constants, already derived from a valid Viewer (plain doubles: no glm in the kernel,
// so nothing hides a call).
struct KernelFrame {
  double eye_m[3], eye_vel_m_s[3], gaze_unit[3], gaze_omega_rad_s[3];
  double tracker_error_rad;
  double xi_cpd, scale;
  double vel_zero_dps;       // where G reaches 0
  double acuity_static_cpd;  // s min(60, xi): size alone
  bool use_size, use_eccentricity, use_velocity;
  bool diagnostics;  // phase 1 stores ecc_deg, vel2_dps2 and alpha_deg (else unspecified)
};

// Structure-of-arrays input, indexed [begin, begin + count). vel_* all null: static objects.
struct KernelInput {
  const double *center_x_m, *center_y_m, *center_z_m, *radius_m;
  const double *vel_x_m_s, *vel_y_m_s, *vel_z_m_s;
};

struct KernelBlock {
  // Phase 1 (geometry). An object with non-finite data or a negative radius has
  // p2_cycles = p2_error = +inf (every threshold +inf: no level; p2_cycles = +inf is the flag
  // for Criterion::invalid_input, never a valid value), ecc_deg, vel2_dps2 and alpha_deg 0,
  // and inv_m and g_cpd unspecified (unused).
  double ecc_deg[kSelectBlock];       // nearest point's eccentricity minus tracker error, >= 0
  double vel2_dps2[kSelectBlock];     // retinal velocity squared, >= 0 (may be +inf)
  double alpha_deg[kSelectBlock];     // angular radius, [0, 90]
  double p2_cycles[kSelectBlock];     // (2 alpha_deg)^2, <= 180^2
  double p2_error[kSelectBlock];      // (360 / (pi d))^2, +inf at d = 0
  double inv_m[kSelectBlock];         // 1 / M(E) >= 1 (1 with eccentricity switched off)
  double g_cpd[kSelectBlock];         // G(v) in [0, 60] (60 with velocity switched off)
  // Filled before phase 2 (select_kernel_rows_regular or select.cpp): non-zero for a
  // geometric-error chain, else 0; row k - 1 holds each object's w_k^2 rounded to float, 0
  // past the end of its chain (0 is never above a threshold).
  double kind_error[kSelectBlock];
  float weight[kRowLevels][kSelectBlock];
  // Phase 2 (levels): each criterion's squared threshold A^2 p^2 rounded to float (NaN or
  // +inf where nothing is allowed), and 1 for an invalid object, else 0.
  float t_size[kSelectBlock], t_ecc[kSelectBlock], t_vel[kSelectBlock], t_comb[kSelectBlock];
  float invalid[kSelectBlock];
};

// Phase 1 for objects [begin, begin + count) into out[0, count); count <= kSelectBlock.
void select_kernel_geometry(const KernelFrame& frame, const KernelInput& in, std::size_t begin,
                            std::size_t count, KernelBlock& out);

// Each object's chain (lod/object_set.hpp), for filling the rows.
struct ChainInput {
  const std::uint32_t* lod_first;
  const std::uint8_t* lod_count;
  const DetailKind* detail_kind;
  const double* level_weight;
  std::size_t n_weights;
};

// Fills kind_error and the weight rows for objects [begin, begin + count) when their chains
// lie back to back with one length of 1 .. kRowLevels + 1 levels (ObjectStore's layout for
// uniform chains) and returns the row count; returns 0, filling nothing, otherwise (then
// select.cpp fills them object by object).
std::size_t select_kernel_rows_regular(const ChainInput& in, std::size_t begin, std::size_t count,
                                       KernelBlock& blk);

// Where phase 2 writes the block's decisions (select.hpp's Decisions, offset to the block).
struct LevelOutput {
  std::uint8_t *lod, *limited_by, *size_only, *eccentricity_only, *velocity_only;
};

// Phase 2 over blk[0, count), rows 0 .. rows - 1 of weight (1 <= rows <= kRowLevels; row 0
// is read even where no chain has a coarser level, so it must be filled).
void select_kernel_levels(const KernelFrame& frame, std::size_t count, std::size_t rows,
                          KernelBlock& blk, const LevelOutput& out);

}  // namespace gazelod::lod::detail
