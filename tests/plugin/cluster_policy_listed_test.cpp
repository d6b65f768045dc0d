// SPDX-License-Identifier: Apache-2.0
// The plugin's cluster switch policy in time proportional to the change (ClusterMeshes::update,
// lod::apply_cluster_switch_policy_listed): over a walk past many instances of two hierarchies,
// with saccades, fast turns, criteria switched off and a frame without the policy, every frame's
// drawn cut and hold reasons equal those of the reference (the linear pass in local space and
// the full policy pass over every cluster, with state of its own), while the frames after the
// first step a small share of the clusters. Large enough that the selector runs on its threads.
#include "lod/cluster/cluster_local_view.hpp"
#include "lod/cluster/cluster_switch_policy.hpp"
#include "plugin/cluster_meshes.hpp"
#include "tests/lod/cluster_instance_scene.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace gazelod::plugin {
namespace {

constexpr std::uint32_t kIndicesPerCluster = 3 * 64;

lod::ClusterHierarchy hierarchy(bool grid, std::uint64_t seed) {
  lod::test::TreeSpec spec;
  spec.grid = grid, spec.levels = grid ? 5 : 9, spec.outputs_per_group = 2, spec.spacing_m = 0.6;
  spec.leaf_error_m = 0.002;
  lod::ClusterHierarchy h = lod::test::make_tree(spec, seed).h;
  for (std::size_t i = 0; i < h.size(); ++i) {
    h.first_index[i] = static_cast<std::uint32_t>(kIndicesPerCluster * i);
    h.index_count[i] = kIndicesPerCluster;
  }
  return h;
}

TEST(ClusterMeshesPolicy, StepsWhatChangedAndEqualsTheFullPassEveryFrame) {
  const std::vector<lod::ClusterHierarchy> trees{hierarchy(true, 7), hierarchy(false, 8)};
  constexpr double kSpacingM = 40.0;
  const std::vector<lod::test::Placement> placements = lod::test::scatter(72, 2, kSpacingM, 11);
  ClusterMeshes meshes;
  lod::ClusterInstances reference;
  for (const lod::ClusterHierarchy& h : trees) (void)reference.add_hierarchy(h, kIndicesPerCluster * h.size());
  for (const lod::test::Placement& p : placements) {
    ClusterMeshDesc d;
    d.hierarchy = trees[p.hierarchy];
    d.index_count = kIndicesPerCluster * d.hierarchy.size();
    d.pose = p.pose;
    d.velocity_m_s = p.velocity_m_s;
    (void)meshes.add(d);
    (void)reference.add_instance(p.hierarchy, p.pose, p.velocity_m_s);
  }
  const std::size_t n = reference.size();
  ASSERT_EQ(meshes.cluster_count(), n);
  // Enough clusters that the plugin's selector shares the frame among its threads.
  ASSERT_GE(n, lod::kClusterParallelMinClusters);

  std::vector<std::uint8_t> drawn(n), why(n), bits(n), record_held(n), ref_drawn(n), ref_held(n);
  std::vector<double> self_window(n), parent_window(n);
  const lod::ClusterSwitchState state{record_held, self_window, parent_window};
  const lod::SwitchPolicyConfig policy;  // the defaults: hold, deferral to a saccade
  constexpr std::size_t kFrames = 400, kNoPolicyFrame = 150;
  std::size_t stepped_after_first = 0, frames_held = 0, frames_changed = 0;
  std::vector<std::uint8_t> last(n);
  for (std::size_t k = 0; k < kFrames; ++k) {
    const lod::Viewer v = lod::test::walk_viewer(k, kFrames, 6.0 * kSpacingM, 5);
    const double t_s = static_cast<double>(k) / 90.0;
    const bool suppressed = k % 23 < 3;  // a saccade now and then
    const bool with_policy = k != kNoPolicyFrame;
    meshes.update(v, with_policy ? &policy : nullptr, t_s, suppressed);

    ASSERT_EQ(lod::select_clusters_local(v, reference, {drawn, why, {}, {}, {}, bits}), "") << "frame " << k;
    if (k == 0) {  // a mesh's first frame draws its perceptual cut
      std::copy(bits.begin(), bits.end(), record_held.begin());
      std::fill(self_window.begin(), self_window.end(), lod::kNoSwitchWindow);
      std::fill(parent_window.begin(), parent_window.end(), lod::kNoSwitchWindow);
    }
    if (with_policy) {
      ASSERT_EQ(lod::apply_cluster_switch_policy(policy, t_s, suppressed, bits, state, ref_drawn, ref_held), "");
    } else {
      std::copy(drawn.begin(), drawn.end(), ref_drawn.begin());
    }
    const std::span<const std::uint8_t> got = meshes.drawn();
    ASSERT_TRUE(std::equal(got.begin(), got.end(), ref_drawn.begin(), ref_drawn.end())) << "drawn, frame " << k;
    if (with_policy) {
      const std::span<const std::uint8_t> held = meshes.held();
      ASSERT_TRUE(std::equal(held.begin(), held.end(), ref_held.begin(), ref_held.end())) << "held, frame " << k;
      frames_held += std::any_of(held.begin(), held.end(), [](std::uint8_t h) { return h != 0; });
    }
    frames_changed += k > 0 && !std::equal(got.begin(), got.end(), last.begin());
    std::copy(got.begin(), got.end(), last.begin());
    if (k == 0 || k == kNoPolicyFrame + 1) {
      EXPECT_EQ(meshes.policy_clusters_stepped(), n) << "a full pass";
    }
    if (k > 0 && k != kNoPolicyFrame && k != kNoPolicyFrame + 1)
      stepped_after_first += meshes.policy_clusters_stepped();
  }
  // The walk exercises the policy: coarsenings held back, and cuts that change.
  EXPECT_GT(frames_held, kFrames / 4);
  EXPECT_GT(frames_changed, kFrames / 4);
  const double share = static_cast<double>(stepped_after_first) / static_cast<double>((kFrames - 3) * n);
  std::printf("clusters %zu; stepped per frame after the first: %.1f %% of them\n", n, 100.0 * share);
  EXPECT_LT(share, 0.5) << "the policy steps the change, not the scene";
}

}  // namespace
}  // namespace gazelod::plugin
