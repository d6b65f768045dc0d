// SPDX-License-Identifier: Apache-2.0
// Without gaze (head-fixed: no tracker, none yet, or lost) the plugin takes the eye to hold the
// world, as the vestibulo-ocular reflex does for whatever it fixates: a head turn alone then
// coarsens nothing (plugin/lod_core.cpp, condition_gaze; docs/perceptual-model.md).
#include "plugin/lod_core.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gazelod::plugin {
namespace {

// A ring of objects around the viewer at eye height, four levels each, detail as geometric
// error so that retinal speed matters.
void populate(LodCore& core) {
  for (int k = 0; k < 36; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 36.0;
    ObjectDesc d;
    d.center_m = {4.0 * std::sin(a), 0.1 * (k % 3), -4.0 * std::cos(a)};
    d.radius_m = 0.3;
    for (std::uint32_t tris = 20'000, l = 0; l < 4; ++l, tris /= 4) {
      lod::LodLevel level;
      level.triangles = tris;
      level.vertices = tris / 2;
      level.detail_kind = lod::DetailKind::geometric_error_m;
      level.detail = l == 0 ? 0.0 : 0.0005 * std::pow(4.0, l - 1);
      d.lods.push_back(level);
    }
    (void)core.add_object(d);
  }
}

FrameInput frame(int k, double yaw_rate_rad_s) {
  FrameInput in;
  in.t_ns = 1'000'000'000 + std::int64_t{k} * 11'111'111;
  in.head.valid = true;
  in.head.orientation = glm::angleAxis(0.3, glm::dvec3(0.0, 1.0, 0.0));  // the same pose in both runs
  in.head.angular_velocity_rad_s = {0.0, yaw_rate_rad_s, 0.0};
  in.view_count = 1;
  in.views[0].fov = {-0.8, 0.8, 0.8, -0.8};
  in.views[0].width_px = in.views[0].height_px = 1600;
  return in;
}

TEST(HeadFixedGaze, AHeadTurnAloneCoarsensNothing) {
  PluginConfig config;
  config.switch_policy = false;  // each frame's perceptual levels
  LodCore turning(config), still(config);
  populate(turning);
  populate(still);
  const double rate = 120.0 * std::numbers::pi / 180.0;  // 120 deg/s: well past every velocity threshold
  for (int k = 0; k < 5; ++k) {
    const FrameDecisions& a = turning.decide(frame(k, rate));
    const std::vector<std::uint8_t> turning_lod(a.lod.begin(), a.lod.end());
    const FrameDecisions& b = still.decide(frame(k, 0.0));
    ASSERT_EQ(a.gaze_source, GazeSourceKind::head_fixed);
    // The eye counter-rotates the head: still in the world.
    const glm::dvec3 eye_in_head = turning.diagnostics().viewer.gaze_angular_velocity_in_head_rad_s;
    EXPECT_NEAR(eye_in_head.y, -rate, 1e-9);
    EXPECT_NEAR(eye_in_head.x, 0.0, 1e-9);
    EXPECT_NEAR(eye_in_head.z, 0.0, 1e-9);
    ASSERT_EQ(turning_lod.size(), b.lod.size());
    EXPECT_TRUE(std::equal(turning_lod.begin(), turning_lod.end(), b.lod.begin())) << "frame " << k;
  }
  // The velocity criterion still works where there is real retinal motion: with the criterion
  // on, the still head's levels are not all 0 (the scene is not trivially at full detail).
  const FrameDecisions& b = still.decide(frame(5, 0.0));
  EXPECT_GT(std::count_if(b.lod.begin(), b.lod.end(), [](std::uint8_t l) { return l > 0; }), 0);
}

}  // namespace
}  // namespace gazelod::plugin
