// SPDX-License-Identifier: Apache-2.0
// MeshLibrary::add_cluster_mesh: one mesh id per cluster over one shared vertex block (ranges,
// bad input), and on lavapipe a cut drawn cluster by cluster, each in its depth's tint. Without
// a Vulkan device the drawing cases skip with the reason.
#include "render/device_context.hpp"
#include "render/frame_renderer.hpp"
#include "render/lod_palette.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_error.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace gazelod::render {
namespace {

// A cap of the unit sphere facing +Z (so the radial shading lights it fully towards a viewer on
// +Z): centre C and four corners; cluster 0 the two triangles left of x = 0, cluster 1 the two
// right of it, counter-clockwise seen from +Z.
struct Cap {
  std::vector<glm::vec3> positions{
      {0.0f, 0.0f, 1.0f}, {0.6f, 0.0f, 0.8f}, {0.0f, 0.6f, 0.8f}, {-0.6f, 0.0f, 0.8f}, {0.0f, -0.6f, 0.8f}};
  std::vector<std::uint32_t> indices{0, 2, 3, 0, 3, 4,   // left: C U L, C L D
                                     0, 1, 2, 0, 4, 1};  // right: C R U, C D R
  std::vector<std::uint32_t> first{0, 6}, count{6, 6};
};

TEST(ClusterMeshLibrary, OneMeshPerClusterOverOneVertexBlock) {
  MeshLibrary lib;
  const std::uint32_t sphere = lib.add_sphere(80);
  const Cap cap;
  const std::uint32_t first = lib.add_cluster_mesh(cap.positions, cap.indices, cap.first, cap.count);
  ASSERT_EQ(lib.size(), 3u);
  EXPECT_EQ(first, sphere + 1);
  // Copies: adding meshes below may move the library's ranges.
  const MeshRange sphere_range = lib.range(sphere);
  const MeshRange left = lib.range(first);
  const MeshRange right = lib.range(first + 1);
  // Both clusters index the same block, which follows the sphere's vertices and indices.
  EXPECT_EQ(left.vertex_offset, right.vertex_offset);
  EXPECT_GT(left.vertex_offset, sphere_range.vertex_offset);
  EXPECT_EQ(left.first_index, sphere_range.first_index + sphere_range.index_count);
  EXPECT_EQ(right.first_index, left.first_index + 6);
  EXPECT_EQ(left.triangles(), 2u);
  EXPECT_EQ(right.triangles(), 2u);
  // A second cluster mesh gets its own block.
  const std::uint32_t again = lib.add_cluster_mesh(cap.positions, cap.indices, cap.first, cap.count);
  EXPECT_EQ(again, first + 2);
  EXPECT_EQ(lib.range(again).vertex_offset, left.vertex_offset + 5);
  EXPECT_EQ(lib.range(again).first_index, right.first_index + 6);
}

TEST(ClusterMeshLibrary, BadInputIsRefusedAndAddsNothing) {
  MeshLibrary lib;
  const Cap cap;
  const auto refused = [&](std::span<const glm::vec3> p, std::span<const std::uint32_t> i,
                           std::span<const std::uint32_t> f, std::span<const std::uint32_t> c,
                           const std::string& says) {
    try {
      lib.add_cluster_mesh(p, i, f, c);
      ADD_FAILURE() << "accepted; expected: " << says;
    } catch (const RenderError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
    EXPECT_EQ(lib.size(), 0u);
  };
  refused(cap.positions, cap.indices, {}, {}, "no clusters");
  const std::vector<std::uint32_t> one{0};
  refused(cap.positions, cap.indices, cap.first, one, "2 first indices but 1 index counts");
  const std::vector<std::uint32_t> past{6, 9};
  refused(cap.positions, cap.indices, cap.first, past, "cluster 1 ends at index 15, past the 12 indices");
  const std::vector<std::uint32_t> partial{6, 5};
  refused(cap.positions, cap.indices, cap.first, partial, "cluster 1 has 5 indices, not a multiple of 3");
  // A first index near 2^32: the end is computed without wrapping.
  const std::vector<std::uint32_t> huge{0, 0xFFFFFFFDu};
  refused(cap.positions, cap.indices, huge, cap.count, "past the 12 indices");
  std::vector<std::uint32_t> wild = cap.indices;
  wild[7] = 5;
  refused(cap.positions, wild, cap.first, cap.count, "index 7 = 5 is out of range (5 vertices)");
  std::vector<glm::vec3> nan_at_3 = cap.positions;
  nan_at_3[3].y = NAN;
  refused(nan_at_3, cap.indices, cap.first, cap.count, "position 3 is not finite");
}

class ClusterMeshRender : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      device_ = std::make_unique<OffscreenDevice>();
    } catch (const NoVulkanDevice& e) {
      GAZELOD_SKIP_OR_FAIL("no Vulkan device: " << e.what());
    }
    const Cap cap;
    first_ = meshes_.add_cluster_mesh(cap.positions, cap.indices, cap.first, cap.count);
    meshes_.upload(device_->context());
  }
  void TearDown() override {
    if (device_)
      for (const std::string& m : device_->validation_messages()) ADD_FAILURE() << "validation: " << m;
  }

  // Symmetric 90 deg x 90 deg view from the origin down -Z: pixel (x, y) of a 200 x 200 image
  // looks along tangent ((x - 100) / 100, (100 - y) / 100).
  static EyeView view() {
    EyeView v;
    const double q = std::atan(1.0);
    v.fov = {-q, q, q, -q};
    return v;
  }

  std::unique_ptr<OffscreenDevice> device_;
  MeshLibrary meshes_;
  std::uint32_t first_ = 0;
};

TEST_F(ClusterMeshRender, EachDrawnClusterShowsItsOwnTrianglesInItsDepthTint) {
  OffscreenTarget target(device_->context(), 200, 200);
  FrameRenderer renderer(device_->context(), meshes_, target.target());
  // The cap 4 m ahead with radius 1: its tip at z = -3, its corners at +-0.6 m, z = -3.2
  // (tangent 0.19, 19 px). Cluster 0 (left) at depth 0, cluster 1 (right) at depth 2.
  const DrawItem both[] = {{{0.0f, 0.0f, -4.0f}, 1.0f, first_, 0}, {{0.0f, 0.0f, -4.0f}, 1.0f, first_ + 1, 2}};
  renderer.draw(0, view(), both);
  RgbaImage img = renderer.read_back(0);
  EXPECT_EQ(nearest_lod(img.rgb(94, 98)), 0);
  EXPECT_EQ(nearest_lod(img.rgb(106, 98)), 2);
  EXPECT_EQ(nearest_lod(img.rgb(130, 100)), -1);  // beyond the right corner: background
  EXPECT_EQ(renderer.triangles_last_frame(), 4u);

  // Only the right cluster: the left half is background, the right half keeps its tint.
  renderer.draw(0, view(), std::span(&both[1], 1));
  img = renderer.read_back(0);
  EXPECT_EQ(nearest_lod(img.rgb(94, 98)), -1);
  EXPECT_EQ(nearest_lod(img.rgb(106, 98)), 2);
  EXPECT_EQ(renderer.triangles_last_frame(), 2u);
}

// Per-cluster culling (FrameRenderer::set_cull_ranges): a strip of 10 one-quad clusters across
// x = -0.4..0.4 at z = 0.9 in the unit frame (inside the unit sphere, facing +Z so the radial
// shading lights it), 4 m ahead, seen through a 0.1 rad wide view (|x| < 0.2 m there). The
// clusters whose own sphere is outside are not submitted, and the image is the one drawn with
// every cluster submitted.
TEST_F(ClusterMeshRender, ClustersOutsideTheViewAreNotSubmittedAndTheImageIsTheSame) {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices, first, count;
  for (int q = 0; q < 10; ++q) {
    const float x0 = -0.4f + 0.08f * static_cast<float>(q), x1 = x0 + 0.08f;
    const auto v = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), {{x0, -0.04f, 0.9f}, {x1, -0.04f, 0.9f}, {x1, 0.04f, 0.9f}, {x0, 0.04f, 0.9f}});
    first.push_back(static_cast<std::uint32_t>(indices.size()));
    indices.insert(indices.end(), {v, v + 1, v + 2, v, v + 2, v + 3});  // counter-clockwise from +Z
    count.push_back(6);
  }
  MeshLibrary strip;
  const std::uint32_t id = strip.add_cluster_mesh(positions, indices, first, count);
  strip.upload(device_->context());
  // The bound of cluster 0 (x -0.4..-0.32): the sphere around its box.
  EXPECT_NEAR(strip.range(id).bound_center_unit.x, -0.36f, 1e-6f);
  EXPECT_NEAR(strip.range(id).bound_center_unit.z, 0.9f, 1e-6f);
  EXPECT_NEAR(strip.range(id).bound_radius_unit, std::sqrt(0.0032f), 1e-5f);

  std::vector<DrawItem> items;
  for (std::uint32_t c = 0; c < 10; ++c) items.push_back({{0.0f, 0.0f, -4.9f}, 1.0f, id + c, c % 3});
  EyeView narrow;
  narrow.fov = {-0.05, 0.05, 0.05, -0.05};
  OffscreenTarget target(device_->context(), 64, 64);
  FrameRenderer renderer(device_->context(), strip, target.target());
  renderer.set_cull_ranges(false);
  renderer.draw(0, narrow, items);
  const RgbaImage all = renderer.read_back(0);
  EXPECT_EQ(renderer.triangles_last_frame(), 20u);
  renderer.set_cull_ranges(true);
  renderer.draw(0, narrow, items);
  const RgbaImage culled = renderer.read_back(0);
  // Clusters 2..7: 3..6 in the view, 2 and 7 reaching its edge; 0, 1, 8, 9 culled.
  EXPECT_EQ(renderer.triangles_last_frame(), 12u);
  EXPECT_EQ(culled.pixels, all.pixels);
  // Not an empty picture: clusters 4 and 5 on the middle row in their tints, background above.
  EXPECT_EQ(nearest_lod(culled.rgb(25, 32)), 4 % 3);
  EXPECT_EQ(nearest_lod(culled.rgb(38, 32)), 5 % 3);
  EXPECT_EQ(nearest_lod(culled.rgb(32, 4)), -1);
}

}  // namespace
}  // namespace gazelod::render
