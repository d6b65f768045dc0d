// SPDX-License-Identifier: Apache-2.0
// `gazelod eval clusters`' figures and output (the experiment: clusters/eval.hpp): one side
// (per-object LOD or cluster LOD) from its run's summary and frames, and the side-by-side
// table (markdown), clusters.json and clusters.svg (triangles per frame of both).
#pragma once

#include "apps/gazelod/run/report.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::cli {

// The target of the cluster experiment: cluster LOD draws at most a third of the triangles
// per-object LOD draws, with at most 0.5 % visible degradations.
inline constexpr double kClusterTriangleRatioTarget = 1.0 / 3.0;
inline constexpr double kClusterDegradationTarget = 0.005;

// One headless run's figures. Units are objects for per-object LOD and leaf clusters (the
// source mesh's clusters) for cluster LOD.
struct ClusterEvalSide {
  std::int64_t frames = 0;
  double triangles_per_frame = 0.0;       // drawn, mean per frame, per eye
  double full_triangles_per_frame = 0.0;  // everything at full detail
  double drawn_over_oracle = 0.0;         // in view: drawn / what the true gaze needs
  // Drawn in the first eye's view (objects, or clusters, whose sphere is in it: what a renderer
  // culling by sphere submits), mean per frame; the rest is chosen by eccentricity and culled.
  double in_view_triangles_per_frame = 0.0;
  std::int64_t audit_unit_frames = 0;  // object-frames or leaf-cluster-frames outside suppression
  double degraded_share = 0.0;         // of those, drawn coarser than the oracle allows
  double switches_per_unit_s = 0.0;    // outside suppression
  // Cluster runs only (0 otherwise): the oracle's cut in view under size / eccentricity /
  // velocity alone, and under all of them, triangles per frame (what each criterion buys at the
  // true gaze, on the run's display).
  double oracle_in_view_per_frame = 0.0, oracle_size_only_per_frame = 0.0, oracle_eccentricity_only_per_frame = 0.0,
         oracle_velocity_only_per_frame = 0.0;
  std::vector<double> t_s, triangles;  // per frame
};

// The figures of one run (its summary and per-frame records). clusters: the figures of the
// run's cluster meshes; else its objects'. Throws UsageError naming `source` when the run has
// no frames, no audit, or (for clusters) no cluster meshes.
ClusterEvalSide cluster_eval_side(const RunSummary& run, const std::vector<FrameRecord>& frames, bool clusters,
                                  const std::string& source);

// The median (the mean of the middle two for an even count; 0 for none).
double median_of(std::vector<double> values);

// One column of the comparison: a bake of the scene and its runs.
struct ClusterEvalColumn {
  std::string key;        // "per_object", "per_object_cluster_rule", "clusters" (clusters.json)
  std::string title;      // the table's column heading
  bool clusters = false;  // read the run's cluster figures (units: leaves)
  std::optional<ClusterEvalSide> side;
  std::string missing;                  // why `side` is empty
  std::vector<double> frame_ms_rounds;  // rendered runs: each round's mean frame time
  double frame_ms = 0.0;                // their median (0: not measured)
  double rendered_triangles = 0.0;      // rendered run: triangles per frame
};

// Column indices of ClusterEvalReport::columns.
inline constexpr std::size_t kPerObjectColumn = 0, kSameRuleColumn = 1, kClustersColumn = 2;

struct ClusterEvalReport {
  std::string scene;                       // what was measured ("generated terrain, ...")
  std::string scenario;                    // the scenario file
  std::string machine;                     // CPU model
  std::vector<ClusterEvalColumn> columns;  // per-object, per-object under the cluster rule, clusters
  int rendered_frames = 0;                 // 0: no rendered runs
  int rendered_rounds = 1;                 // rendered runs per column (ClusterEvalColumn::frame_ms_rounds)

  // Column a's triangles per frame over column b's (0 when either is missing); in_view: of
  // those drawn in the first eye's view.
  double triangle_ratio(std::size_t a, std::size_t b, bool in_view = false) const;
  // Clusters draw at most a third of per-object LOD's triangles at <= 0.5 % degradations.
  bool target_met() const;
};

// The side-by-side table and the target line (markdown).
std::string cluster_eval_markdown(const ClusterEvalReport& report);
nlohmann::json cluster_eval_json(const ClusterEvalReport& report);
// clusters.svg: triangles per frame of both sides (and full detail) over the run.
void write_cluster_eval_svg(const ClusterEvalReport& report, const std::filesystem::path& file);

}  // namespace gazelod::cli
