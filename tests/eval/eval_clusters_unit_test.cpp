// SPDX-License-Identifier: Apache-2.0
// gazelod eval clusters' parts that need no run: the same-rule baseline's hierarchy
// (clusters/eval_baseline.hpp) and one side's figures from a run (clusters/eval_report.hpp),
// with errors saying what is missing.
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/clusters/eval_baseline.hpp"
#include "apps/gazelod/clusters/eval_report.hpp"
#include "lod/cluster/cluster_select_store.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace gazelod::cli {
namespace {

#define EXPECT_HAS(msg, part) EXPECT_NE(std::string(msg).find(part), std::string::npos) << (msg)

TEST(EvalClustersBaseline, ChainBecomesOneClusterPerLevel) {
  const std::vector<float> xyz = {0, 0, 0, 2, 0, 0, 0, 2, 0, 2, 2, 0};
  const std::vector<std::vector<std::uint32_t>> levels = {{0, 1, 2, 1, 3, 2}, {}, {0, 1, 2}};
  const std::vector<double> errors = {0.0, 0.01, 0.05};
  std::vector<std::uint32_t> indices;
  const lod::ClusterHierarchy h = chain_hierarchy(xyz, levels, errors, indices);
  ASSERT_EQ(h.size(), 2u);  // the empty level is skipped
  EXPECT_EQ(indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2, 0, 1, 2}));
  EXPECT_EQ(h.first_index, (std::vector<std::uint32_t>{0, 6}));
  EXPECT_EQ(h.index_count, (std::vector<std::uint32_t>{6, 3}));
  EXPECT_EQ(h.self_error_m[0], 0.0f);
  EXPECT_GE(h.self_error_m[1], 0.05f);
  EXPECT_EQ(h.parent_error_m[0], h.self_error_m[1]);
  EXPECT_EQ(h.parent_error_m[1], lod::kNoParentError);
  EXPECT_FLOAT_EQ(h.self_center_x_m[0], 1.0f);
  EXPECT_GE(h.self_radius_m[0], std::sqrt(2.0f));
  // A hierarchy the selection accepts: a cut is exactly one level.
  EXPECT_EQ(lod::validate_cluster_hierarchy(h, indices.size()), "");
}

TEST(EvalClustersReport, ASideFromARunAndWhatIsMissing) {
  RunSummary run;
  run.frames = 2;
  run.triangles_drawn = 300;
  run.triangles_full = 1000;
  run.audit.available = true;
  run.audit.triangle_ratio = 1.25;
  run.audit.drawn_triangles = 120;
  run.audit.object_frames = 40;
  run.audit.degraded_share = 0.01;
  run.audit.switches_fixation.per_object_s = 0.5;
  std::vector<FrameRecord> frames(2);
  frames[0].t_s = 0.0, frames[0].triangles_drawn = 100, frames[0].cluster_triangles_drawn = 10;
  frames[1].t_s = 0.1, frames[1].triangles_drawn = 200, frames[1].cluster_triangles_drawn = 30;
  const ClusterEvalSide s = cluster_eval_side(run, frames, false, "run-a");
  EXPECT_EQ(s.frames, 2);
  EXPECT_DOUBLE_EQ(s.triangles_per_frame, 150.0);
  EXPECT_DOUBLE_EQ(s.full_triangles_per_frame, 500.0);
  EXPECT_DOUBLE_EQ(s.drawn_over_oracle, 1.25);
  EXPECT_DOUBLE_EQ(s.in_view_triangles_per_frame, 60.0);
  EXPECT_EQ(s.audit_unit_frames, 40);
  EXPECT_DOUBLE_EQ(s.switches_per_unit_s, 0.5);
  EXPECT_EQ(s.triangles, (std::vector<double>{100, 200}));
  EXPECT_EQ(s.t_s, (std::vector<double>{0.0, 0.1}));
  // A run without cluster meshes: the cluster side says so.
  try {
    (void)cluster_eval_side(run, frames, true, "run-a");
    FAIL() << "no cluster figures accepted";
  } catch (const UsageError& e) {
    EXPECT_HAS(e.what(), "run-a: no cluster figures");
  }
  run.clusters.meshes = 1;
  run.clusters.triangles_drawn = 60;
  run.clusters.triangles_full = 1000;
  ClusterAuditSummary& a = run.clusters.audit;
  // Cluster meshes without an audit (no ground truth): said, not read as zeros.
  try {
    (void)cluster_eval_side(run, frames, true, "run-a");
    FAIL() << "an unaudited run accepted";
  } catch (const UsageError& e) {
    EXPECT_HAS(e.what(), "run-a: the cluster meshes' visibility audit is not available");
  }
  a.available = true;
  a.leaf_frames = 400;
  a.switches_per_leaf_s_fixation = 0.7;
  a.oracle_triangles = 96;
  a.oracle_size_only_triangles = 300;
  a.oracle_eccentricity_only_triangles = 200;
  a.oracle_velocity_only_triangles = 500;
  const ClusterEvalSide k = cluster_eval_side(run, frames, true, "run-a");
  EXPECT_EQ(k.audit_unit_frames, 400);
  EXPECT_DOUBLE_EQ(k.triangles_per_frame, 30.0);
  EXPECT_DOUBLE_EQ(k.switches_per_unit_s, 0.7);
  EXPECT_EQ(k.triangles, (std::vector<double>{10, 30}));
  EXPECT_DOUBLE_EQ(k.oracle_in_view_per_frame, 48.0);
  EXPECT_DOUBLE_EQ(k.oracle_size_only_per_frame, 150.0);
  EXPECT_DOUBLE_EQ(k.oracle_eccentricity_only_per_frame, 100.0);
  EXPECT_DOUBLE_EQ(k.oracle_velocity_only_per_frame, 250.0);
  EXPECT_DOUBLE_EQ(s.oracle_size_only_per_frame, 0.0) << "the per-object side has no per-criterion oracle";
  // No frames: an error, not a division by zero.
  run.frames = 0;
  EXPECT_THROW((void)cluster_eval_side(run, {}, false, "run-a"), UsageError);
}

TEST(EvalClustersReport, TableTargetAndJson) {
  ClusterEvalReport r;
  r.scene = "test";
  r.columns.resize(3);
  for (auto& c : r.columns) c.side = ClusterEvalSide{};
  r.columns[kPerObjectColumn].side->triangles_per_frame = 300.0;
  r.columns[kSameRuleColumn].side->triangles_per_frame = 900.0;
  r.columns[kClustersColumn].side->triangles_per_frame = 90.0;
  r.columns[kClustersColumn].side->degraded_share = 0.004;
  r.columns[kPerObjectColumn].side->in_view_triangles_per_frame = 200.0;
  r.columns[kClustersColumn].side->in_view_triangles_per_frame = 50.0;
  EXPECT_DOUBLE_EQ(r.triangle_ratio(kClustersColumn, kPerObjectColumn), 0.3);
  EXPECT_DOUBLE_EQ(r.triangle_ratio(kClustersColumn, kPerObjectColumn, true), 0.25);
  EXPECT_TRUE(r.target_met());
  EXPECT_HAS(cluster_eval_markdown(r), "met (ratio 0.300, degradations 0.400%; in the first eye's view 0.250)");
  EXPECT_HAS(cluster_eval_markdown(r), "| of those, in the first eye's view");
  EXPECT_EQ(cluster_eval_json(r)["in_view_triangle_ratio"], 0.25);
  r.columns[kClustersColumn].side->degraded_share = 0.006;  // too many degradations
  EXPECT_FALSE(r.target_met());
  EXPECT_HAS(cluster_eval_markdown(r), "MISSED");
  r.columns[kClustersColumn].side.reset();
  r.columns[kClustersColumn].missing = "no cluster figures";
  EXPECT_FALSE(r.target_met());
  EXPECT_HAS(cluster_eval_markdown(r), "not measured");
  EXPECT_EQ(cluster_eval_json(r)["triangle_ratio"], 0.0);
}

// Rendered rounds: each column's figure is the median of its rounds, shown with their range.
TEST(EvalClustersReport, RenderedRoundsGiveTheMedianAndTheRange) {
  EXPECT_EQ(median_of({}), 0.0);
  EXPECT_EQ(median_of({5.0}), 5.0);
  EXPECT_EQ(median_of({9.0, 1.0, 4.0}), 4.0);
  EXPECT_EQ(median_of({4.0, 1.0, 9.0, 2.0}), 3.0);
  ClusterEvalReport r;
  r.columns.resize(3);
  for (auto& c : r.columns) c.side = ClusterEvalSide{};
  r.columns[kPerObjectColumn].key = "per_object";
  r.columns[kSameRuleColumn].key = "per_object_cluster_rule";
  r.columns[kClustersColumn].key = "clusters";
  r.rendered_frames = 20;
  r.rendered_rounds = 3;
  r.columns[kClustersColumn].frame_ms_rounds = {150.0, 120.0, 210.0};
  r.columns[kClustersColumn].frame_ms = median_of(r.columns[kClustersColumn].frame_ms_rounds);
  const std::string md = cluster_eval_markdown(r);
  EXPECT_HAS(md, "rendered (3 interleaved rounds of 20 frames)");
  EXPECT_HAS(md, "150.0 ms (120.0-210.0)");
  const auto j = cluster_eval_json(r)["clusters"]["rendered"];
  EXPECT_EQ(j["frame_ms"], 150.0);
  EXPECT_EQ(j["rounds"], 3);
  EXPECT_EQ(j["frame_ms_rounds"].size(), 3u);
  EXPECT_FALSE(cluster_eval_json(r)["per_object"].contains("rendered")) << "a column not rendered has none";
}

}  // namespace
}  // namespace gazelod::cli
