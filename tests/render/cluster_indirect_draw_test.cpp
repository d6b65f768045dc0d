// SPDX-License-Identifier: Apache-2.0
// FrameRenderer::draw_indirect_count on a GPU-built cut (ClusterSelectPass): a baked terrain's
// cut drawn with one vkCmdDrawIndexedIndirectCount is the image of the same cut drawn one
// vkCmdDrawIndexed per cluster (FrameRenderer::draw, merging off), pixel for pixel. On lavapipe;
// without a Vulkan device the case skips with the reason.
#include "bake/cluster/cluster_build.hpp"
#include "bake/terrain_mesh.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "render/cluster_select_pass.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "tests/render/cluster_select_gpu_fixture.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace gazelod::render {
namespace {

using test::ClusterSelectGpu;

TEST_F(ClusterSelectGpu, IndirectCountDrawsThePerClusterImage) {
  bake::TerrainOptions options;
  options.triangles = 20'000;
  options.size_m = 80.0;
  const bake::GeneratedMesh terrain = bake::terrain_meshes(options).at(0);
  const bake::ClusterBuildResult built = bake::build_cluster_hierarchy(terrain.positions, terrain.indices);
  const lod::ClusterHierarchy& h = built.hierarchy;

  // The mesh library wants positions in a unit frame that a centre and radius place: here the
  // box's centre and the farthest corner's distance.
  glm::vec3 lo(terrain.positions[0], terrain.positions[1], terrain.positions[2]), hi = lo;
  for (std::size_t v = 0; v < terrain.positions.size(); v += 3) {
    const glm::vec3 p(terrain.positions[v], terrain.positions[v + 1], terrain.positions[v + 2]);
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = glm::length(hi - centre);
  std::vector<glm::vec3> unit;
  for (std::size_t v = 0; v < terrain.positions.size(); v += 3)
    unit.push_back((glm::vec3(terrain.positions[v], terrain.positions[v + 1], terrain.positions[v + 2]) - centre) /
                   radius);
  MeshLibrary meshes;
  const std::uint32_t first = meshes.add_cluster_mesh(unit, built.indices, h.first_index, h.index_count);
  meshes.upload(ctx());
  std::vector<ClusterDrawRange> ranges;
  for (std::size_t c = 0; c < h.size(); ++c) {
    const MeshRange& r = meshes.range(first + static_cast<std::uint32_t>(c));
    ranges.push_back({r.first_index, r.index_count, r.vertex_offset});
  }

  lod::ClusterStore store;
  store.add_mesh(h, {}, glm::dvec3(0.0), built.indices.size());
  ClusterSelectPass pass(ctx(), store.view(), ranges);
  OffscreenTarget target(ctx(), 320, 240);
  FrameRenderer renderer(ctx(), meshes, target.target());
  renderer.set_merge_draws(false);

  lod::Viewer viewer;
  viewer.eye_position_m = {0.0, 1.7, 30.0};
  viewer.gaze_direction = {0.1, -0.25, -1.0};
  viewer.xi_cpd = 15.0;
  EyeView view;
  view.pose.position_m = viewer.eye_position_m;
  view.pose.orientation = glm::angleAxis(-0.3, glm::dvec3{1, 0, 0}) * glm::angleAxis(0.2, glm::dvec3{0, 1, 0});
  view.fov = {-0.6, 0.5, 0.45, -0.5};

  pass.run(viewer, &view);
  std::vector<std::uint8_t> gpu(h.size());
  pass.read_drawn(gpu);
  const std::vector<std::uint8_t> cpu = test::cpu_cut(viewer, store.view());
  ASSERT_EQ(gpu, cpu);
  std::vector<DrawItem> items;
  for (std::size_t c = 0; c < h.size(); ++c)
    if (cpu[c]) items.push_back({centre, radius, first + static_cast<std::uint32_t>(c), 0});
  ASSERT_GT(items.size(), 20u);
  renderer.draw(0, view, items);
  const RgbaImage per_cluster = renderer.read_back(0);
  EXPECT_GT(renderer.draw_commands_last_frame(), 20u);

  renderer.draw_indirect_count(
      0, view, {centre, radius, 0, pass.commands_buffer(), 0, pass.count_buffer(), 0, pass.command_capacity()});
  const RgbaImage indirect = renderer.read_back(0);
  EXPECT_EQ(renderer.draw_commands_last_frame(), 1u);
  ASSERT_EQ(indirect.pixels.size(), per_cluster.pixels.size());
  std::size_t differ = 0, covered = 0;
  for (std::size_t i = 0; i < indirect.pixels.size(); i += 4) {
    differ += !std::equal(&indirect.pixels[i], &indirect.pixels[i] + 4, &per_cluster.pixels[i]);
    covered += !std::equal(&indirect.pixels[i], &indirect.pixels[i] + 3, &indirect.pixels[0]);
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(covered, 320u * 240u / 10);  // the terrain fills part of the view
  // Fewer commands than drawn clusters: those outside the view were culled on the GPU.
  EXPECT_LT(pass.read_draw_count(), static_cast<std::uint32_t>(std::count(gpu.begin(), gpu.end(), 1)));
}

}  // namespace
}  // namespace gazelod::render
