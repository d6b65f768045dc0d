// SPDX-License-Identifier: Apache-2.0
// The bounding-hierarchy selection (lod/cluster/cluster_selector.hpp): its tree bounds every
// parent record below each node; its cut equals the linear pass in local space byte for byte
// (drawn, limiting criterion, record bits) and as a list, on every frame of walks over many
// instances of synthetic trees and of a baked terrain (rotated, scaled, moving), with the viewer
// inside spheres, fast head turns and saccades, criteria off; on 1, 2 and 4 threads alike; with
// its incremental byte writes alike. And the instances share one hierarchy's memory; the thread
// pool runs every task once (also under ThreadSanitizer: scripts/setup.sh).
#include "lod/cluster/cluster_bvh.hpp"
#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_local_view.hpp"
#include "lod/cluster/cluster_selector.hpp"
#include "lod/cluster/cluster_thread_pool.hpp"
#include "tests/lod/cluster_instance_scene.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace gazelod::lod {
namespace {

using test::CutBytes;
using test::Placement;
using test::TreeSpec;

std::vector<TreeSpec> tree_specs() {
  std::vector<TreeSpec> specs(4);
  specs[0].grid = true, specs[0].levels = 5, specs[0].outputs_per_group = 2;
  specs[1].levels = 8, specs[1].equal_error_chance = 0.4;
  specs[2].grid = true, specs[2].levels = 4, specs[2].outputs_per_group = 3, specs[2].leaf_error_m = 0.01;
  specs[3].grid = true, specs[3].levels = 6, specs[3].spacing_m = 0.1, specs[3].leaf_error_m = 0.0001;
  return specs;
}

// Registers the hierarchies and the placements; returns the instances' placements (for moving them).
std::vector<Placement> place(ClusterInstances& instances, const std::vector<ClusterHierarchy>& hierarchies,
                             std::size_t count, double spacing_m, std::uint64_t seed) {
  std::vector<std::uint32_t> ids;
  for (const ClusterHierarchy& h : hierarchies) ids.push_back(instances.add_hierarchy(h, 3 * h.size() + 1'000'000));
  std::vector<Placement> placed = test::scatter(count, static_cast<std::uint32_t>(ids.size()), spacing_m, seed);
  for (const Placement& p : placed) instances.add_instance(ids[p.hierarchy], p.pose, p.velocity_m_s);
  return placed;
}

// The moving instances move on by one 90 Hz frame.
void move(ClusterInstances& instances, std::vector<Placement>& placed) {
  for (std::uint32_t k = 0; k < placed.size(); ++k) {
    if (placed[k].velocity_m_s == glm::dvec3(0.0)) continue;
    placed[k].pose.translation_m += placed[k].velocity_m_s / 90.0;
    instances.set_pose(k, placed[k].pose, placed[k].velocity_m_s);
  }
}

// Walks `frames` frames, comparing every one; returns the clusters evaluated over all frames.
std::size_t walk_and_compare(ClusterInstances& instances, std::vector<Placement>& placed, std::size_t frames,
                             double extent_m, std::uint64_t seed, ClusterSelector& selector) {
  CutBytes bytes(instances.size()), linear;
  std::size_t evaluated = 0, drawn = 0;
  for (std::size_t f = 0; f < frames; ++f) {
    const Viewer v = test::walk_viewer(f, frames, extent_m, seed);
    const std::string diff = test::compare_with_linear(v, instances, selector, bytes, linear);
    EXPECT_EQ(diff, "") << "frame " << f;
    if (!diff.empty()) break;
    evaluated += selector.clusters_evaluated();
    drawn += selector.drawn().size();
    move(instances, placed);
  }
  EXPECT_GT(drawn, 0u);
  return evaluated;
}

TEST(ClusterBvh, BoundsEveryParentRecordBelowEachNode) {
  std::uint64_t seed = 1;
  for (const TreeSpec& spec : tree_specs()) {
    const test::TestTree t = test::make_tree(spec, seed++);
    for (std::size_t task : {std::size_t{7}, kBvhTaskClusters}) {
      const ClusterBvh b = build_cluster_bvh(t.h, task);
      EXPECT_EQ(check_cluster_bvh(b, t.h), "");
      for (std::uint32_t r : b.task_roots) EXPECT_TRUE(b.node_cluster_count[r] <= task || b.is_leaf(r));
    }
  }
  const ClusterHierarchy terrain = test::baked_terrain(20'000, 20.0, 3.0);
  const ClusterBvh b = build_cluster_bvh(terrain);
  EXPECT_EQ(check_cluster_bvh(b, terrain), "");
  EXPECT_EQ(b.task_roots, std::vector<std::uint32_t>{0});
  EXPECT_LT(b.node_count(), terrain.size()) << "leaves hold several groups";
  EXPECT_EQ(build_cluster_bvh(ClusterHierarchy{}).size(), 0u);
}

TEST(ClusterBvh, CutEqualsLinearPassOnWalksOverSyntheticTrees) {
  std::vector<ClusterHierarchy> trees;
  std::uint64_t seed = 11;
  for (const TreeSpec& spec : tree_specs()) trees.push_back(test::make_tree(spec, seed++).h);
  ClusterInstances instances(40);  // small units: several per instance
  std::vector<Placement> placed = place(instances, trees, 48, 12.0, 5);
  ClusterSelector selector;
  const std::size_t evaluated = walk_and_compare(instances, placed, 400, 90.0, 3, selector);
  EXPECT_LT(evaluated, 400 * instances.size()) << "some subtrees skipped";
}

TEST(ClusterBvh, CutEqualsLinearPassOnWalksOverBakedTerrain) {
  const std::vector<ClusterHierarchy> tiles{test::baked_terrain(20'000, 20.0, 3.0),
                                            test::baked_terrain(4'000, 8.0, 1.0)};
  ClusterInstances instances;
  std::vector<Placement> placed = place(instances, tiles, 36, 22.0, 9);
  ClusterSelector selector;
  const std::size_t frames = 300;
  const std::size_t evaluated = walk_and_compare(instances, placed, frames, 130.0, 4, selector);
  EXPECT_LT(evaluated, frames * instances.size() / 2) << "most of a walk's scene is skipped";
}

// The eye inside or near a random instance's random cluster sphere, or far; gaze anywhere or at
// a cluster; random motion (as tests/lod/cluster_select_test.cpp's viewers).
TEST(ClusterBvh, CutEqualsLinearPassForViewersInsideSpheres) {
  std::vector<ClusterHierarchy> hs{test::make_tree(tree_specs()[0], 21).h, test::baked_terrain(4'000, 8.0, 1.0)};
  ClusterInstances instances;
  const std::vector<Placement> placed = place(instances, hs, 16, 10.0, 2);
  ClusterSelector selector;
  CutBytes bytes(instances.size()), linear;
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto world_centre = [&]() {
    const auto k = static_cast<std::uint32_t>(static_cast<std::size_t>(u(rng) * double(placed.size())) % placed.size());
    const ClusterInstance& inst = instances.instance(k);
    const ClusterHierarchy& h = instances.hierarchy(inst.hierarchy);
    const std::size_t c = static_cast<std::size_t>(u(rng) * double(h.size())) % h.size();
    const glm::dvec3 local{h.self_center_x_m[c], h.self_center_y_m[c], h.self_center_z_m[c]};
    return inst.pose.translation_m + inst.pose.scale * (inst.pose.rotation * local);
  };
  const auto uv = [&]() { return glm::dvec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5}; };
  for (int frame = 0; frame < 1500; ++frame) {
    Viewer v;
    const double away = u(rng);
    v.eye_position_m = world_centre() + (away < 0.3 ? 0.001 : away < 0.7 ? 2.0 : 30.0) * uv();
    v.gaze_direction = u(rng) < 0.4 ? world_centre() - v.eye_position_m : uv();
    if (!(glm::length(v.gaze_direction) > 0.0)) v.gaze_direction = {0, 0, -1};
    v.eye_velocity_m_s = 2.0 * uv();
    const double turn = u(rng);
    v.head_angular_velocity_rad_s = (turn < 0.6 ? 0.3 : turn < 0.9 ? 4.0 : 8.0) * uv();
    v.gaze_angular_velocity_in_head_rad_s = (u(rng) < 0.2 ? 10.0 : 0.5) * uv();
    v.xi_cpd = 4.0 + 60.0 * u(rng);
    v.scale = 0.3 + 0.7 * u(rng);
    v.tracker_error_deg = 3.0 * u(rng);
    if (u(rng) < 0.3) v.use_size = u(rng) < 0.5, v.use_eccentricity = u(rng) < 0.5, v.use_velocity = u(rng) < 0.5;
    const std::string diff = test::compare_with_linear(v, instances, selector, bytes, linear);
    ASSERT_EQ(diff, "") << "frame " << frame;
  }
}

TEST(ClusterInstances, InstancesShareOneHierarchy) {
  const ClusterHierarchy tile = test::baked_terrain(4'000, 8.0, 1.0);
  ClusterInstances one, many;
  one.add_instance(one.add_hierarchy(tile, 1u << 20), {}, glm::dvec3(0.0));
  for (int k = 0; k < 300; ++k) {
    InstanceTransform pose;
    pose.translation_m = {10.0 * k, 0.0, 0.0};
    const std::uint32_t h = many.add_hierarchy(tile, 1u << 20);  // the same hierarchy each time
    EXPECT_EQ(h, 0u);
    EXPECT_EQ(many.add_instance(h, pose, glm::dvec3(0.0)), static_cast<std::uint32_t>(k));
  }
  EXPECT_EQ(many.hierarchy_count(), 1u);
  EXPECT_EQ(many.size(), 300 * tile.size());
  EXPECT_EQ(many.instance(299).first_cluster, 299 * tile.size());
  // Memory per instance: a pose, not a copy of the records.
  EXPECT_LT(many.memory_bytes(), one.memory_bytes() + 300 * 2 * sizeof(ClusterInstance));
  // Another hierarchy (or the same with another index buffer) is its own.
  ClusterHierarchy other = tile;
  other.self_center_x_m[0] += 1e-3f;
  EXPECT_EQ(many.add_hierarchy(other, 1u << 20), 1u);
  EXPECT_EQ(many.add_hierarchy(tile, 1u << 21), 2u);
  // Refusals leave the store as it was.
  ClusterHierarchy bad = tile;
  bad.parent_error_m[0] = std::nanf("");
  EXPECT_THROW(many.add_hierarchy(bad, 1u << 20), std::invalid_argument);
  InstanceTransform flat;
  flat.scale = 0.0;
  EXPECT_THROW(many.add_instance(0, flat, glm::dvec3(0.0)), std::invalid_argument);
  EXPECT_THROW(many.add_instance(7, {}, glm::dvec3(0.0)), std::out_of_range);
  EXPECT_THROW(many.set_pose(300, {}, glm::dvec3(0.0)), std::out_of_range);
  EXPECT_THROW(many.set_pose(0, {}, glm::dvec3(std::nan(""))), std::invalid_argument);
  EXPECT_EQ(many.hierarchy_count(), 3u);
  EXPECT_EQ(many.instance_count(), 300u);
}

TEST(ClusterSelector, IncrementalBytesEqualFullWrites) {
  std::vector<ClusterHierarchy> hs{test::make_tree(tree_specs()[0], 31).h, test::make_tree(tree_specs()[1], 32).h};
  ClusterInstances instances;
  std::vector<Placement> placed = place(instances, hs, 20, 12.0, 6);
  ClusterSelector kept, fresh;
  CutBytes bytes(instances.size());
  for (std::size_t f = 0; f < 200; ++f) {
    if (f == 120) {  // a new instance: every array grows, and every byte is written again
      instances.add_instance(0, placed[0].pose, glm::dvec3(0.0));
      placed.push_back(placed[0]), placed.back().velocity_m_s = glm::dvec3(0.0);
      bytes = CutBytes(instances.size());
    }
    const bool written_elsewhere = f == 80;
    if (written_elsewhere) std::fill(bytes.drawn.begin(), bytes.drawn.end(), 1);
    const Viewer v = test::walk_viewer(f, 200, 80.0, 7);
    CutBytes once(instances.size());  // often at the address of the last frame's: not incremental
    ASSERT_EQ(kept.select(v, instances, {bytes.drawn, bytes.why, bytes.bits, !written_elsewhere}), "");
    ASSERT_EQ(fresh.select(v, instances, {once.drawn, once.why, once.bits}), "");
    ASSERT_EQ(bytes.drawn, once.drawn) << "frame " << f;
    ASSERT_EQ(bytes.why, once.why) << "frame " << f;
    ASSERT_EQ(bytes.bits, once.bits) << "frame " << f;
    move(instances, placed);
  }
}

TEST(ClusterSelector, RefusesWhatItCannotEvaluate) {
  const ClusterHierarchy tree = test::make_tree(tree_specs()[2], 41).h;
  ClusterInstances instances;
  const std::uint32_t h = instances.add_hierarchy(tree, 3 * tree.size());
  instances.add_instance(h, {}, glm::dvec3(0.0));
  ClusterSelector selector;
  CutBytes bytes(instances.size());
  Viewer bad;
  bad.xi_cpd = 0.0;
  EXPECT_NE(selector.select(bad, instances, {}), "");
  std::vector<std::uint8_t> shorter(instances.size() - 1);
  EXPECT_NE(selector.select(Viewer{}, instances, {shorter, {}, {}}), "");
  EXPECT_NE(select_clusters_local(Viewer{}, instances, {shorter, shorter, {}, {}, {}, {}}), "");
  // A tiny instance far from the eye: the eye's coordinates in its space exceed float range.
  InstanceTransform tiny;
  tiny.scale = 1e-30;
  instances.add_instance(h, tiny, glm::dvec3(0.0));
  Viewer far;
  far.eye_position_m = {1e3, 0.0, 0.0};
  bytes = CutBytes(instances.size());
  EXPECT_NE(selector.select(far, instances, {bytes.drawn, bytes.why, bytes.bits}), "");
  EXPECT_NE(select_clusters_local(far, instances, {bytes.drawn, bytes.why, {}, {}, {}, {}}), "");
  // An empty store selects nothing.
  ClusterInstances none;
  EXPECT_EQ(selector.select(Viewer{}, none, {}), "");
  EXPECT_TRUE(selector.drawn().empty());
}

// Also run under ThreadSanitizer (scripts/setup.sh): the pool's hand-offs and the units' outputs.
TEST(ClusterSelectorThreads, SameCutOnOneTwoAndFourThreads) {
  std::vector<ClusterHierarchy> hs{test::make_tree(tree_specs()[0], 51).h, test::make_tree(tree_specs()[3], 52).h};
  ClusterInstances instances(64);  // several units per instance
  std::vector<Placement> placed = place(instances, hs, 24, 12.0, 10);
  ClusterSelector one(1), two(2, 0), four(4, 0);
  CutBytes b1(instances.size()), b2(instances.size()), b4(instances.size());
  for (std::size_t f = 0; f < 60; ++f) {
    const Viewer v = test::walk_viewer(f, 60, 80.0, 12);
    ASSERT_EQ(one.select(v, instances, {b1.drawn, b1.why, b1.bits}), "");
    ASSERT_EQ(two.select(v, instances, {b2.drawn, b2.why, b2.bits, true}), "");
    ASSERT_EQ(four.select(v, instances, {b4.drawn, b4.why, b4.bits, true}), "");
    for (const ClusterSelector* s : {&two, &four}) {
      ASSERT_TRUE(std::equal(one.drawn().begin(), one.drawn().end(), s->drawn().begin(), s->drawn().end()))
          << "frame " << f << ": the list differs on " << s->threads() << " threads";
      ASSERT_TRUE(std::equal(one.drawn_limited_by().begin(), one.drawn_limited_by().end(),
                             s->drawn_limited_by().begin(), s->drawn_limited_by().end()));
    }
    ASSERT_EQ(b1.drawn, b2.drawn);
    ASSERT_EQ(b1.bits, b4.bits);
    ASSERT_EQ(b2.why, b4.why);
    move(instances, placed);
  }
  EXPECT_EQ(four.threads(), 4u);
}

// The pool itself: every task once per run, over many runs (the workers wait between them), and
// a task's exception rethrown in the caller after the run.
TEST(ClusterSelectorThreads, PoolRunsEveryTaskOnceAndRethrows) {
  ClusterThreadPool pool(3);
  EXPECT_EQ(pool.threads(), 3u);
  std::vector<int> hits(100, 0);
  for (int run = 0; run < 200; ++run) {
    const std::size_t count = static_cast<std::size_t>(run % 7 == 0 ? 1 : 1 + run % 100);
    auto task = [&](std::size_t i, unsigned thread) {
      ASSERT_LT(thread, 3u);
      ++hits[i];
    };
    pool.run(count, task);
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(hits[i], 1) << "run " << run << ", task " << i;
    std::fill(hits.begin(), hits.end(), 0);
  }
  auto failing = [](std::size_t i, unsigned) {
    if (i == 5) throw std::runtime_error("task 5");
  };
  EXPECT_THROW(pool.run(50, failing), std::runtime_error);
  auto fine = [&](std::size_t i, unsigned) { hits[i] = 2; };
  pool.run(10, fine);  // usable after a failed run
  EXPECT_EQ(hits[9], 2);
}

}  // namespace
}  // namespace gazelod::lod
