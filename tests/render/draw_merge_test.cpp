// SPDX-License-Identifier: Apache-2.0
// FrameRenderer's draw merging (set_merge_draws): consecutive items under the same centre,
// radius and tint whose index ranges follow each other become one draw, and the image is the
// unmerged one pixel for pixel; with multiDrawIndirect (set_multi_draw), one indirect command
// per run of one tint, again the same image. On lavapipe; without a Vulkan device the cases skip with the
// reason.
#include "render/device_context.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_error.hpp"
#include "render/sphere_mesh.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace gazelod::render {
namespace {

constexpr std::uint32_t kTrianglesPerCluster = 24;

class RenderDrawMerge : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      device_ = std::make_unique<OffscreenDevice>();
    } catch (const NoVulkanDevice& e) {
      GAZELOD_SKIP_OR_FAIL("no Vulkan device: " << e.what());
    }
    // A sphere of ~4,000 triangles cut into clusters of 24 triangles in index order, like a
    // hierarchy's clusters back to back; a stand-in sphere first, so the block does not start
    // at index 0.
    sphere_ = meshes_.add_sphere(80);
    const MeshData m = make_sphere(sphere_resolution(4000));
    for (std::uint32_t f = 0; f < m.indices.size(); f += 3 * kTrianglesPerCluster) {
      first_index_.push_back(f);
      index_count_.push_back(
          std::min<std::uint32_t>(3 * kTrianglesPerCluster, static_cast<std::uint32_t>(m.indices.size()) - f));
    }
    first_ = meshes_.add_cluster_mesh(m.positions, m.indices, first_index_, index_count_);
    meshes_.upload(device_->context());
  }
  void TearDown() override {
    if (device_)
      for (const std::string& m : device_->validation_messages()) ADD_FAILURE() << "validation: " << m;
  }

  // A 90 x 90 deg view from the origin down -Z, 256 x 256 pixels.
  static EyeView view() {
    EyeView v;
    const double q = std::atan(1.0);
    v.fov = {-q, q, q, -q};
    return v;
  }

  std::size_t clusters() const { return first_index_.size(); }

  std::unique_ptr<OffscreenDevice> device_;
  MeshLibrary meshes_;
  std::uint32_t sphere_ = 0, first_ = 0;
  std::vector<std::uint32_t> first_index_, index_count_;
};

TEST_F(RenderDrawMerge, AMixedCutIsTheSameImageWithFarFewerDraws) {
  // Depths in runs of 10 clusters (0, 1, 2, 0, ...), every 13th cluster left out, and a
  // stand-in sphere in front between two runs: runs break at a tint change, a gap and other
  // constants.
  const glm::vec3 centre(0.0f, 0.0f, -1.5f);
  std::vector<DrawItem> items;
  for (std::size_t c = 0; c < clusters(); ++c) {
    if (c % 13 == 5) continue;
    items.push_back({centre, 1.0f, first_ + static_cast<std::uint32_t>(c), static_cast<std::uint32_t>((c / 10) % 3)});
    if (c == clusters() / 2) items.push_back({{0.15f, 0.1f, -0.35f}, 0.08f, sphere_, 4});
  }
  OffscreenTarget target(device_->context(), 256, 256);
  FrameRenderer renderer(device_->context(), meshes_, target.target());
  renderer.set_merge_draws(false);
  renderer.draw(0, view(), items);
  const RgbaImage unmerged = renderer.read_back(0);
  const std::uint64_t unmerged_triangles = renderer.triangles_last_frame();
  EXPECT_EQ(renderer.draws_last_frame(), items.size());

  renderer.set_merge_draws(true);
  renderer.set_multi_draw(false);
  renderer.draw(0, view(), items);
  const RgbaImage merged = renderer.read_back(0);
  EXPECT_EQ(renderer.triangles_last_frame(), unmerged_triangles);
  // Each run of 10 splits at most once at a left-out cluster; the sphere adds itself and a split.
  const std::uint32_t merged_draws = renderer.draws_last_frame();
  EXPECT_LE(merged_draws, 2 * (clusters() / 10 + 1) + 2);
  EXPECT_LT(3 * merged_draws, items.size());
  EXPECT_EQ(renderer.draw_commands_last_frame(), merged_draws);
  ASSERT_TRUE(device_->context().multi_draw_indirect) << "lavapipe has multiDrawIndirect";

  // The same draws as one indirect command per run of one tint (and one for the sphere).
  renderer.set_multi_draw(true);
  ASSERT_TRUE(renderer.multi_draw_active());
  renderer.draw(0, view(), items);
  const RgbaImage indirect = renderer.read_back(0);
  EXPECT_EQ(renderer.triangles_last_frame(), unmerged_triangles);
  EXPECT_EQ(renderer.draws_last_frame(), merged_draws);
  EXPECT_LE(renderer.draw_commands_last_frame(), clusters() / 10 + 1 + 2);
  EXPECT_EQ(indirect.pixels, merged.pixels);

  ASSERT_EQ(merged.pixels.size(), unmerged.pixels.size());
  const auto background = merged.at(0, 0);
  std::size_t differing = 0, lit = 0;
  for (std::size_t i = 0; i < merged.pixels.size(); i += 4) {
    if (merged.pixels[i] != unmerged.pixels[i] || merged.pixels[i + 1] != unmerged.pixels[i + 1] ||
        merged.pixels[i + 2] != unmerged.pixels[i + 2] || merged.pixels[i + 3] != unmerged.pixels[i + 3])
      ++differing;
    if (merged.pixels[i] != background[0] || merged.pixels[i + 1] != background[1] ||
        merged.pixels[i + 2] != background[2])
      ++lit;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(lit, 256u * 256u / 4);  // the scene covers the image: the comparison means something
}

TEST_F(RenderDrawMerge, OnlyFollowingRangesUnderTheSameConstantsMerge) {
  OffscreenTarget target(device_->context(), 64, 64);
  FrameRenderer renderer(device_->context(), meshes_, target.target());
  const glm::vec3 c(0.0f, 0.0f, -3.0f);
  const auto draws = [&](std::vector<DrawItem> items) {
    renderer.draw(0, view(), items);
    return renderer.draws_last_frame();
  };
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {c, 1.0f, first_ + 1, 0}, {c, 1.0f, first_ + 2, 0}}), 1u);
  EXPECT_EQ(renderer.triangles_last_frame(), 3u * kTrianglesPerCluster);
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {c, 1.0f, first_ + 1, 1}}), 2u);   // tint
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {c, 1.0f, first_ + 2, 0}}), 2u);   // a gap
  EXPECT_EQ(draws({{c, 1.0f, first_ + 1, 0}, {c, 1.0f, first_, 0}}), 2u);   // backwards
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {c, 1.01f, first_ + 1, 0}}), 2u);  // radius
  // A culled item (behind the eye) between two following ranges does not split them.
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {-c, 1.0f, first_ + 5, 0}, {c, 1.0f, first_ + 1, 0}}), 1u);
  // The stand-in sphere ends right where cluster 0 starts, but in another vertex block.
  EXPECT_EQ(draws({{c, 1.0f, sphere_, 0}, {c, 1.0f, first_, 0}}), 2u);
  // Indirect: the two ranges under one tint are one command, a tint change starts another.
  renderer.set_multi_draw(true);
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {c, 1.0f, first_ + 2, 0}, {c, 1.0f, first_ + 3, 1}}), 3u);
  EXPECT_EQ(renderer.draw_commands_last_frame(), 2u);
  renderer.set_merge_draws(false);
  EXPECT_EQ(draws({{c, 1.0f, first_, 0}, {c, 1.0f, first_ + 1, 0}, {c, 1.0f, first_ + 2, 0}}), 3u);
  EXPECT_EQ(renderer.draw_commands_last_frame(), 3u);
}

}  // namespace
}  // namespace gazelod::render
