// SPDX-License-Identifier: Apache-2.0
// Cluster meshes in the plugin's frame budget (LodCore::apply_budget, ClusterMeshes::apply_steps;
// docs/cluster-budget.md): without a budget nothing changes and a budget that fits everything
// draws exactly the unbudgeted frame; a budget too small for the full cuts coarsens cluster
// meshes and objects alike, the prediction under the budget, each mesh's drawn cut a consistent
// cover never finer than the perceptual cut, the reported triangles those drawn; the same
// inputs give the same frames.
#include "plugin/lod_core.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace gazelod::plugin {
namespace {

constexpr std::uint32_t kTrisPerCluster = 128;

// Grid trees, 4 clusters merged into 2 per group, 128 triangles per cluster: each level up
// halves the triangles.
lod::test::TestTree tree(std::uint64_t seed) {
  lod::test::TreeSpec spec;
  spec.grid = true, spec.levels = 5, spec.outputs_per_group = 2, spec.spacing_m = 0.8, spec.leaf_error_m = 0.002;
  lod::test::TestTree t = lod::test::make_tree(spec, seed);
  for (std::size_t i = 0; i < t.h.size(); ++i) {
    t.h.first_index[i] = static_cast<std::uint32_t>(3 * kTrisPerCluster * i);
    t.h.index_count[i] = 3 * kTrisPerCluster;
  }
  return t;
}

struct Scene {
  std::vector<lod::test::TestTree> trees{tree(1), tree(2), tree(3)};
};

PluginConfig config(double budget_ms) {
  PluginConfig c;
  c.switch_policy = false;  // the drawn cut at step 0 is the perceptual one
  c.budget_ms = budget_ms;
  return c;
}

void populate(LodCore& core, const Scene& s) {
  for (int k = 0; k < 24; ++k) {
    ObjectDesc d;
    d.center_m = {-6.0 + 0.5 * k, 0.2 * (k % 5), -3.0 - 0.7 * k};
    d.radius_m = 0.4;
    for (std::uint32_t tris = 40'000, l = 0; l < 5; ++l, tris /= 4) {
      lod::LodLevel level;
      level.triangles = tris;
      level.vertices = tris / 2;
      level.detail_kind = lod::DetailKind::geometric_error_m;
      level.detail = l == 0 ? 0.0 : 0.0005 * std::pow(4.0, l - 1);
      d.lods.push_back(level);
    }
    (void)core.add_object(d);
  }
  // Three meshes (32 x 32 source clusters over ~25 m) on the ground ahead, one nearer.
  const double z_m[3] = {-8.0, -30.0, -60.0};
  for (std::size_t m = 0; m < s.trees.size(); ++m) {
    ClusterMeshDesc d;
    d.hierarchy = s.trees[m].h;
    d.index_count = 3 * kTrisPerCluster * d.hierarchy.size();
    d.pose.translation_m = {-12.0, -1.6, z_m[m] - 25.0};
    (void)core.add_cluster_mesh(d);
  }
}

FrameInput frame(int k) {
  FrameInput in;
  in.t_ns = 1'000'000'000 + std::int64_t{k} * 11'111'111;
  in.head.valid = true;
  // A slow head sweep: the perceptual cut changes from frame to frame.
  const double yaw = 0.2 * std::sin(0.1 * k);
  in.head.orientation = glm::angleAxis(yaw, glm::dvec3(0.0, 1.0, 0.0));
  in.head.position_m = {0.0, 0.0, -0.05 * k};
  in.head.linear_velocity_m_s = {0.0, 0.0, -4.5};
  in.view_count = 1;
  in.views[0].fov = {-0.8, 0.8, 0.8, -0.8};
  in.views[0].width_px = in.views[0].height_px = 1200;
  return in;
}

double cut_triangles(std::span<const std::uint8_t> drawn, std::uint32_t first, std::size_t count) {
  return double(std::count(drawn.begin() + first, drawn.begin() + first + count, 1)) * kTrisPerCluster;
}

TEST(ClusterBudget, WithoutABudgetOrWithRoomForEverythingTheFrameIsUnchanged) {
  Scene s;
  LodCore plain(config(0.0)), roomy(config(1e6));
  populate(plain, s), populate(roomy, s);
  for (int k = 0; k < 10; ++k) {
    const FrameDecisions& a = plain.decide(frame(k));
    const FrameDecisions& b = roomy.decide(frame(k));
    EXPECT_TRUE(a.cluster_budget_step.empty());
    EXPECT_TRUE(plain.diagnostics().cluster_triangles_drawn.empty());
    ASSERT_EQ(b.cluster_budget_step.size(), 3u);
    for (std::size_t m = 0; m < 3; ++m) {
      EXPECT_EQ(b.cluster_budget_step[m], 0);
      EXPECT_EQ(b.cluster_detail_scale[m], 1.0f);
    }
    ASSERT_TRUE(
        std::equal(a.cluster_drawn.begin(), a.cluster_drawn.end(), b.cluster_drawn.begin(), b.cluster_drawn.end()));
    ASSERT_TRUE(std::equal(a.cluster_limited_by.begin(), a.cluster_limited_by.end(), b.cluster_limited_by.begin(),
                           b.cluster_limited_by.end()));
    ASSERT_TRUE(std::equal(a.lod.begin(), a.lod.end(), b.lod.begin(), b.lod.end()));
    // Without the switch policy the drawn cut is the perceptual one.
    const auto perceptual = plain.diagnostics().cluster_drawn_perceptual;
    ASSERT_TRUE(std::equal(a.cluster_drawn.begin(), a.cluster_drawn.end(), perceptual.begin(), perceptual.end()));
  }
}

TEST(ClusterBudget, TooSmallABudgetCoarsensMeshesAndObjects) {
  Scene s;
  LodCore roomy(config(1e6));
  populate(roomy, s);
  (void)roomy.decide(frame(0));
  const double full_ms = roomy.diagnostics().predicted_ms;  // the perceptual frame, prior costs
  ASSERT_GT(full_ms, 0.3);
  const double budget_ms = 0.35 * full_ms;
  LodCore core(config(budget_ms));
  populate(core, s);
  std::size_t coarser_meshes = 0, coarser_objects = 0;
  double sum_rel = 0.0, worst = 0.0;
  std::size_t predictions = 0;
  for (int k = 0; k < 30; ++k) {
    const FrameDecisions& out = core.decide(frame(k));
    const FrameDiagnostics& diag = core.diagnostics();
    ASSERT_FALSE(diag.budget_infeasible);
    EXPECT_LE(diag.predicted_ms, budget_ms) << "frame " << k;
    for (std::size_t i = 0; i < out.lod.size(); ++i) {
      ASSERT_GE(out.lod[i], diag.lod_perceptual[i]);
      coarser_objects += out.lod[i] > diag.lod_perceptual[i];
    }
    ASSERT_EQ(out.cluster_budget_step.size(), 3u);
    for (std::uint32_t m = 0; m < 3; ++m) {
      const lod::test::TestTree& t = s.trees[m];
      const std::uint32_t first = out.cluster_first[m];
      const auto drawn = out.cluster_drawn.subspan(first, t.h.size());
      const auto perceptual = diag.cluster_drawn_perceptual.subspan(first, t.h.size());
      ASSERT_EQ(lod::test::check_cut(t, drawn), "") << "frame " << k << " mesh " << m;
      const std::vector<int> level = lod::test::cut_levels(t, drawn), at = lod::test::cut_levels(t, perceptual);
      for (std::size_t l = 0; l < level.size(); ++l) ASSERT_GE(level[l], at[l]) << "never finer than perceptual";
      const double tris = cut_triangles(out.cluster_drawn, first, t.h.size());
      EXPECT_EQ(diag.cluster_triangles_drawn[m], tris);
      EXPECT_EQ(out.cluster_detail_scale[m], static_cast<float>(budget::kClusterStepScale[out.cluster_budget_step[m]]));
      if (out.cluster_budget_step[m] > 0) {
        ++coarser_meshes;
        EXPECT_LT(tris, cut_triangles(diag.cluster_drawn_perceptual, first, t.h.size()));
        const double rel = (diag.cluster_triangles_predicted[m] - tris) / tris;
        sum_rel += std::abs(rel), worst = std::max(worst, std::abs(rel)), ++predictions;
      } else {
        EXPECT_EQ(diag.cluster_triangles_predicted[m], tris);  // step 0: the cut as drawn
      }
    }
  }
  EXPECT_GT(coarser_meshes, 0u);
  EXPECT_GT(coarser_objects, 0u);
  ASSERT_GT(predictions, 0u);
  std::printf(
      "coarsened mesh-frames %zu, object-frames %zu; predicted triangles: mean |error| %.1f %%, worst %.1f %%\n",
      coarser_meshes, coarser_objects, 100.0 * sum_rel / double(predictions), 100.0 * worst);
}

TEST(ClusterBudget, SameInputsSameFrames) {
  Scene s;
  LodCore a(config(1.0)), b(config(1.0));
  populate(a, s), populate(b, s);
  for (int k = 0; k < 20; ++k) {
    const FrameDecisions& x = a.decide(frame(k));
    const FrameDecisions& y = b.decide(frame(k));
    ASSERT_TRUE(
        std::equal(x.cluster_drawn.begin(), x.cluster_drawn.end(), y.cluster_drawn.begin(), y.cluster_drawn.end()));
    ASSERT_TRUE(std::equal(x.cluster_budget_step.begin(), x.cluster_budget_step.end(), y.cluster_budget_step.begin(),
                           y.cluster_budget_step.end()));
    ASSERT_TRUE(std::equal(x.lod.begin(), x.lod.end(), y.lod.begin(), y.lod.end()));
    ASSERT_EQ(a.diagnostics().predicted_ms, b.diagnostics().predicted_ms);
    // The same measured times feed both fits.
    a.end_frame(1.0 + 0.01 * k), b.end_frame(1.0 + 0.01 * k);
  }
}

}  // namespace
}  // namespace gazelod::plugin
