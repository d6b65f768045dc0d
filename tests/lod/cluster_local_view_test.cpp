// SPDX-License-Identifier: Apache-2.0
// The selection in an instance's own space (lod/cluster/cluster_local_view.hpp): the viewer's
// transform, the same cut as ClusterStore's world-space pass where the transform is exact, and
// on the scenario walks (sim/scenarios/) over a baked terrain tiled as instances: how often the
// local cut differs from the world-space one, in which direction (printed; bench/RESULTS.md
// records it), and the bounding-hierarchy selection equal to the local pass on every frame.
#include "lod/cluster/cluster_local_view.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/cluster/cluster_selector.hpp"
#include "tests/lod/cluster_instance_scene.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace gazelod::lod {
namespace {

TEST(ClusterLocalView, MovesTheViewerIntoTheInstanceSpace) {
  ClusterInstance inst;
  inst.pose.rotation = glm::angleAxis(std::numbers::pi / 2, glm::dvec3{0, 1, 0});  // local +x -> world -z
  inst.pose.translation_m = {10.0, 0.0, 0.0};
  inst.pose.scale = 2.0;
  inst.velocity_m_s = {0.0, 0.0, -4.0};
  Viewer w;
  w.eye_position_m = {10.0, 0.0, -6.0};  // local (3, 0, 0)
  w.eye_velocity_m_s = {0.0, 0.0, -2.0};
  w.gaze_direction = {0.0, 0.0, -1.0};
  w.head_angular_velocity_rad_s = {0.0, 1.0, 0.0};
  LocalView l;
  ASSERT_EQ(local_view(w, inst, l), "");
  const auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-12; };
  EXPECT_TRUE(near(l.viewer.eye_position_m, {3.0, 0.0, 0.0}));
  EXPECT_TRUE(near(l.viewer.eye_velocity_m_s, {1.0, 0.0, 0.0}));  // 2 m/s along -z, halved
  EXPECT_TRUE(near(l.mesh_velocity, {2.0, 0.0, 0.0}));
  EXPECT_TRUE(near(l.viewer.gaze_direction, {1.0, 0.0, 0.0}));
  EXPECT_TRUE(near(l.viewer.head_angular_velocity_rad_s, {0.0, 1.0, 0.0}));  // about the same axis
  // A tiny instance: the eye (6 m away) beyond float range in its units, or (at its origin) a
  // velocity beyond double range.
  ClusterInstance tiny = inst;
  tiny.pose.scale = 1e-300;
  EXPECT_NE(local_view(w, tiny, l), "");
  Viewer at_origin = w;
  at_origin.eye_position_m = tiny.pose.translation_m;
  at_origin.eye_velocity_m_s = {1e10, 0.0, 0.0};
  EXPECT_NE(local_view(at_origin, tiny, l), "");
}

// With the identity pose the world records are the local ones bit for bit, so both passes agree
// exactly, per-criterion cuts included.
TEST(ClusterLocalView, IdentityPoseGivesTheWorldSpaceCut) {
  test::TreeSpec spec;
  spec.grid = true, spec.levels = 5, spec.outputs_per_group = 2;
  const ClusterHierarchy h = test::make_tree(spec, 3).h;
  ClusterInstances instances;
  ClusterStore store;
  const glm::dvec3 vel{0.5, 0.0, -0.3};
  instances.add_instance(instances.add_hierarchy(h, 3 * h.size()), {}, vel);
  store.add_mesh(h, {}, vel, 3 * h.size());
  const std::size_t n = h.size();
  std::vector<std::uint8_t> a[6], b[6];
  for (auto* set : {&a, &b})
    for (auto& v : *set) v.assign(n, 0);
  for (std::size_t f = 0; f < 200; ++f) {
    const Viewer v = test::walk_viewer(f, 200, 20.0, 5);
    ASSERT_EQ(select_clusters_local(v, instances, {a[0], a[1], a[2], a[3], a[4], a[5], {}}), "");
    ASSERT_EQ(select_clusters(v, store.view(), {b[0], b[1], b[2], b[3], b[4], b[5], {}}), "");
    for (int k = 0; k < 6; ++k) ASSERT_EQ(a[k], b[k]) << "frame " << f << ", output " << k;
  }
}

test::Disagreement walk_scenario(const std::string& file, std::size_t every) {
  const ClusterHierarchy tile = test::baked_terrain(20'000, 40.0, 6.0);
  ClusterInstances instances;
  ClusterStore store;
  const std::uint32_t h = instances.add_hierarchy(tile, 1u << 22);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      InstanceTransform pose;  // tiles of a terrain as glTF nodes: most unrotated, some turned or scaled
      pose.translation_m = {40.0 * (i - 3.5), 0.0, 40.0 * (j - 3.5)};
      const int k = 8 * i + j;
      if (k % 5 == 0) pose.rotation = glm::angleAxis(0.5 * std::numbers::pi * (k % 4) + 0.01, glm::dvec3{0, 1, 0});
      if (k % 7 == 0) pose.scale = 1.5;
      instances.add_instance(h, pose, glm::dvec3(0.0));
      store.add_mesh(tile, pose, glm::dvec3(0.0), 1u << 22);
    }
  sim::Simulator simulator(sim::load_scenario_file(std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/" + file));
  const std::size_t n = instances.size();
  std::vector<std::uint32_t> flags(store.record_count());
  test::CutBytes bytes(n), local, world(n);
  ClusterSelector selector;
  test::Disagreement d;
  const double step_ns = 1e9 / simulator.scenario().frame_rate_hz;
  for (std::size_t f = 0; double(f) * step_ns < double(simulator.duration_ns()); f += every) {
    const Viewer v = test::scenario_viewer(simulator, static_cast<std::int64_t>(double(f) * step_ns), 20.0);
    EXPECT_EQ(test::compare_with_linear(v, instances, selector, bytes, local), "") << file << " frame " << f;
    EXPECT_EQ(select_clusters(v, store.view(), {world.drawn, world.why, {}, {}, {}, world.bits, flags}), "");
    d.add(local, world);
  }
  std::printf(
      "%s: %zu frames x %zu clusters: record decisions differing local vs world: %zu coarser, %zu finer "
      "of %zu; clusters drawn differently: %zu\n",
      file.c_str(), d.frames, n, d.local_coarser, d.local_finer, d.decisions, d.drawn_differ);
  return d;
}

TEST(ClusterLocalView, CutMatchesWorldSpaceOnScenarioWalks) {
  for (const auto& [file, every] : {std::pair<std::string, std::size_t>{"terrain-walk.json", 6},
                                    {"fast_turn.json", 1},
                                    {"default-120hz-50ms.json", 2}}) {
    const test::Disagreement d = walk_scenario(file, every);
    ASSERT_GT(d.frames, 100u);
    // Both passes are conservative against the exact rule; they may round differently only
    // within the kernel's slack of a threshold.
    EXPECT_LT(double(d.local_coarser + d.local_finer), 1e-4 * double(d.decisions)) << file;
    RecordProperty(file + "_differing", std::to_string(d.local_coarser + d.local_finer));
  }
}

}  // namespace
}  // namespace gazelod::lod
