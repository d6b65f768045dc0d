// SPDX-License-Identifier: Apache-2.0
// The per-cluster audit's pure parts (apps/gazelod/clusters/audit.hpp,
// clusters/scene.hpp): counting leaves against the oracle, the run summary, and node
// transforms as the plugin's poses.
#include "apps/gazelod/clusters/audit.hpp"
#include "apps/gazelod/clusters/scene.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace gazelod::cli {
namespace {

TEST(ClusterAuditMath, LeavesCoarserThanTheOracleInViewAreDegraded) {
  // Clusters 0-3 are leaves (depth 0), 4 and 5 depth 1, 6 depth 2.
  const std::vector<std::uint8_t> depth{0, 0, 0, 0, 1, 1, 2};
  const std::vector<LeafCover> drawn{{6, 0.4f}, {4, 0.1f}, {2, 0.0f}, {5, 0.1f}};
  const std::vector<LeafCover> oracle{{0, 0.0f}, {4, 0.1f}, {5, 0.1f}, {6, 0.4f}};
  const std::vector<std::uint8_t> in_view{1, 1, 1, 0};
  ClusterLeafInput in{drawn, oracle, {}, in_view, depth};
  ClusterAuditFrame f;
  count_cluster_leaves(in, f);
  EXPECT_EQ(f.leaves_in_view, 3);
  EXPECT_EQ(f.degraded, 1) << "leaf 0 only: leaf 2 is finer than its oracle, leaf 3 is out of view";
  EXPECT_EQ(f.excess_depth, 2u);
  EXPECT_EQ(f.excess_depth_max, 2u);
  EXPECT_EQ(f.switches, 0) << "no previous frame";
  // Against the previous frame's covers: leaves 0 and 2 changed; leaf 3 is out of view.
  const std::vector<std::uint32_t> previous{4, 4, 5, 6};
  in.previous = previous;
  ClusterAuditFrame g;
  count_cluster_leaves(in, g);
  EXPECT_EQ(g.switches, 2);
  // Equal errors are never a degradation, whatever the cluster.
  const std::vector<LeafCover> same_error{{5, 0.1f}, {4, 0.1f}, {2, 0.0f}, {5, 0.1f}};
  const std::vector<LeafCover> oracle_same{{4, 0.1f}, {4, 0.1f}, {2, 0.0f}, {5, 0.1f}};
  ClusterAuditFrame h;
  count_cluster_leaves({same_error, oracle_same, {}, in_view, depth}, h);
  EXPECT_EQ(h.degraded, 0);
}

TEST(ClusterAuditMath, SummarySplitsSuppressionAndGuardsEmptyRatios) {
  ClusterAuditFrame fixation;
  fixation.available = true;
  fixation.leaves_in_view = 100, fixation.degraded = 2, fixation.excess_depth = 3, fixation.excess_depth_max = 2;
  fixation.drawn_triangles = 300, fixation.oracle_triangles = 200, fixation.switches = 5, fixation.leaf_s = 1.0;
  ClusterAuditFrame saccade = fixation;
  saccade.suppressed = true, saccade.degraded = 50, saccade.switches = 20, saccade.miscovered = 1;
  const std::vector<ClusterAuditFrame> frames{fixation, saccade, ClusterAuditFrame{}};
  const ClusterAuditSummary s = summarize_cluster_audit(frames);
  ASSERT_TRUE(s.available);
  EXPECT_EQ(s.frames, 2);
  EXPECT_EQ(s.leaf_frames, 100);
  EXPECT_DOUBLE_EQ(s.degraded_share, 0.02);
  EXPECT_DOUBLE_EQ(s.excess_depth_mean, 1.5);
  EXPECT_EQ(s.degraded_suppressed, 50);
  EXPECT_DOUBLE_EQ(s.triangle_ratio, 1.5);
  EXPECT_DOUBLE_EQ(s.switches_per_leaf_s_fixation, 5.0);
  EXPECT_DOUBLE_EQ(s.switches_per_leaf_s_suppressed, 20.0);
  EXPECT_EQ(s.miscovered, 1);
  const nlohmann::json j = cluster_audit_json(s);
  EXPECT_DOUBLE_EQ(j.at("visible_degradations").at("share").get<double>(), 0.02);
  EXPECT_EQ(j.at("miscovered_leaf_frames").get<int>(), 1);
  std::ostringstream out;
  print_cluster_audit(s, out);
  EXPECT_NE(out.str().find("visible degradations 2.00% of 100 in-view leaf-frames"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("1 leaf-frames NOT covered exactly once"), std::string::npos) << out.str();

  // Nothing audited: no division by zero, no NaN, "available": false.
  const ClusterAuditSummary none = summarize_cluster_audit(std::vector<ClusterAuditFrame>{ClusterAuditFrame{}});
  EXPECT_FALSE(none.available);
  EXPECT_EQ(none.degraded_share, 0.0);
  EXPECT_EQ(none.triangle_ratio, 0.0);
  EXPECT_FALSE(cluster_audit_json(none).at("available").get<bool>());
}

TEST(ClusterAuditMath, RunSummaryLineAndJson) {
  ClusterRunSummary s;
  std::ostringstream empty;
  print_cluster_run(s, 10, empty);
  EXPECT_EQ(empty.str(), "");
  EXPECT_EQ(cluster_run_json(s).at("meshes").get<int>(), 0);
  s.meshes = 2, s.clusters = 30, s.leaves = 16;
  s.triangles_drawn = 2500, s.triangles_perceptual = 2000, s.triangles_full = 10000;
  std::ostringstream out;
  print_cluster_run(s, 10, out);
  EXPECT_NE(out.str().find("2 meshes, 30 clusters (16 leaves): 250 triangles drawn per frame of 1000"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("(25.0%, per eye; 200 before the switch policy)"), std::string::npos) << out.str();
  EXPECT_DOUBLE_EQ(cluster_run_json(s).at("drawn_over_full").get<double>(), 0.25);
}

TEST(ClusterScenePose, NodeTransformsBecomeInstanceTransformsOrSayWhyNot) {
  const glm::dvec3 shift(0.5, 0.0, -2.0);
  glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 3.0));
  world = glm::rotate(world, 0.7, glm::normalize(glm::dvec3(1.0, 1.0, 0.0)));
  world = glm::scale(world, glm::dvec3(2.5));
  lod::InstanceTransform xf;
  ASSERT_EQ(instance_transform_of(world, shift, xf), "");
  EXPECT_NEAR(xf.scale, 2.5, 1e-12);
  // The pose maps points as the matrix does, then shifted.
  const glm::dvec3 p(0.3, -1.2, 0.8);
  const glm::dvec3 expected = glm::dvec3(world * glm::dvec4(p, 1.0)) + shift;
  const glm::dvec3 got = xf.translation_m + xf.scale * (xf.rotation * p);
  EXPECT_NEAR(glm::length(got - expected), 0.0, 1e-9);

  lod::InstanceTransform untouched;
  untouched.scale = 7.0;
  const auto refused = [&](const glm::dmat4& m, const std::string& says) {
    const std::string why = instance_transform_of(m, shift, untouched);
    EXPECT_NE(why.find(says), std::string::npos) << "'" << why << "'";
    EXPECT_EQ(untouched.scale, 7.0);
  };
  refused(glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 1.0)), "non-uniformly");
  refused(glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0)), "mirrors");
  refused(glm::scale(glm::dmat4(1.0), glm::dvec3(0.0)), "degenerate");
  glm::dmat4 sheared(1.0);
  sheared[1][0] = 0.5;  // y axis leans along x
  sheared[1] = glm::dvec4(glm::dvec3(sheared[1]) / glm::length(glm::dvec3(sheared[1])), 0.0);
  refused(sheared, "shears");
  glm::dmat4 projective(1.0);
  projective[2][3] = 0.1;
  refused(projective, "projective");
  glm::dmat4 nan(1.0);
  nan[3][0] = std::nan("");
  refused(nan, "not finite");
}

}  // namespace
}  // namespace gazelod::cli
