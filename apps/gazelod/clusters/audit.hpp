// SPDX-License-Identifier: Apache-2.0
// The visibility audit of `gazelod run` for cluster meshes (run/audit.hpp is the one for
// objects; the same suppression windows and the same truth). Per frame an oracle cut is
// selected with lod::select_clusters at the TRUE eye state (the per-object oracle's viewer:
// true head pose and gaze, tracker error 0, the run's xi and criteria) over a ClusterStore of
// the same hierarchies and poses, with no switch policy: the perceptual cut at the true gaze,
// which the plugin never sees. Then, per leaf (source cluster) whose self sphere is in view:
//   degraded  the coarsest drawn cluster over the leaf (clusters/cover.hpp) has a larger
//             self error than the oracle's cluster over it: drawn coarser than the true gaze
//             allows (a finding only outside suppression, as for objects);
//   switch    the cluster over the leaf differs from the previous frame's;
// and the triangles of the drawn and the oracle's clusters whose self sphere is in view, and of
// the oracle's cut under each criterion alone (lod::select_clusters' per-criterion cuts, at the
// same true eye state: what size, eccentricity and velocity each buy on the run's display). Every
// frame also checks the drawn cut of each mesh: leaves not covered exactly once (cracks or
// overlaps; the plugin promises none) are counted over all leaves.
#pragma once

#include "apps/gazelod/clusters/cover.hpp"
#include "apps/gazelod/clusters/scene.hpp"
#include "lod/display.hpp"
#include "lod/select.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace gazelod::cli {

// One frame's cluster audit (all zero when `available` is false).
struct ClusterAuditFrame {
  bool available = false;
  bool suppressed = false;
  std::int64_t leaves_in_view = 0;
  std::int64_t degraded = 0;       // in-view leaves drawn coarser than the oracle's cut
  std::uint64_t excess_depth = 0;  // over those: depth of the drawn cluster over the leaf minus the oracle's (>= 0)
  std::uint32_t excess_depth_max = 0;
  std::uint64_t drawn_triangles = 0;  // in view (self sphere), per eye
  std::uint64_t oracle_triangles = 0;
  // The oracle's cut under size / eccentricity / velocity alone, in view, per eye.
  std::uint64_t oracle_size_only_triangles = 0, oracle_eccentricity_only_triangles = 0,
                oracle_velocity_only_triangles = 0;
  std::int64_t switches = 0;    // in-view leaves whose cluster changed since the previous frame
  double leaf_s = 0.0;          // in-view leaves x the time since the previous frame
  std::int64_t miscovered = 0;  // leaves (in view or not) not covered exactly once by the drawn cut
};

// Per leaf, both cuts' covers (clusters/cover.hpp) and what the counting needs.
struct ClusterLeafInput {
  std::span<const LeafCover> drawn, oracle;
  std::span<const std::uint32_t> previous;  // the previous frame's drawn cover cluster; empty on the first frame
  std::span<const std::uint8_t> in_view;    // 1: the leaf's self sphere is in view
  std::span<const std::uint8_t> depth_of;   // per cluster of the leaf's mesh: its depth
};

// Adds one mesh's leaves to `f` (degraded, excess, switches, leaves_in_view). Leaves beyond
// the shortest span are ignored. No allocation.
void count_cluster_leaves(const ClusterLeafInput& in, ClusterAuditFrame& f);

class ClusterAuditOracle {
 public:
  // One oracle store over the scene's meshes, one cover graph per mesh (throws
  // std::invalid_argument naming the mesh when either refuses it).
  explicit ClusterAuditOracle(const ClusterScene& scene);

  // One frame. truth: the per-object oracle's viewer (AuditOracle::viewer()); eye_m, head, fov:
  // the true head pose and the display's first view, for "in view"; drawn: the plugin's
  // FrameDecisions::cluster_drawn (the scene's layout). frame_s: time since the previous frame
  // (0 on the first). The frame is not available (and "why" is said in `error`) when the
  // oracle's selection refuses its input or drawn has the wrong length.
  ClusterAuditFrame audit(const lod::Viewer& truth, const glm::dvec3& eye_m, const glm::dquat& head,
                          const lod::FovRad& fov, std::span<const std::uint8_t> drawn, bool suppressed, double frame_s,
                          std::string* error = nullptr);

  std::span<const std::uint8_t> oracle_drawn() const { return oracle_drawn_; }

  // Mesh `mesh` (the scene's order) moved: the same pose and velocity the plugin got. Throws
  // std::invalid_argument or std::out_of_range as lod::ClusterStore::set_pose.
  void set_pose(std::size_t mesh, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s);

 private:
  lod::ClusterStore store_;
  std::vector<const lod::ClusterHierarchy*> local_;  // per mesh: its own space (the scene's)
  std::vector<ClusterCover> covers_;                 // per mesh
  std::vector<std::uint32_t> first_, count_;         // per mesh: clusters
  std::vector<std::uint32_t> leaf_first_;            // per mesh: into the per-leaf arrays
  std::vector<std::uint32_t> triangles_;             // per cluster
  std::vector<std::uint8_t> depth_;                  // per cluster
  std::vector<std::uint8_t> oracle_drawn_, limited_, in_view_, leaf_in_view_;
  std::vector<std::uint8_t> size_only_, eccentricity_only_, velocity_only_;  // per cluster
  std::vector<std::uint32_t> record_flags_;            // per distinct record: the selection's scratch
  std::vector<LeafCover> drawn_cover_, oracle_cover_;  // per leaf
  std::vector<std::uint32_t> previous_cover_;          // per leaf
  bool first_frame_ = true;
};

struct ClusterAuditSummary {
  bool available = false;
  std::int64_t frames = 0;
  // Outside suppression windows, over in-view leaf-frames.
  std::int64_t leaf_frames = 0;
  std::int64_t degraded = 0;
  double degraded_share = 0.0;
  double excess_depth_mean = 0.0;  // over the degraded leaf-frames
  std::uint32_t excess_depth_max = 0;
  std::int64_t leaf_frames_suppressed = 0, degraded_suppressed = 0;
  std::uint64_t drawn_triangles = 0, oracle_triangles = 0;
  std::uint64_t oracle_size_only_triangles = 0, oracle_eccentricity_only_triangles = 0,
                oracle_velocity_only_triangles = 0;
  double triangle_ratio = 0.0;  // drawn / oracle (0 when the oracle drew none)
  std::int64_t switches_fixation = 0, switches_suppressed = 0;
  double leaf_s_fixation = 0.0, leaf_s_suppressed = 0.0;
  double switches_per_leaf_s_fixation = 0.0, switches_per_leaf_s_suppressed = 0.0;
  std::int64_t miscovered = 0;  // leaf-frames, all frames
};

ClusterAuditSummary summarize_cluster_audit(std::span<const ClusterAuditFrame> frames);

// The cluster meshes over a run (RunSummary::clusters): the scene's counts, set by the caller,
// and the triangles of every frame's cuts summed (per eye).
// gazelod run --cluster-select gpu (run/gpu_clusters.hpp): the compute pass's selections (one
// per eye and frame), their draw commands and GPU time, and how its cut compared with the
// plugin's, once per frame, cluster by cluster.
struct ClusterGpuSummary {
  bool used = false;
  std::size_t dispatches_per_select = 0;
  // refused: the plugin refused the viewer (or handed out bad detail scales): the CPU's cut drawn
  std::uint64_t selections = 0, selections_refused = 0;
  std::uint64_t commands = 0;  // summed over selections
  std::uint64_t dispatches_timed = 0;
  double dispatch_ms_sum = 0.0, dispatch_ms_max = 0.0;  // timestamp queries
  std::uint64_t frames_compared = 0, decisions_compared = 0, differences = 0;
};

struct ClusterRunSummary {
  std::size_t meshes = 0, clusters = 0, leaves = 0;
  std::uint64_t triangles_drawn = 0;       // the drawn cuts (after the switch policy)
  std::uint64_t triangles_perceptual = 0;  // each frame's perceptual cut
  std::uint64_t triangles_full = 0;        // every mesh at full detail (its leaves)
  ClusterAuditSummary audit;
  ClusterGpuSummary gpu;
};

// frames.csv's cluster columns (a leading comma each): the header's, and one frame's (audit
// cells empty when it is not available).
void write_cluster_csv_header(std::ostream& csv);
void write_cluster_csv_cells(std::ostream& csv, std::uint64_t triangles_drawn, std::uint64_t triangles_perceptual,
                             const ClusterAuditFrame& audit);

// summary.json's "clusters" object ({"meshes": 0} without cluster meshes).
nlohmann::json cluster_run_json(const ClusterRunSummary& s);
// The terminal's "clusters" line: triangles per frame over `frames` frames (nothing without
// cluster meshes).
void print_cluster_run(const ClusterRunSummary& s, std::int64_t frames, std::ostream& out);
// summary.json's clusters.audit object; {"available": false} when no frame was audited.
nlohmann::json cluster_audit_json(const ClusterAuditSummary& s);
// The terminal lines ("cluster audit   ...").
void print_cluster_audit(const ClusterAuditSummary& s, std::ostream& out);

}  // namespace gazelod::cli
