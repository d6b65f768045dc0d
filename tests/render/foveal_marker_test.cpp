// SPDX-License-Identifier: Apache-2.0
// The foveal circle of the debug view: dots at the requested angle around the gaze, and where
// they land in a rendered frame.
#include "auxiliary/angles.hpp"
#include "render/device_context.hpp"
#include "render/foveal_marker.hpp"
#include "render/frame_renderer.hpp"
#include "render/lod_palette.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_error.hpp"
#include "tests/skip_or_fail.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace gazelod::render {
namespace {

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * aux::kDegPerRad;
}

TEST(FovealMarker, DotsLieAtTheRadiusAroundTheGaze) {
  const glm::dvec3 eye(0.1, 1.6, -0.3);
  for (const glm::dvec3 gaze : {glm::dvec3(0, 0, -1), glm::dvec3(0.3, -0.2, -1), glm::dvec3(0, 1, 0)}) {
    std::array<DrawItem, 12> dots{};
    ASSERT_EQ(foveal_circle(eye, gaze, 7.5, 3, dots, 0.5, 0.2), dots.size());
    for (std::size_t i = 0; i < dots.size(); ++i) {
      const glm::dvec3 d = glm::dvec3(dots[i].center_m) - eye;
      EXPECT_NEAR(glm::length(d), 0.5, 1e-6);
      EXPECT_NEAR(angle_deg(d, gaze), 7.5, 1e-3);
      EXPECT_EQ(dots[i].mesh, 3u);
      EXPECT_EQ(dots[i].lod_level, kMarkerLevel);
      EXPECT_NEAR(dots[i].radius_m, 0.5 * std::tan(0.2 / aux::kDegPerRad), 1e-7);
      // Evenly spread: neighbours 30 degrees apart around the axis, i.e. a chord of
      // 2 sin(7.5 deg) sin(15 deg) at unit distance.
      const glm::dvec3 next = glm::dvec3(dots[(i + 1) % dots.size()].center_m) - eye;
      EXPECT_NEAR(glm::distance(d / 0.5, next / 0.5),
                  2.0 * std::sin(7.5 / aux::kDegPerRad) * std::sin(15.0 / aux::kDegPerRad), 1e-5);
    }
  }
}

TEST(FovealMarker, NoGazeNoCircle) {
  std::array<DrawItem, 4> dots{};
  EXPECT_EQ(foveal_circle({0, 0, 0}, {0, 0, 0}, 5.0, 0, dots), 0u);
  EXPECT_EQ(foveal_circle({0, 0, 0}, {NAN, 0, -1}, 5.0, 0, dots), 0u);
  EXPECT_EQ(foveal_circle({0, 0, 0}, {0, 0, -1}, NAN, 0, dots), 0u);
}

TEST(FovealMarker, RenderedCircleHasTheProjectedRadius) {
  std::unique_ptr<OffscreenDevice> device;
  try {
    device = std::make_unique<OffscreenDevice>();
  } catch (const NoVulkanDevice& e) {
    GAZELOD_SKIP_OR_FAIL("no Vulkan device: " << e.what());
  }
  MeshLibrary meshes;
  const std::uint32_t dot = meshes.add_sphere(80);
  meshes.upload(device->context());
  OffscreenTarget target(device->context(), 200, 200);
  FrameRenderer renderer(device->context(), meshes, target.target());
  EyeView view;
  view.fov = {-std::numbers::pi / 4, std::numbers::pi / 4, std::numbers::pi / 4, -std::numbers::pi / 4};
  std::array<DrawItem, 16> dots{};
  foveal_circle(view.pose.position_m, {0, 0, -1}, 20.0, dot, dots, 0.25, 2.0);
  renderer.draw(0, view, dots);
  const RgbaImage img = renderer.read_back(0);
  // tan(20 deg) / tan(45 deg) of the half-width (100 px): 36.4 px right of the centre for the
  // first dot (along u = +x), and the same distance below for the fifth (a quarter turn on,
  // along v = gaze x u = -y).
  const auto r_px = static_cast<std::uint32_t>(std::lround(100.0 * std::tan(20.0 / aux::kDegPerRad)));
  EXPECT_GT(img.rgb(100 + r_px, 100).g, 0.9f);
  EXPECT_GT(img.rgb(100 + r_px, 100).b, 0.9f);
  EXPECT_GT(img.rgb(100, 100 + r_px).r, 0.9f);
  EXPECT_GT(img.rgb(100, 100 + r_px).b, 0.9f);
  EXPECT_EQ(nearest_lod(img.rgb(100, 100)), -1);  // the centre stays clear
  EXPECT_EQ(nearest_lod(img.rgb(100 + r_px + 8, 100)), -1);
  EXPECT_EQ(renderer.triangles_last_frame(), 0u);  // markers are not scene triangles
  for (const std::string& m : device->validation_messages()) ADD_FAILURE() << "validation: " << m;
}

}  // namespace
}  // namespace gazelod::render
