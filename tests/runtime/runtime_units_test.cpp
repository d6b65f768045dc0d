// SPDX-License-Identifier: Apache-2.0
// Unit tests of the runtime's pure parts: the path grammar and table, interaction profile
// bindings, the simulated clock and the gaze orientation of a direction.
#include "auxiliary/yaw_pitch.hpp"
#include "sim/runtime/interaction_profiles.hpp"
#include "sim/runtime/path_table.hpp"
#include "sim/runtime/pose_math.hpp"
#include "sim/runtime/sim_clock.hpp"
#include "xr/eye_gaze_paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace gazelod::xrrt {
namespace {

TEST(RuntimePaths, WellFormedPathsFollowTheSpecGrammar) {
  EXPECT_TRUE(is_well_formed_path("/user/hand/left"));
  EXPECT_TRUE(is_well_formed_path("/user/eyes_ext/input/gaze_ext/pose"));
  EXPECT_TRUE(is_well_formed_path("/a.b-c_d/0"));
  EXPECT_FALSE(is_well_formed_path(""));
  EXPECT_FALSE(is_well_formed_path("/"));
  EXPECT_FALSE(is_well_formed_path("user/hand"));
  EXPECT_FALSE(is_well_formed_path("/user/hand/"));
  EXPECT_FALSE(is_well_formed_path("/user//hand"));
  EXPECT_FALSE(is_well_formed_path("/user/Hand"));
  EXPECT_FALSE(is_well_formed_path("/user/hand left"));
  EXPECT_FALSE(is_well_formed_path("/user/./hand"));
  EXPECT_FALSE(is_well_formed_path("/user/../hand"));
  EXPECT_FALSE(is_well_formed_path("/" + std::string(XR_MAX_PATH_LENGTH, 'a')));
  EXPECT_TRUE(is_well_formed_name("gaze_pose"));
  EXPECT_FALSE(is_well_formed_name("gaze/pose"));
  EXPECT_FALSE(is_well_formed_name(""));
}

TEST(RuntimePaths, TableInternsOnceAndRejectsUnknownPaths) {
  PathTable t;
  const XrPath a = t.intern("/user/hand/left");
  const XrPath b = t.intern("/user/hand/right");
  EXPECT_NE(a, XR_NULL_PATH);
  EXPECT_NE(a, b);
  EXPECT_EQ(t.intern("/user/hand/left"), a);
  ASSERT_NE(t.find(b), nullptr);
  EXPECT_EQ(*t.find(b), "/user/hand/right");
  EXPECT_EQ(t.find(XR_NULL_PATH), nullptr);
  EXPECT_EQ(t.find(b + 1), nullptr);
}

TEST(RuntimeProfiles, BindingsMatchProfileComponentsAndHands) {
  const InteractionProfile* simple = find_profile("/interaction_profiles/khr/simple_controller");
  const InteractionProfile* touch = find_profile("/interaction_profiles/oculus/touch_controller");
  const InteractionProfile* eyes = find_profile(xr::kEyeGazeProfile);
  ASSERT_NE(simple, nullptr);
  ASSERT_NE(touch, nullptr);
  ASSERT_NE(eyes, nullptr);
  EXPECT_EQ(find_profile("/interaction_profiles/none/such"), nullptr);
  EXPECT_TRUE(profile_has_binding(*simple, "/user/hand/left/input/select/click"));
  EXPECT_TRUE(profile_has_binding(*simple, "/user/hand/right/output/haptic"));
  EXPECT_FALSE(profile_has_binding(*simple, "/user/hand/left/input/trigger/value"));
  EXPECT_FALSE(profile_has_binding(*simple, "/user/head/input/select/click"));
  // Hand-specific buttons, and identifiers naming a component's parent.
  EXPECT_TRUE(profile_has_binding(*touch, "/user/hand/left/input/x/click"));
  EXPECT_FALSE(profile_has_binding(*touch, "/user/hand/right/input/x/click"));
  EXPECT_TRUE(profile_has_binding(*touch, "/user/hand/right/input/trigger"));
  EXPECT_FALSE(profile_has_binding(*touch, "/user/hand/right/input/trig"));
  EXPECT_TRUE(profile_has_binding(*eyes, xr::kGazePosePath));
  EXPECT_TRUE(eyes->needs_eye_gaze_extension);
}

TEST(RuntimeProfiles, TopLevelPathsAndInputKinds) {
  EXPECT_EQ(top_level_of("/user/hand/left/input/select/click"), "/user/hand/left");
  EXPECT_EQ(top_level_of("/user/eyes_ext/input/gaze_ext/pose"), "/user/eyes_ext");
  EXPECT_EQ(top_level_of("/user/hands"), "");
  EXPECT_TRUE(is_top_level_user_path("/user/head"));
  EXPECT_FALSE(is_top_level_user_path("/user/hand/left/input"));
  EXPECT_EQ(input_kind("/user/hand/left/input/select/click"), InputKind::boolean);
  EXPECT_EQ(input_kind("/user/hand/left/input/trigger/value"), InputKind::scalar);
  EXPECT_EQ(input_kind("/user/hand/left/input/thumbstick"), InputKind::vector2);
  EXPECT_EQ(input_kind("/user/hand/left/input/grip/pose"), InputKind::pose);
  EXPECT_EQ(input_kind("/user/hand/left/output/haptic"), InputKind::haptic);
}

TEST(RuntimeClock, PeriodAndTimeBase) {
  SimClock c;
  c.start(false, 90.0);
  EXPECT_EQ(c.period_ns(), 11'111'111);
  EXPECT_EQ(c.now(), kTimeBaseNs);  // unpaced: no frame yet
  c.note_frame(kTimeBaseNs + 3 * c.period_ns());
  EXPECT_EQ(c.now(), kTimeBaseNs + 3 * c.period_ns());
  EXPECT_EQ(SimClock::scenario_ns(kTimeBaseNs + 5), 5);
  c.start(false, 0.0);  // a refresh rate of 0 must not divide by zero
  EXPECT_GT(c.period_ns(), 0);
  c.start(false, std::nan(""));
  EXPECT_GT(c.period_ns(), 0);
  // The monotonic mapping round-trips.
  EXPECT_EQ(c.to_monotonic_ns(c.from_monotonic_ns(123'456'789)), 123'456'789);
}

TEST(RuntimePose, GazeOrientationPointsMinusZAlongDirectionWithoutRoll) {
  const glm::dvec3 dirs[] = {{0, 0, -1}, {0.3, 0.1, -1}, {-0.5, -0.4, -0.2}, {0, 0.9, -0.1}, {1, 0, 0}};
  for (glm::dvec3 d : dirs) {
    d = glm::normalize(d);
    const glm::dquat q = aux::orientation_along(d);
    const glm::dvec3 fwd = q * glm::dvec3(0, 0, -1);
    EXPECT_LT(std::atan2(glm::length(glm::cross(fwd, d)), glm::dot(fwd, d)), 1e-12);
    const glm::dvec3 right = q * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(right.y, 0.0, 1e-12);  // no roll: +X stays level
  }
}

TEST(RuntimePose, ComposeAndInverse) {
  const Pose a{glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3))), {0.1, -0.2, 0.3}};
  const Pose b{glm::angleAxis(-0.3, glm::dvec3(0, 1, 0)), {1.0, 0.0, -2.0}};
  const Pose id = compose(inverse(a), a);
  EXPECT_NEAR(glm::length(id.position), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(id.orientation.w), 1.0, 1e-12);
  const glm::dvec3 p(0.5, 0.25, -1.0);
  const Pose ab = compose(a, b);
  const glm::dvec3 direct = a.orientation * (b.orientation * p + b.position) + a.position;
  EXPECT_NEAR(glm::length(ab.orientation * p + ab.position - direct), 0.0, 1e-12);
  XrPosef bad{};
  bad.orientation.w = 2.0f;
  EXPECT_FALSE(is_unit_orientation(bad));
  EXPECT_TRUE(is_unit_orientation(to_xr(a)));
}

}  // namespace
}  // namespace gazelod::xrrt
