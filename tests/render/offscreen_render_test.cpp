// SPDX-License-Identifier: Apache-2.0
// Offscreen rendering on lavapipe: an object lands where the hand-computed projection says,
// in its LOD tint, with depth, in every supported target format. Without a Vulkan device
// every case skips with the reason (never passes silently).
#include "render/device_context.hpp"
#include "render/frame_renderer.hpp"
#include "render/lod_palette.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/png_io.hpp"
#include "render/render_error.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace gazelod::render {
namespace {

constexpr std::uint32_t kWidth = 300, kHeight = 120;

// Asymmetric FOV with tangents left -1, right 0.5, up 0.5, down -1 (see camera_test.cpp):
// the direction (0.25, 0, -1) lands on pixel (250, 40).
EyeView asymmetric_view() {
  EyeView v;
  v.fov = {-std::atan(1.0), std::atan(0.5), std::atan(0.5), -std::atan(1.0)};
  return v;
}

// |a - b| per channel, in 8-bit steps.
float max_channel_diff(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = glm::abs(a - b) * 255.0f;
  return std::max({d.r, d.g, d.b});
}

class OffscreenRender : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      device_ = std::make_unique<OffscreenDevice>();
    } catch (const NoVulkanDevice& e) {
      GAZELOD_SKIP_OR_FAIL("no Vulkan device: " << e.what());
    }
    sphere_ = meshes_.add_sphere(5000);
    small_ = meshes_.add_sphere(80);
    meshes_.upload(device_->context());
  }
  void TearDown() override {
    if (device_) {
      for (const std::string& m : device_->validation_messages()) ADD_FAILURE() << "validation: " << m;
    }
  }
  const DeviceContext& ctx() const { return device_->context(); }

  std::unique_ptr<OffscreenDevice> device_;
  MeshLibrary meshes_;
  std::uint32_t sphere_ = 0, small_ = 0;
};

TEST_F(OffscreenRender, SphereAtKnownDirectionHasItsLodColourAtTheProjectedCentre) {
  OffscreenTarget target(ctx(), kWidth, kHeight);
  FrameRenderer renderer(ctx(), meshes_, target.target());
  // 4 m ahead, 1 m right: direction (0.25, 0, -1). Radius 0.3 m covers ~0.075 rad ~ 15 px.
  const DrawItem item{{1.0f, 0.0f, -4.0f}, 0.3f, sphere_, 3};
  renderer.draw(0, asymmetric_view(), std::span(&item, 1));
  const RgbaImage img = renderer.read_back(0);
  ASSERT_EQ(img.width, kWidth);
  ASSERT_EQ(img.height, kHeight);
  // The surface point at the projected centre faces the eye: full headlight, exact tint.
  EXPECT_LE(max_channel_diff(img.rgb(250, 40), lod_colour(3)), 2.0f);
  EXPECT_EQ(nearest_lod(img.rgb(250, 40)), 3);
  // Corners and a point well outside the disc are background.
  for (auto [x, y] : {std::pair{0u, 0u}, {kWidth - 1, 0u}, {0u, kHeight - 1}, {kWidth - 1, kHeight - 1}, {200u, 40u}})
    EXPECT_LE(max_channel_diff(img.rgb(x, y), background_colour()), 1.0f) << x << "," << y;
  // Alpha is opaque everywhere we looked.
  EXPECT_EQ(img.at(250, 40)[3], 255);
  EXPECT_EQ(renderer.triangles_last_frame(), meshes_.range(sphere_).triangles());
}

TEST_F(OffscreenRender, DepthKeepsTheNearerObjectInFront) {
  OffscreenTarget target(ctx(), kWidth, kHeight);
  FrameRenderer renderer(ctx(), meshes_, target.target());
  // Same direction (0.25, 0, -1): far big sphere drawn after the near small one.
  const DrawItem items[] = {{{0.5f, 0.0f, -2.0f}, 0.1f, sphere_, 0}, {{2.0f, 0.0f, -8.0f}, 2.0f, small_, 5}};
  renderer.draw(0, asymmetric_view(), items);
  const RgbaImage img = renderer.read_back(0);
  EXPECT_EQ(nearest_lod(img.rgb(250, 40)), 0);
  // 80 px per unit tangent vertically: the near sphere (0.1 m at 2.06 m) spans ~4 px, the far
  // one (2 m at 8.25 m) ~20 px, so 8 px below the centre only the far one shows.
  EXPECT_EQ(nearest_lod(img.rgb(250, 40 + 8)), 5);
  EXPECT_EQ(renderer.triangles_last_frame(),
            std::uint64_t{meshes_.range(sphere_).triangles()} + meshes_.range(small_).triangles());
}

TEST_F(OffscreenRender, ZeroObjectsGiveOnlyBackground) {
  OffscreenTarget target(ctx(), 64, 48, 2);
  FrameRenderer renderer(ctx(), meshes_, target.target());
  renderer.draw(1, asymmetric_view(), {});
  const RgbaImage img = renderer.read_back(1);
  for (std::uint32_t y = 0; y < img.height; ++y)
    for (std::uint32_t x = 0; x < img.width; ++x)
      ASSERT_LE(max_channel_diff(img.rgb(x, y), background_colour()), 1.0f) << x << "," << y;
  EXPECT_EQ(renderer.triangles_last_frame(), 0u);
  EXPECT_THROW(renderer.read_back(0), RenderError);
  // Objects only behind the eye or outside the FOV are culled, not submitted.
  const DrawItem outside[] = {{{0.0f, 0.0f, 4.0f}, 0.5f, sphere_, 0}, {{-10.0f, 0.0f, -2.0f}, 0.5f, sphere_, 0}};
  renderer.draw(1, asymmetric_view(), outside);
  EXPECT_EQ(renderer.triangles_last_frame(), 0u);
  EXPECT_EQ(nearest_lod(renderer.read_back(1).rgb(32, 24)), -1);  // never drawn: layout still undefined
}

TEST_F(OffscreenRender, SwapchainLikeFormatsGiveTheSameColours) {
  // OpenXR runtimes hand out sRGB and BGRA swapchains; the tint must read back the same.
  for (VkFormat format : {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_B8G8R8A8_SRGB}) {
    OffscreenTarget target(ctx(), kWidth, kHeight, 1, format);
    FrameRenderer renderer(ctx(), meshes_, target.target());
    const DrawItem item{{1.0f, 0.0f, -4.0f}, 0.3f, sphere_, 1};
    renderer.draw(0, asymmetric_view(), std::span(&item, 1));
    const RgbaImage img = renderer.read_back(0);
    EXPECT_LE(max_channel_diff(img.rgb(250, 40), lod_colour(1)), 3.0f) << format;
    EXPECT_LE(max_channel_diff(img.rgb(0, 0), background_colour()), 2.0f) << format;
  }
}

TEST_F(OffscreenRender, RedrawingTheSameImageAndSkippingBadItems) {
  OffscreenTarget target(ctx(), kWidth, kHeight);
  FrameRenderer renderer(ctx(), meshes_, target.target());
  const DrawItem first{{1.0f, 0.0f, -4.0f}, 0.3f, sphere_, 2};
  renderer.draw(0, asymmetric_view(), std::span(&first, 1));
  // Second frame into the same image (now in COLOR_ATTACHMENT_OPTIMAL): the old one is gone;
  // a NaN centre and a zero radius are skipped, not drawn.
  const DrawItem second[] = {{{NAN, 0.0f, -4.0f}, 0.3f, sphere_, 4},
                             {{1.0f, 0.0f, -4.0f}, 0.0f, sphere_, 4},
                             {{-2.0f, 0.0f, -4.0f}, 0.3f, small_, 6}};
  renderer.draw(0, asymmetric_view(), second);
  const RgbaImage img = renderer.read_back(0);
  EXPECT_EQ(nearest_lod(img.rgb(250, 40)), -1);
  // (-0.5, 0, -1): x = (-0.5 + 1) / 1.5 * 300 = 100.
  EXPECT_EQ(nearest_lod(img.rgb(100, 40)), 6);
  EXPECT_EQ(renderer.triangles_last_frame(), meshes_.range(small_).triangles());
  const DrawItem bad{{0.0f, 0.0f, -4.0f}, 0.3f, 99, 0};
  EXPECT_THROW(renderer.draw(0, asymmetric_view(), std::span(&bad, 1)), RenderError);
  EXPECT_THROW(renderer.draw(1, asymmetric_view(), {}), RenderError);
}

TEST_F(OffscreenRender, FrameSavedAsPngReadsBackIdentically) {
  OffscreenTarget target(ctx(), kWidth, kHeight);
  FrameRenderer renderer(ctx(), meshes_, target.target());
  const DrawItem item{{1.0f, 0.0f, -4.0f}, 0.3f, sphere_, 4};
  renderer.draw(0, asymmetric_view(), std::span(&item, 1));
  const RgbaImage img = renderer.read_back(0);
  const auto file =
      std::filesystem::temp_directory_path() /
      ("gazelod_render_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".png");
  write_png(file, img);
  const RgbaImage back = read_png(file);
  std::filesystem::remove(file);
  EXPECT_EQ(back.width, img.width);
  EXPECT_EQ(back.height, img.height);
  EXPECT_EQ(back.pixels, img.pixels);
  EXPECT_EQ(nearest_lod(back.rgb(250, 40)), 4);
}

TEST_F(OffscreenRender, BadTargetsAreRejected) {
  EXPECT_THROW(OffscreenTarget(ctx(), 0, 10), RenderError);
  OffscreenTarget target(ctx(), 8, 8, 1, VK_FORMAT_R16G16B16A16_SFLOAT);
  EXPECT_THROW(FrameRenderer(ctx(), meshes_, target.target()), RenderError);
  MeshLibrary not_uploaded;
  not_uploaded.add_sphere(20);
  OffscreenTarget ok(ctx(), 8, 8);
  EXPECT_THROW(FrameRenderer(ctx(), not_uploaded, ok.target()), RenderError);
}

}  // namespace
}  // namespace gazelod::render
