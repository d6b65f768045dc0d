// SPDX-License-Identifier: Apache-2.0
// A cluster mesh's coarsening steps for the frame budget (lod::ClusterSet::mesh_detail_scale,
// ClusterSelector's per-instance detail scales; budget/cluster_cut_cost.hpp): scale 1 is the
// unscaled cut bit for bit; a scaled cut through the bounding tree equals the linear pass's
// (the subtree skipping stays exact), is a consistent cover of every mesh and never finer than
// the perceptual cut; more scale never draws more triangles; bad scales are refused; the
// cut-cost ladder equals a brute-force count, and its prediction's error against the cuts
// actually drawn on a baked terrain (printed, and bounded).
#include "budget/cluster_cut_cost.hpp"
#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_local_view.hpp"
#include "lod/cluster/cluster_selector.hpp"
#include "tests/lod/cluster_instance_scene.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace gazelod {
namespace {

using budget::kClusterSteps;
using budget::kClusterStepScale;
using lod::test::CutBytes;

// Synthetic trees whose groups never produce more clusters than they merge (a coarser cut has
// no more triangles: one triangle per cluster), placed many times, rotated, scaled, moving.
struct Scene {
  std::vector<lod::test::TestTree> trees;
  lod::ClusterInstances instances;
  std::vector<std::uint32_t> tree_of;  // per instance
};

void build_scene(Scene& s, std::size_t count, std::uint64_t seed) {
  std::vector<lod::test::TreeSpec> specs(3);
  specs[0].grid = true, specs[0].levels = 5, specs[0].outputs_per_group = 2;
  specs[1].levels = 8, specs[1].equal_error_chance = 0.4;
  specs[2].grid = true, specs[2].levels = 6, specs[2].spacing_m = 0.1, specs[2].leaf_error_m = 0.0001;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    s.trees.push_back(lod::test::make_tree(specs[i], seed + i));
    (void)s.instances.add_hierarchy(s.trees.back().h, 3 * s.trees.back().h.size());
  }
  for (const lod::test::Placement& p : lod::test::scatter(count, 3, 6.0, seed)) {
    s.tree_of.push_back(p.hierarchy);
    s.instances.add_instance(p.hierarchy, p.pose, p.velocity_m_s);
  }
}

std::string select_bvh(lod::ClusterSelector& sel, const lod::Viewer& v, const lod::ClusterInstances& inst, CutBytes& b,
                       std::span<const double> scales) {
  return sel.select(v, inst, {b.drawn, b.why, b.bits, false}, scales);
}

std::string select_linear(const lod::Viewer& v, const lod::ClusterInstances& inst, CutBytes& b,
                          std::span<const double> scales) {
  return lod::select_clusters_local(v, inst, {b.drawn, b.why, {}, {}, {}, b.bits, {}}, scales);
}

double triangles(const lod::ClusterInstances& inst, std::uint32_t k, std::span<const std::uint8_t> drawn) {
  const lod::ClusterInstance& i = inst.instance(k);
  const lod::ClusterHierarchy& h = inst.hierarchy(i.hierarchy);
  double t = 0.0;
  for (std::size_t c = 0; c < h.size(); ++c) t += drawn[i.first_cluster + c] ? h.index_count[c] / 3 : 0;
  return t;
}

TEST(ClusterDetailScale, OneIsTheUnscaledCutBitForBit) {
  Scene s;
  build_scene(s, 24, 3);
  const std::size_t n = s.instances.size();
  const std::vector<double> ones(s.instances.instance_count(), 1.0);
  lod::ClusterSelector plain(2, 1), scaled(2, 1);  // shared work on two threads too
  CutBytes a(n), b(n), la(n), lb(n);
  std::size_t drawn = 0;
  for (std::size_t f = 0; f < 40; ++f) {
    const lod::Viewer v = lod::test::walk_viewer(f, 40, 60.0, 5);
    ASSERT_EQ(select_bvh(plain, v, s.instances, a, {}), "");
    ASSERT_EQ(select_bvh(scaled, v, s.instances, b, ones), "");
    ASSERT_EQ(a.drawn, b.drawn) << "frame " << f;
    ASSERT_EQ(a.why, b.why) << "frame " << f;
    ASSERT_EQ(a.bits, b.bits) << "frame " << f;
    ASSERT_TRUE(std::equal(plain.drawn().begin(), plain.drawn().end(), scaled.drawn().begin(), scaled.drawn().end()));
    ASSERT_EQ(select_linear(v, s.instances, la, {}), "");
    ASSERT_EQ(select_linear(v, s.instances, lb, ones), "");
    ASSERT_EQ(la.drawn, lb.drawn);
    ASSERT_EQ(la.bits, lb.bits);
    drawn += plain.drawn().size();
  }
  EXPECT_GT(drawn, 0u);
}

TEST(ClusterDetailScale, ScaledCutEqualsTheLinearPassAndCoversEveryMesh) {
  Scene s;
  build_scene(s, 30, 11);
  const std::size_t n = s.instances.size(), meshes = s.instances.instance_count();
  lod::ClusterSelector sel(2, 1);
  CutBytes bvh(n), linear(n);
  std::mt19937_64 rng(17);
  std::vector<double> scales(meshes);
  std::size_t coarsened = 0;
  for (std::size_t f = 0; f < 60; ++f) {
    const lod::Viewer v = lod::test::walk_viewer(f, 60, 60.0, 9);
    for (double& sc : scales) sc = kClusterStepScale[rng() % kClusterSteps];
    ASSERT_EQ(select_bvh(sel, v, s.instances, bvh, scales), "");
    ASSERT_EQ(select_linear(v, s.instances, linear, scales), "");
    ASSERT_EQ(bvh.drawn, linear.drawn) << "frame " << f;
    ASSERT_EQ(bvh.why, linear.why) << "frame " << f;
    ASSERT_EQ(bvh.bits, linear.bits) << "frame " << f;
    // Every mesh covered exactly once, no cracks: one drawn node on every leaf's path.
    for (std::uint32_t k = 0; k < meshes; ++k) {
      const lod::ClusterInstance& inst = s.instances.instance(k);
      const lod::test::TestTree& t = s.trees[s.tree_of[k]];
      ASSERT_EQ(
          lod::test::check_cut(t, std::span<const std::uint8_t>(bvh.drawn).subspan(inst.first_cluster, t.h.size())), "")
          << "frame " << f << " mesh " << k << " scale " << scales[k];
    }
    coarsened +=
        static_cast<std::size_t>(std::count_if(scales.begin(), scales.end(), [](double x) { return x > 1.0; }));
  }
  EXPECT_GT(coarsened, 0u);
}

TEST(ClusterDetailScale, MoreScaleNeverDrawsMoreTrianglesNorAFinerCluster) {
  Scene s;
  build_scene(s, 24, 23);
  const std::size_t n = s.instances.size(), meshes = s.instances.instance_count();
  lod::ClusterSelector sel(1);
  std::vector<CutBytes> cut(kClusterSteps, CutBytes(n));
  double total_first = 0.0, total_last = 0.0;
  for (std::size_t f = 0; f < 30; ++f) {
    const lod::Viewer v = lod::test::walk_viewer(f, 30, 60.0, 4);
    for (std::size_t k = 0; k < kClusterSteps; ++k) {
      const std::vector<double> scales(meshes, kClusterStepScale[k]);
      ASSERT_EQ(select_bvh(sel, v, s.instances, cut[k], scales), "");
    }
    for (std::uint32_t m = 0; m < meshes; ++m) {
      const lod::ClusterInstance& inst = s.instances.instance(m);
      const lod::test::TestTree& t = s.trees[s.tree_of[m]];
      std::vector<int> before;
      for (std::size_t k = 0; k < kClusterSteps; ++k) {
        const auto mine = std::span<const std::uint8_t>(cut[k].drawn).subspan(inst.first_cluster, t.h.size());
        const std::vector<int> levels = lod::test::cut_levels(t, mine);
        if (k > 0) {
          // Per leaf, the node drawn over it is the perceptual one's or above it (never finer).
          for (std::size_t l = 0; l < levels.size(); ++l)
            ASSERT_GE(levels[l], before[l]) << "frame " << f << " mesh " << m << " step " << k << " leaf " << l;
          ASSERT_LE(triangles(s.instances, m, cut[k].drawn), triangles(s.instances, m, cut[k - 1].drawn));
        }
        before = levels;
      }
      total_first += triangles(s.instances, m, cut[0].drawn);
      total_last += triangles(s.instances, m, cut[kClusterSteps - 1].drawn);
    }
  }
  // The ladder does coarsen: 16 times the error leaves well under half the triangles here.
  EXPECT_LT(total_last, 0.5 * total_first);
}

TEST(ClusterDetailScale, BadScalesAreRefused) {
  Scene s;
  build_scene(s, 4, 2);
  CutBytes b(s.instances.size());
  lod::ClusterSelector sel(1);
  const lod::Viewer v = lod::test::walk_viewer(0, 10, 20.0, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::vector<double>& bad :
       {std::vector<double>{1.0, 1.0, 1.0}, std::vector<double>{1.0, 0.5, 1.0, 1.0},
        std::vector<double>{1.0, 1.0, nan, 1.0}, std::vector<double>{2e6, 1.0, 1.0, 1.0}}) {
    EXPECT_NE(select_bvh(sel, v, s.instances, b, bad), "");
    EXPECT_NE(select_linear(v, s.instances, b, bad), "");
  }
  EXPECT_NE(lod::check_detail_scales(std::vector<double>{1.0, 0.999}, 2), "");
  EXPECT_EQ(lod::check_detail_scales(std::vector<double>{1.0, 16.0}, 2), "");
  EXPECT_EQ(lod::check_detail_scales({}, 2), "");
}

// The ladder equals a brute-force count of the uniform cut at each rung's threshold.
TEST(ClusterCutCost, LadderIsTheUniformCutsTriangles) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    lod::test::TreeSpec spec;
    spec.grid = true, spec.levels = 5, spec.outputs_per_group = 2;
    spec.equal_error_chance = 0.0;  // (a group of error 0 over source clusters would hide them)
    const lod::test::TestTree t = lod::test::make_tree(spec, seed);
    const budget::ClusterCutCost cost(t.h);
    ASSERT_GT(cost.rungs(), 8u);
    for (std::size_t j = 0; j < cost.rungs(); ++j) {
      const double tau = cost.threshold_m(j);
      double brute = 0.0;
      for (std::size_t i = 0; i < t.h.size(); ++i)
        if (t.h.self_error_m[i] < tau && !(t.h.parent_error_m[i] < tau)) brute += t.h.index_count[i] / 3;
      EXPECT_NEAR(cost.triangles_at_rung(double(j)), brute, 1e-9 * brute) << "rung " << j;
    }
    EXPECT_EQ(cost.finest_triangles(), double(t.leaves.size()));           // the source clusters
    EXPECT_EQ(cost.coarsest_triangles(), double(spec.outputs_per_group));  // the top group's
    std::array<double, kClusterSteps> out{};
    cost.predict_steps(600.0, 700.0, out);
    EXPECT_EQ(out[0], 700.0);  // step 0: the cut as drawn
    for (std::size_t k = 1; k < kClusterSteps; ++k) {
      EXPECT_LE(out[k], out[k - 1]);
      EXPECT_LE(out[k], 600.0);
    }
    EXPECT_LT(out[kClusterSteps - 1], 0.5 * 600.0);
  }
}

// The prediction against the cuts actually drawn at each step, along a walk over a baked
// terrain (bake's hierarchy; the viewer as cluster_bvh_test's walks), with the uniform cut's
// drop (elasticity 1) and with the elasticity learnt as the plugin learns it (from the step
// drawn each frame: here each step in turn). Printed for docs/cluster-budget.md; bounded so
// that a regression in the model shows.
TEST(ClusterCutCost, PredictionErrorOnABakedTerrain) {
  const lod::ClusterHierarchy terrain = lod::test::baked_terrain(60'000, 30.0, 4.0);
  lod::ClusterInstances instances;
  std::size_t index_buffer = 0;
  for (std::size_t i = 0; i < terrain.size(); ++i)
    index_buffer = std::max<std::size_t>(index_buffer, std::size_t{terrain.first_index[i]} + terrain.index_count[i]);
  const std::uint32_t h = instances.add_hierarchy(terrain, index_buffer);
  instances.add_instance(h, {}, glm::dvec3(0.0));
  const budget::ClusterCutCost cost(terrain);
  lod::ClusterSelector sel(1);
  CutBytes b(instances.size());
  budget::ClusterStepElasticity learnt;
  std::array<double, kClusterSteps> uniform_err{}, learnt_err{}, learnt_signed{}, learnt_worst{};
  std::size_t frames = 0;
  for (std::size_t f = 0; f < 120; ++f) {
    lod::Viewer v = lod::test::walk_viewer(f, 120, 30.0, 3);
    v.use_size = v.use_eccentricity = v.use_velocity = true;  // the plugin's criteria
    ASSERT_EQ(select_bvh(sel, v, instances, b, {}), "");
    const double perceptual = triangles(instances, 0, b.drawn);
    std::array<double, kClusterSteps> uniform{}, predicted{}, actual{};
    cost.predict_steps(perceptual, perceptual, uniform, 1.0);
    cost.predict_steps(perceptual, perceptual, predicted, learnt.value);
    for (std::size_t k = 1; k < kClusterSteps; ++k) {
      const std::vector<double> scale{kClusterStepScale[k]};
      ASSERT_EQ(select_bvh(sel, v, instances, b, scale), "");
      actual[k] = triangles(instances, 0, b.drawn);
    }
    if (f >= 8) {  // the first frames learn
      for (std::size_t k = 1; k < kClusterSteps; ++k) {
        const double rel = (predicted[k] - actual[k]) / std::max(actual[k], 1.0);
        uniform_err[k] += std::abs(uniform[k] - actual[k]) / std::max(actual[k], 1.0);
        learnt_err[k] += std::abs(rel), learnt_signed[k] += rel;
        learnt_worst[k] = std::max(learnt_worst[k], std::abs(rel));
      }
      ++frames;
    }
    const std::size_t drawn_step = 1 + f % (kClusterSteps - 1);  // as if the budget chose it
    learnt.update(cost.observed_elasticity(perceptual, drawn_step, actual[drawn_step]));
  }
  double mean_uniform = 0.0, mean_learnt = 0.0;
  for (std::size_t k = 1; k < kClusterSteps; ++k) {
    std::printf(
        "step %zu (s = %.3f): uniform drop mean |error| %.1f %%; learnt: mean |error| %.1f %%, "
        "mean signed %+.1f %%, worst %.1f %%\n",
        k, kClusterStepScale[k], 100.0 * uniform_err[k] / double(frames), 100.0 * learnt_err[k] / double(frames),
        100.0 * learnt_signed[k] / double(frames), 100.0 * learnt_worst[k]);
    mean_uniform += uniform_err[k] / double(frames) / double(kClusterSteps - 1);
    mean_learnt += learnt_err[k] / double(frames) / double(kClusterSteps - 1);
  }
  std::printf("all steps: uniform %.1f %%, learnt %.1f %% (elasticity %.2f)\n", 100.0 * mean_uniform,
              100.0 * mean_learnt, learnt.value);
  EXPECT_LT(mean_learnt, 0.5 * mean_uniform);
  EXPECT_LT(mean_learnt, 0.25);
}

}  // namespace
}  // namespace gazelod
