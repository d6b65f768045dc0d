// SPDX-License-Identifier: Apache-2.0
// FrameBudget with cluster meshes as items (budget/frame_budget.hpp): a budget too small for
// the full cuts coarsens objects and cluster meshes alike and brings the prediction under the
// budget, checked against an independent sum; a generous one keeps every step 0; the same
// inputs give the same choice; mismatched spans are refused; the cost fit counts the triangles
// a mesh actually drew.
#include "budget/frame_budget.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gazelod::budget {
namespace {

using Chains = std::vector<std::vector<lod::LodLevel>>;

Chains chains(std::size_t objects) {
  Chains c(objects);
  for (std::size_t k = 0; k < objects; ++k)
    for (std::uint32_t tris = 40'000 + 1'000 * std::uint32_t(k); tris >= 500; tris /= 2) {
      lod::LodLevel l;
      l.triangles = tris;
      l.vertices = tris / 2;
      c[k].push_back(l);
    }
  return c;
}

// A mesh whose steps lose a third of their triangles each.
BudgetClusterView cluster(double tris0, double px) {
  BudgetClusterView v;
  v.size_px = px;
  for (std::size_t k = 0; k < kClusterSteps; ++k, tris0 *= 0.66) v.triangles[k] = tris0;
  return v;
}

FrameBudgetOptions options() {
  FrameBudgetOptions o;
  o.prior = {0.0, 1e-8, 0.0, 0.0};  // 1e-5 ms per triangle, nothing else: easy sums
  return o;
}

double by_hand_ms(const Chains& c, std::span<const std::uint8_t> lod, std::span<const BudgetClusterView> meshes,
                  std::span<const std::uint8_t> step) {
  double tris = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) tris += c[k][lod[k]].triangles;
  for (std::size_t m = 0; m < meshes.size(); ++m) tris += meshes[m].triangles[step[m]];
  return 1e-5 * tris;
}

struct Frame {
  Chains c = chains(20);
  std::vector<std::uint8_t> perceptual = std::vector<std::uint8_t>(20, 0);
  std::vector<BudgetObjectView> view = std::vector<BudgetObjectView>(20, BudgetObjectView{20'000.0, 1.0});
  std::vector<BudgetClusterView> meshes{cluster(300'000, 200'000), cluster(120'000, 50'000), cluster(60'000, 90'000)};
  std::vector<std::uint8_t> lod = std::vector<std::uint8_t>(20, 0), step = std::vector<std::uint8_t>(3, 0);
};

TEST(ClusterFrameBudget, TooSmallABudgetCoarsensObjectsAndMeshes) {
  Frame f;
  // Everything at its finest: 20 objects ~ 0.99 M triangles + 480 k cluster triangles = ~14.7 ms.
  const double full_ms = by_hand_ms(f.c, f.perceptual, f.meshes, f.step);
  ASSERT_GT(full_ms, 14.0);
  FrameBudget b(f.c, 6.0, options(), f.meshes.size());
  ASSERT_EQ(b.choose(f.perceptual, f.view, f.lod, f.meshes, f.step), "");
  EXPECT_FALSE(b.infeasible());
  EXPECT_LE(b.predicted_ms(), 6.0);
  EXPECT_NEAR(b.predicted_ms(), by_hand_ms(f.c, f.lod, f.meshes, f.step), 1e-9);
  EXPECT_GT(b.predicted_ms(), 5.0);  // the solver fills the budget, it does not just go coarsest
  const auto coarser_objects = std::count_if(f.lod.begin(), f.lod.end(), [](std::uint8_t l) { return l > 0; });
  const auto coarser_meshes = std::count_if(f.step.begin(), f.step.end(), [](std::uint8_t s) { return s > 0; });
  EXPECT_GT(coarser_objects, 0);
  EXPECT_GT(coarser_meshes, 0);
  for (std::size_t m = 0; m < f.meshes.size(); ++m) {
    EXPECT_LT(f.step[m], kClusterSteps);
    EXPECT_EQ(b.cluster_predicted_triangles(m), f.meshes[m].triangles[f.step[m]]);
  }
}

TEST(ClusterFrameBudget, AGenerousBudgetKeepsEveryStepZero) {
  Frame f;
  FrameBudget b(f.c, 100.0, options(), f.meshes.size());
  std::fill(f.step.begin(), f.step.end(), 7);
  ASSERT_EQ(b.choose(f.perceptual, f.view, f.lod, f.meshes, f.step), "");
  EXPECT_EQ(f.step, std::vector<std::uint8_t>(3, 0));
  EXPECT_EQ(f.lod, f.perceptual);
}

TEST(ClusterFrameBudget, NothingFitsGivesTheCoarsestSteps) {
  Frame f;
  FrameBudget b(f.c, 0.2, options(), f.meshes.size());  // the coarsest frame is ~0.33 ms
  ASSERT_EQ(b.choose(f.perceptual, f.view, f.lod, f.meshes, f.step), "");
  EXPECT_TRUE(b.infeasible());
  EXPECT_EQ(f.step, std::vector<std::uint8_t>(3, kClusterSteps - 1));
}

TEST(ClusterFrameBudget, SameInputsSameChoice) {
  Frame f, g;
  FrameBudget a(f.c, 6.0, options(), 3), b(g.c, 6.0, options(), 3);
  for (int frame = 0; frame < 20; ++frame) {
    // Moving inputs: the meshes' sizes and triangles change from frame to frame.
    for (std::size_t m = 0; m < 3; ++m) {
      f.meshes[m] = g.meshes[m] = cluster(100'000.0 * double(m + 1) * (1.0 + 0.3 * std::sin(frame + m)), 60'000.0);
    }
    ASSERT_EQ(a.choose(f.perceptual, f.view, f.lod, f.meshes, f.step), "");
    ASSERT_EQ(b.choose(g.perceptual, g.view, g.lod, g.meshes, g.step), "");
    ASSERT_EQ(f.lod, g.lod);
    ASSERT_EQ(f.step, g.step);
    ASSERT_EQ(a.predicted_ms(), b.predicted_ms());
    ASSERT_LE(a.predicted_ms(), 6.0);
    EXPECT_TRUE(a.observe(1.2 * a.predicted_ms()));
    EXPECT_TRUE(b.observe(1.2 * b.predicted_ms()));
  }
}

TEST(ClusterFrameBudget, MismatchedSpansAreRefused) {
  Frame f;
  FrameBudget b(f.c, 6.0, options(), 3);
  std::vector<std::uint8_t> two(2);
  EXPECT_NE(b.choose(f.perceptual, f.view, f.lod), "");  // the meshes are missing
  EXPECT_NE(b.choose(f.perceptual, f.view, f.lod, std::span(f.meshes).first(2), two), "");
  EXPECT_NE(b.choose(f.perceptual, f.view, f.lod, f.meshes, two), "");
  EXPECT_FALSE(b.record_cluster_triangles(std::vector<double>{1.0}));
}

// The cost fit takes the triangles recorded as drawn: with the true cost 2e-5 ms per triangle
// and the meshes drawing twice the predicted triangles, the fit's C1 lands where those
// measured frames put it (not where the predictions would).
TEST(ClusterFrameBudget, TheFitCountsTheDrawnTriangles) {
  Frame f;
  f.c = chains(0);
  f.perceptual.clear(), f.view.clear(), f.lod.clear();
  FrameBudget b(f.c, 1000.0, options(), 3);
  for (int frame = 0; frame < 200; ++frame) {
    for (std::size_t m = 0; m < 3; ++m) f.meshes[m] = cluster(50'000.0 * double(m + 1) + 3'000.0 * (frame % 7), 1.0);
    ASSERT_EQ(b.choose(f.perceptual, f.view, f.lod, f.meshes, f.step), "");
    std::vector<double> drawn(3);
    double tris = 0.0;
    for (std::size_t m = 0; m < 3; ++m) tris += drawn[m] = 2.0 * f.meshes[m].triangles[f.step[m]];
    ASSERT_TRUE(b.record_cluster_triangles(drawn));
    EXPECT_TRUE(b.observe(1e-5 * tris));
  }
  // Measured = 1e-5 ms per drawn triangle (2e-5 ms per predicted one): the fit per drawn
  // triangle, with the fixed vertex share (0.5 vertices per triangle at C2 = 0 prior) free.
  const double per_tri_ms =
      1e3 * (b.coefficients().c1_s_per_tri + kClusterVerticesPerTriangle * b.coefficients().c2_s_per_vert);
  EXPECT_NEAR(per_tri_ms, 1e-5, 1e-6);
}

}  // namespace
}  // namespace gazelod::budget
