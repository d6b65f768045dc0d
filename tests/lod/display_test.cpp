// SPDX-License-Identifier: Apache-2.0
// Displays: xi per axis, presets, validation, FOV near 0 and near 180 deg.
#include "lod/acuity.hpp"
#include "lod/display.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gazelod::lod {
namespace {

TEST(Display, AllPresetsPresentAndValid) {
  for (const char* name : {"desktop", "iglasses", "quest3", "questpro", "index", "viveproeye", "varjoxr4", "visionpro",
                           "psvr2", "pimaxcrystal"}) {
    const DisplaySpec* d = find_display_preset(name);
    ASSERT_NE(d, nullptr) << name;
    EXPECT_EQ(validate_display(*d), "") << name;
    EXPECT_FALSE(d->source.empty()) << name;
    EXPECT_FALSE(d->label.empty()) << name;
    const double xi = xi_cpd(*d);
    EXPECT_GT(xi, 0.0) << name;
    EXPECT_LT(xi, 60.0) << name;
    EXPECT_GE(xi_center_cpd(*d), xi) << name;  // lenses concentrate pixels at the centre
  }
  EXPECT_EQ(display_presets().size(), 10u);
  EXPECT_EQ(find_display_preset("rift"), nullptr);
  EXPECT_EQ(find_display_preset(""), nullptr);
}

TEST(Display, EyeTrackedPresetsHaveRateAndAccuracy) {
  for (const char* name : {"questpro", "viveproeye", "varjoxr4", "visionpro", "psvr2", "pimaxcrystal"}) {
    const DisplaySpec* d = find_display_preset(name);
    EXPECT_GT(d->eye_tracking_hz, 0.0) << name;
    EXPECT_GT(d->eye_tracking_accuracy_deg, 0.0) << name;
  }
  for (const char* name : {"quest3", "index", "desktop"})
    EXPECT_EQ(find_display_preset(name)->eye_tracking_hz, 0.0) << name;
}

TEST(Display, AsymmetricOpenXrFov) {
  // A Quest-2-like left eye: more FOV outward than inward.
  ViewSpec v{1832, 1920, FovRad{-0.942, 0.698, 0.942, -0.960}};
  EXPECT_EQ(validate_view(v), "");
  const double h = (0.698 + 0.942) * 180 / std::numbers::pi;
  EXPECT_NEAR(fov_h_deg(v), h, 1e-12);
  EXPECT_NEAR(xi_h_cpd(v), 1832 / (2 * h), 1e-12);
  EXPECT_DOUBLE_EQ(xi_cpd(v), std::max(xi_h_cpd(v), xi_v_cpd(v)));
}

TEST(Display, FovNearZero) {
  ViewSpec v{1000, 1000, symmetric_fov(1e-9, 1e-9)};
  EXPECT_EQ(validate_view(v), "");
  EXPECT_TRUE(std::isfinite(xi_cpd(v)));
  EXPECT_GT(xi_cpd(v), 60.0);
  // Beyond the eye: thresholds are 0, nothing NaN.
  EXPECT_EQ(eccentricity_threshold_deg(xi_cpd(v)), 0.0);
  EXPECT_EQ(velocity_threshold_dps(xi_cpd(v)), 0.0);
  ViewSpec zero{1000, 1000, symmetric_fov(0.0, 10.0)};
  EXPECT_NE(validate_view(zero).find("horizontal FOV"), std::string::npos);
  EXPECT_EQ(xi_h_cpd(zero), 0.0);
}

TEST(Display, FovNear180) {
  ViewSpec v{100, 100, symmetric_fov(179.999999, 179.999999)};
  EXPECT_EQ(validate_view(v), "");
  const double xi = xi_cpd(v);
  EXPECT_NEAR(xi, 100 / (2 * 179.999999), 1e-9);
  EXPECT_TRUE(std::isfinite(eccentricity_threshold_deg(xi)));
  EXPECT_TRUE(std::isfinite(velocity_threshold_dps(xi)));
  ViewSpec full{100, 100, symmetric_fov(180.0, 90.0)};
  EXPECT_FALSE(validate_view(full).empty());
  ViewSpec over{100, 100, FovRad{-1.6, 1.6, 0.5, -0.5}};
  EXPECT_NE(validate_view(over).find("angleLeft"), std::string::npos);
}

TEST(Display, RefusesBadFields) {
  EXPECT_NE(validate_view(ViewSpec{0, 10, symmetric_fov(90, 90)}).find("pixels"), std::string::npos);
  EXPECT_NE(validate_view(ViewSpec{10, 10, FovRad{NAN, 1, 1, -1}}).find("angleLeft"), std::string::npos);
  EXPECT_NE(validate_view(ViewSpec{10, 10, FovRad{0.5, -0.5, 1, -1}}).find("horizontal"), std::string::npos);
  DisplaySpec d = *find_display_preset("quest3");
  d.view_count = 3;
  EXPECT_NE(validate_display(d).find("view_count"), std::string::npos);
  d.view_count = 2;
  d.refresh_hz = 0;
  EXPECT_NE(validate_display(d).find("refresh"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::lod
