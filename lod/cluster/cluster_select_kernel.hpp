// SPDX-License-Identifier: Apache-2.0
// The vectorised parts of select_clusters (lod/cluster/cluster_select.cpp), per block of clusters:
//   evaluate_records: for one record per cluster (the self or the parent bounds+error), whether
//     its error is invisible under the combined rule and, on request, under each criterion
//     alone (straight-line float arithmetic, no branch). A cheap screen first decides the
//     records that need no eccentricity or velocity (size alone, errors 0 and +inf); the full
//     evaluation runs on the rest, gathered;
//   combine_records: drawn = self invisible and parent not, the limiting criterion, bytes out.
// Each is compiled for baseline x86-64, x86-64-v3 and x86-64-v4 and picked at load time (GCC
// target_clones), like lod/select_kernel.cpp.
//
// Float, not double: 16 lanes per AVX-512 vector, and the records are float already. Every
// rounding is steered towards keeping detail, so a record the kernel calls invisible is
// invisible under the exact rule (tests/lod/reference_cluster_select.cpp, in double):
//   - the nearest-point distance is rounded down (kDistanceLow) and the "inside" test up;
//   - the eccentricity is lowered by kEccentricitySlackRad, the retinal velocity by kVelocitySlack
//     of its terms, G raised by kGSlackCpd (acuity only grows with lower E and v);
//   - thresholds are raised by kThresholdMargin (rounding of the products), frame constants
//     rounded up where they scale a threshold and down where they scale a distance.
// Where the exact rule lies within these slacks of a threshold (about 1e-4 relative, or 1e-4
// cycles/deg) the kernel may keep a finer cluster; never a coarser one.
// The file is compiled with -ffp-contract=off (lod/CMakeLists.txt): then every lane, the
// scalar remainder and every clone's loop round identically, so records shared by a group give
// bit-identical decisions wherever they sit in the arrays (the cut's consistency needs that).
#pragma once

#include "lod/lod_chain.hpp"

#include <cstddef>
#include <cstdint>

namespace gazelod::lod {
struct Viewer;
struct ClusterSet;
}  // namespace gazelod::lod

namespace gazelod::lod::detail {

inline constexpr std::size_t kClusterBlock = 256;  // clusters per block: block arrays stay in L1

// Nearest-point distances are floored here (metres): an eye inside a sphere (or within this of
// it) sees the record from this distance, so no error above kNearFloorM / (K A) ever goes by
// size there (K = 360 / pi; under 1e-8 m at A >= 1 cycle/deg).
inline constexpr float kNearFloorM = static_cast<float>(kNearestPointFloorM);

// Slacks (see above; bounds derived in cluster_select_kernel.cpp, measured by the tests).
inline constexpr float kDistanceLow = 1.0f - 0x1p-20f;     // d = |c - eye| times this
inline constexpr float kEccentricitySlackRad = 4e-6f;      // E lowered by this
inline constexpr float kVelocitySlack = 1e-5f;             // v lowered by this x (|V|/dn + |w|)
inline constexpr float kGSlackCpd = 1e-4f;                 // G raised by this
inline constexpr double kThresholdMargin = 1.0 + 0x1p-16;  // A e K raised by this factor

// Frame constants, from a valid Viewer (cluster_select.cpp), in float.
struct ClusterFrame {
  float eye_hi_m[3], eye_lo_m[3];  // the eye as a float pair: c - eye keeps float precision
  float gaze_unit[3];
  float gaze_omega_rad_s[3], gaze_omega_norm_rad_s;  // |w| rounded up
  float ecc_offset_rad;                              // tracker error + kEccentricitySlackRad, rounded up
  float scale;                                       // s, rounded up
  float scale_xi_cpd;                                // s xi, rounded up
  float static_limit_cpd;                            // a0 = s min(60, xi), rounded up; +inf with size off
  float error_factor;                                // K kThresholdMargin (deg per radian, twice), rounded up
  float on_eccentricity, on_velocity;                // 0 / 1
};

// Per mesh: its velocity relative to the eye, the size-off distance cap (metres) at which
// its finest error sits at the static limit a0 (rounded down; +inf where size is on, for the
// combined rule: cap_combined_m), and the factor its errors are multiplied by.
struct ClusterMeshFrame {
  float rel_vel_m_s[3], rel_speed_m_s;  // |V| rounded up
  float cap_m;                          // for the per-criterion decisions (size off)
  float cap_combined_m;                 // cap_m with size off, +inf with size on
  // K kThresholdMargin / detail_scale, rounded up: ClusterFrame::error_factor, bit for bit, at
  // detail scale 1 (the perceptual cut). A detail scale s >= 1 (a frame budget's coarsening step,
  // budget/cluster_cut_cost.hpp) divides every error of the mesh by s, i.e. multiplies the
  // largest error the acuity rule lets go at each point by s. Every comparison of the kernel is
  // monotone in this factor, so a larger s never makes a record visible that a smaller one
  // calls invisible (coarser steps never draw finer clusters), and the rule with errors e / s is
  // still Reddy's rule on a valid hierarchy (errors divided alike keep their nesting), so the
  // bounding tree's proof of its subtree skipping (cluster_select_bvh.cpp) holds unchanged.
  // (The size-off cap is not divided: with size off the scale coarsens only out to it.)
  float error_factor;
};

// Largest detail scale a mesh may be given: beyond it the factor would leave float's normal range.
inline constexpr double kMaxClusterDetailScale = 1e6;

// The constants select_clusters derives (cluster_select.cpp); viewer valid, mesh < mesh count,
// detail_scale in [1, kMaxClusterDetailScale] (callers check; 1: the perceptual cut).
ClusterFrame make_cluster_frame(const Viewer& viewer);
ClusterMeshFrame make_cluster_mesh_frame(const Viewer& viewer, const ClusterSet& clusters, std::size_t mesh,
                                         double detail_scale = 1.0);

// One record per cluster, structure of arrays, indexed [begin, begin + count).
struct RecordInput {
  const float *center_x_m, *center_y_m, *center_z_m, *radius_m, *error_m;
};

// Per record, 0 or 1 as float (counts in the criterion rule, no mask conversions).
struct RecordBlock {
  float combined[kClusterBlock];  // error invisible under the combined rule
  // Only with all_criteria: invisible under size / eccentricity / velocity alone (a switched-
  // off criterion: only an error of 0), and the error is > 0.
  float size[kClusterBlock], eccentricity[kClusterBlock], velocity[kClusterBlock];
  float positive[kClusterBlock];
  float invalid[kClusterBlock];  // non-finite centre or radius, negative or NaN radius / error
  // Scratch: 1 where the screen left the record to the full evaluation; between its two loops
  // the nearest-point distance (floored), E and v (lowered), in m, deg and deg/s.
  std::int32_t pending[kClusterBlock];
  float near_m[kClusterBlock], ecc_deg[kClusterBlock], vel_dps[kClusterBlock];
};

// How much evaluate_records decides before the full evaluation (which then runs on the records
// left, gathered, or on the whole block where most are left):
//   none:    nothing, every record fully evaluated;
//   trivial: the records whose every output is known without E or v (error 0: invisible under
//            any criterion; error +inf: visible under all; invalid), with every output exactly
//            what the full evaluation gives: for the per-criterion cuts (leaves, error 0, are
//            about half of a hierarchy's clusters);
//   by_size: also the records invisible by size alone (which implies the combined rule). The
//            decisions are the same as the full evaluation's (the combined rule contains the
//            size comparison, computed alike), but the eccentricity and velocity flags of records
//            size decides are then 0: only for callers that need no per-criterion cut
//            (limited_by is size there either way).
enum class RecordScreen { none, trivial, by_size };
// implied_invisible (with a screen; may be null): per record of the block, 1 where the record
// is known to be invisible without evaluating it (the cluster's parent record is invisible, and
// a parent invisible implies its children's records are, cluster_select.hpp): such a record,
// if valid, is invisible and never fully evaluated (its other flags stay the screen's).
void evaluate_records(const ClusterFrame& frame, const ClusterMeshFrame& mesh, const RecordInput& in, std::size_t begin,
                      std::size_t count, bool all_criteria, RecordScreen screen, const float* implied_invisible,
                      RecordBlock& out);

// Distinct records (ClusterSet's record table): evaluated block by block like the per-cluster
// ones, each record's outcomes packed into one word (pack_record_flags: bit 0 combined, 1 size,
// 2 eccentricity, 3 velocity, 4 positive, 5 invalid), then combined per cluster from its two
// records' words (combine_record_flags: combine_records' outputs, the per-criterion ones
// included, bit for bit), so that a record shared by many clusters is evaluated once. Indices
// are clamped to [lo, hi] (the mesh's range: data validate_clusters refuses stays in bounds).
struct ClusterOutput;
void pack_record_flags(std::size_t count, const RecordBlock& in, std::uint32_t* flags);
void combine_record_flags(std::size_t count, const std::uint32_t* flags, const std::uint32_t* self_index,
                          const std::uint32_t* parent_index, std::uint32_t lo, std::uint32_t hi,
                          const ClusterOutput& out);

// Where combine_records writes (cluster_select.hpp's ClusterDecisions, offset to the block);
// the per-criterion pointers all null or all set; record_invisible may be null.
struct ClusterOutput {
  std::uint8_t *drawn, *limited_by;
  std::uint8_t *size_only, *eccentricity_only, *velocity_only;
  std::uint8_t* record_invisible;
};

// self: evaluated with all_criteria; parent: with all_criteria when the per-criterion outputs
// are set.
void combine_records(std::size_t count, const RecordBlock& self, const RecordBlock& parent, const ClusterOutput& out);

}  // namespace gazelod::lod::detail
