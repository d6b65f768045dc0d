// SPDX-License-Identifier: Apache-2.0
// Per-cluster LOD selection: Reddy's rule (lod/select.hpp) applied to every cluster of a
// cluster hierarchy (lod/cluster/cluster_hierarchy.hpp; Karis et al. 2021), so that detail follows
// the fovea across one mesh instead of one level for all of it.
//
// API (plain data in, caller-owned arrays out, no allocation, no hidden state):
//   ClusterStore store;                                // lod/cluster/cluster_select_store.hpp
//   store.add_mesh(hierarchy, pose, velocity, index_count);  // validates it (throws if bad)
//   ClusterDecisions out{drawn, limited_by};           // caller-owned spans of n bytes
//   std::string err = select_clusters(viewer, store.view(), out);  // per frame, "" on success
//   draw cluster i when drawn[i] == 1.
//   With out.record_flags (store.record_count() words of scratch) each distinct record is
//   evaluated once (ClusterSet::record_*), the faster path; without, two records per cluster.
// (A ClusterSet assembled otherwise: validate_clusters once at registration.) Per frame: no
// allocation, about 40 KiB of stack, linear time.
//
// The rule, per record (a bounds sphere c, rho and an error e in metres, world space):
//   d  = max(|c - eye| - rho, kNearFloorM)    nearest point of the sphere (floored: inside it
//                                             the record is seen from 1 um, so size drops no
//                                             visible error there);
//   E  = max(0, angle(gaze, c) - asin(rho / |c - eye|) - tracker error)   the sphere's nearest
//        point's eccentricity (0 inside the sphere), as select_lods;
//   v  = max(0, v(c) - rho (2 |V| / d + |w|) / d)   the retinal velocity of select_lods at the
//        centre, lowered by a bound on how much slower any point of the sphere moves (V the
//        mesh's velocity relative to the eye, w the gaze's rotation): the slowest point's speed,
//        bounded below; 0 where d is at the floor;
//   f  = 1 / (2 (e / d) deg) = d pi / (360 e)   the removed frequency of select.hpp's geometric
//        error;
//   the error is invisible when f > A = s min(G(v) M(E), xi): e = 0 always is, e = +inf
//   (kNoParentError) never is.
// A cluster is drawn when its self record is invisible and its parent record is not.
//
// Why the cut is consistent (every source triangle drawn exactly once): all clusters of a
// group share the group's record (as their parent; the clusters a group produced share it as
// their self), so they see identical inputs and make identical decisions about it; the kernel
// rounds every lane identically (cluster_select_kernel.hpp), so that holds bit for bit. And
// each term above is monotone under the hierarchy's nesting (self error <= parent error, parent
// sphere containing the self sphere): a containing sphere has a nearer nearest point, a nearer
// nearest-point eccentricity and (the reason v is bounded over the sphere, not taken at its
// centre) no faster slowest point, so a parent record invisible implies its children's records
// invisible, and along any leaf's ancestor path the invisible records form a prefix. (With v
// at the centre, a parent whose centre moves more slowly on the retina than a child's could be
// visible above an invisible child: two clusters drawn over one leaf.)
//
// Criteria: switching one off as select_lods does (E = 0, v = 0; size off: each mesh counts as
// no nearer than the distance at which its finest error sits at the static limit
// s min(60, xi), mesh_finest_error_m). limited_by says, for a drawn cluster, which criterion
// lets its self error go (size, eccentricity, velocity or only combined, by
// lod::limiting_criterion; Criterion::none for a source cluster, error 0, and for every cluster
// not drawn); the optional per-criterion outputs are the cut each criterion alone would draw (a
// switched-off one: the finest cut).
// Precision: the kernel works in float and errs towards keeping detail (a record it calls
// invisible is invisible under the exact rule in double; within ~1e-5 relative of a threshold
// it may keep a finer cluster).
// Moving meshes: mesh_vel_* is each mesh's world velocity (like ObjectSet's); its rotation is
// not modelled. Positions are current world positions: ClusterStore::set_pose re-transforms a
// mesh's clusters when it moves.
#pragma once

#include "lod/criterion.hpp"
#include "lod/select.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace gazelod::lod {

// The records of one or many meshes' clusters, world space, one entry per cluster (the fields
// of lod/cluster/cluster_hierarchy.hpp after the instance transform), and the meshes they belong to.
struct ClusterSet {
  std::span<const float> self_center_x_m, self_center_y_m, self_center_z_m, self_radius_m, self_error_m;
  std::span<const float> parent_center_x_m, parent_center_y_m, parent_center_z_m, parent_radius_m, parent_error_m;
  // Mesh m owns clusters [mesh_first_cluster[m], + mesh_cluster_count[m]); the meshes lie back
  // to back from cluster 0 and cover every cluster.
  std::span<const std::uint32_t> mesh_first_cluster, mesh_cluster_count;
  // Per mesh world velocity; all three empty: every mesh is static.
  std::span<const double> mesh_vel_x_m_s, mesh_vel_y_m_s, mesh_vel_z_m_s;
  // Per mesh: > 0 and no larger than any positive error of its records (finest_cluster_error_m;
  // +inf allowed where it has none finite); sets the size-off distance.
  std::span<const double> mesh_finest_error_m;

  // Optional, all or none (ClusterStore fills them): the set's distinct records, each mesh's
  // back to back (mesh m's are [mesh_first_record[m], + mesh_record_count[m])), and per cluster
  // the index of its self and of its parent record among them, whose fields equal the cluster's
  // own bit for bit (validate_clusters checks; at most 2^31 - 1 records per mesh). With them and
  // ClusterDecisions::record_flags, select_clusters evaluates each distinct record once (a
  // group's record is shared by its members and by the clusters it produced) instead of twice
  // per cluster; every output is the same.
  std::span<const float> record_center_x_m, record_center_y_m, record_center_z_m, record_radius_m, record_error_m;
  std::span<const std::uint32_t> self_record, parent_record;
  std::span<const std::uint32_t> mesh_first_record, mesh_record_count;
  // (Last, so positional initialisers of the fields above still work.) Optional, empty or one per mesh: the mesh's
  // detail scale s in [1, 1e6] (empty: 1 for every mesh, the perceptual cut). s divides every error of the mesh before
  // the rule, so the mesh's cut coarsens as if the largest invisible error at each point were s times larger: a frame
  // budget's coarsening steps (budget/cluster_cut_cost.hpp). A larger s never draws a finer
  // cluster; the cut stays consistent (the errors keep their nesting).
  std::span<const double> mesh_detail_scale;

  std::size_t size() const { return self_error_m.size(); }
  std::size_t mesh_count() const { return mesh_cluster_count.size(); }
  std::size_t record_count() const { return record_error_m.size(); }
  bool has_records() const { return !record_error_m.empty() || !self_record.empty() || !mesh_first_record.empty(); }
};

struct ClusterDecisions {
  std::span<std::uint8_t> drawn;       // 1: in the cut, else 0
  std::span<std::uint8_t> limited_by;  // Criterion (invalid_input: bad data, not drawn)
  // Optional, all three or none: the cut under each criterion alone.
  std::span<std::uint8_t> drawn_size_only, drawn_eccentricity_only, drawn_velocity_only;
  // Optional: bit 0 the self error, bit 1 the parent error invisible under the combined rule
  // (the input of apply_cluster_switch_policy, lod/cluster/cluster_switch_policy.hpp). Without the
  // per-criterion outputs, a self record under an invisible parent is set, not evaluated (the
  // nesting implies it); with them, every record's bits are those of its full evaluation.
  std::span<std::uint8_t> record_invisible;
  // Optional scratch, at least one word per distinct record (ClusterSet::record_count; shorter
  // is refused): given for a set that has its distinct records, each of them is evaluated once
  // into it (afterwards it holds their outcomes, a bit per criterion: not an interface); for a
  // set without them it is not used.
  std::span<std::uint32_t> record_flags;
};

// The smallest positive error among the records (+inf if there is none finite): a mesh's
// mesh_finest_error_m.
double finest_cluster_error_m(std::span<const float> self_error_m, std::span<const float> parent_error_m);

// "" when detail_scale is empty or holds one value in [1, 1e6] per mesh, else the first bad one
// (select_clusters checks this per frame: linear in the meshes, no allocation when "").
[[nodiscard]] std::string check_detail_scales(std::span<const double> detail_scale, std::size_t meshes);

// "" when the set is consistent, else a message naming the first bad cluster (or mesh) and
// field: span lengths, finite centres, radii and errors >= 0 (parent error +inf allowed), self
// error <= parent error, the parent sphere containing the self sphere (to float rounding) where
// the parent error is finite, mesh ranges back to back over all clusters, finite velocities,
// mesh_finest_error_m as above; with distinct records, their ranges back to back over all of
// them and every cluster's two indices inside its mesh's range, on records equal to its own. Linear time: run it at
// registration, not per frame.
[[nodiscard]] std::string validate_clusters(const ClusterSet& clusters);

// One frame. Refuses an invalid Viewer, spans of the wrong length or mesh ranges that do not
// tile the clusters with a message (outputs untouched). Data that validate_clusters would
// refuse (not checked per frame) never yields NaN or a byte out of range: a cluster with a
// non-finite or negative field is not drawn and gets Criterion::invalid_input.
[[nodiscard]] std::string select_clusters(const Viewer& viewer, const ClusterSet& clusters,
                                          const ClusterDecisions& out);

}  // namespace gazelod::lod
