// SPDX-License-Identifier: Apache-2.0
// Screen-plane gaze to head-space direction, checked against hand-computed angles (atan2 of
// the screen offsets over the eye distance) and the frame conventions in screen_geometry.hpp.
#include "gaze/hid/screen_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::gaze::hid {
namespace {

constexpr double kPi = 3.14159265358979323846;
double deg(double rad) {
  return rad * 180.0 / kPi;
}

// A 500 x 300 mm screen; both eyes 600 mm in front of its centre, 64 mm apart.
const ScreenGeometry kScreen{0.5, 0.3, {}};
TrackingData at(std::int32_t gx_um, std::int32_t gy_um) {
  TrackingData t;
  t.gaze_x_um = gx_um;
  t.gaze_y_um = gy_um;
  t.left_eye_um = {-32000, 0, 600000};
  t.right_eye_um = {32000, 0, 600000};
  return t;
}

TEST(HidScreenGeometry, ScreenCentreIsStraightAhead) {
  const GazeSample s = gaze_from_screen(at(250000, 150000), kScreen);
  ASSERT_TRUE(s.valid);
  EXPECT_NEAR(s.direction.x, 0.0, 1e-12);
  EXPECT_NEAR(s.direction.y, 0.0, 1e-12);
  EXPECT_NEAR(s.direction.z, -1.0, 1e-12);  // OpenXR forward
  EXPECT_FLOAT_EQ(s.confidence, 1.0f);
}

TEST(HidScreenGeometry, RightEdgeAndTopLeftCornerAngles) {
  // Right edge, vertical centre: 0.25 m right at 0.6 m: yaw = atan2(0.25, 0.6) = 22.62 deg.
  const GazeSample r = gaze_from_screen(at(500000, 150000), kScreen);
  ASSERT_TRUE(r.valid);
  EXPECT_NEAR(deg(std::atan2(r.direction.x, -r.direction.z)), 22.619864948, 1e-6);
  EXPECT_NEAR(r.direction.y, 0.0, 1e-12);
  // Upper-left corner (0, 0): left and up (+y up in head space, though the point's y is down).
  const GazeSample c = gaze_from_screen(at(0, 0), kScreen);
  ASSERT_TRUE(c.valid);
  const double len = std::sqrt(0.25 * 0.25 + 0.15 * 0.15 + 0.6 * 0.6);
  EXPECT_NEAR(c.direction.x, -0.25 / len, 1e-12);
  EXPECT_NEAR(c.direction.y, 0.15 / len, 1e-12);
  EXPECT_NEAR(c.direction.z, -0.6 / len, 1e-12);
}

TEST(HidScreenGeometry, OneEyeHalvesConfidenceAndMovesTheOrigin) {
  TrackingData t = at(250000, 150000);
  t.left_eye_um.z = 0;  // left eye not tracked
  const GazeSample s = gaze_from_screen(t, kScreen);
  ASSERT_TRUE(s.valid);
  EXPECT_FLOAT_EQ(s.confidence, 0.5f);
  // From the right eye (32 mm right of centre) to the centre: slightly left.
  EXPECT_NEAR(deg(std::atan2(s.direction.x, -s.direction.z)), -deg(std::atan2(0.032, 0.6)), 1e-9);
}

TEST(HidScreenGeometry, NoEyesFarOffScreenOrBadGeometryAreInvalid) {
  TrackingData none = at(250000, 150000);
  none.left_eye_um = {};
  none.right_eye_um = {};
  EXPECT_FALSE(gaze_from_screen(none, kScreen).valid);
  EXPECT_FALSE(gaze_from_screen(TrackingData{}, kScreen).valid);       // an all-zero report
  EXPECT_FALSE(gaze_from_screen(at(-260000, 150000), kScreen).valid);  // > half a screen left
  EXPECT_TRUE(gaze_from_screen(at(-240000, 150000), kScreen).valid);   // just inside the margin
  EXPECT_FALSE(gaze_from_screen(at(250000, 460000), kScreen).valid);   // > half a screen below
  EXPECT_FALSE(gaze_from_screen(at(250000, 150000), ScreenGeometry{0.0, 0.3, {}}).valid);
  EXPECT_FALSE(gaze_from_screen(at(250000, 150000), ScreenGeometry{NAN, 0.3, {}}).valid);
  EXPECT_FALSE(validate(ScreenGeometry{0.5, -1.0, {}}).empty());
}

TEST(HidScreenGeometry, TopLeftYDownEyeFrameGivesTheSameDirection) {
  // The same eyes expressed from the upper-left corner with +y down: x + 250 mm, y = 150 mm.
  ScreenGeometry corner = kScreen;
  corner.eye_frame = {true, true};
  TrackingData t = at(400000, 50000);
  const GazeSample a = gaze_from_screen(t, kScreen);
  t.left_eye_um = {218000, 150000, 600000};
  t.right_eye_um = {282000, 150000, 600000};
  const GazeSample b = gaze_from_screen(t, corner);
  ASSERT_TRUE(a.valid && b.valid);
  EXPECT_NEAR(a.direction.x, b.direction.x, 1e-12);
  EXPECT_NEAR(a.direction.y, b.direction.y, 1e-12);
  EXPECT_NEAR(a.direction.z, b.direction.z, 1e-12);
  EXPECT_NEAR(glm::length(b.direction), 1.0, 1e-12);
}

TEST(HidScreenGeometry, HeadPositionGivesTheEyeOriginInHeadSpace) {
  TrackingData t = at(250000, 150000);
  t.has_head = true;
  t.head_position_um = {0, -50000, 680000};  // head centre 5 cm lower, 8 cm further back
  const GazeSample s = gaze_from_screen(t, kScreen);
  ASSERT_TRUE(s.valid);
  EXPECT_NEAR(s.origin_m.x, 0.0, 1e-12);
  EXPECT_NEAR(s.origin_m.y, 0.05, 1e-12);
  EXPECT_NEAR(s.origin_m.z, -0.08, 1e-12);
}

}  // namespace
}  // namespace gazelod::gaze::hid
