// SPDX-License-Identifier: Apache-2.0
// Reddy's acuity model: the reference table of docs/perceptual-model.md, the hard inputs (0,
// denormals, seams, inf, NaN) and monotonicity over dense grids that include the seams.
#include "lod/acuity.hpp"
#include "lod/display.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace gazelod::lod {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Closed forms written out independently of acuity.cpp.
double e_thr_formula(double xi) {
  return (std::sqrt(7.49 * 60.0 / xi) - 1.0) / 0.3;
}
double v_thr_formula(double xi, double ecc) {
  const double m = ecc > 5.79 ? 7.49 / std::pow(0.3 * ecc + 1.0, 2) : 1.0;
  return std::pow(10.0, (57.69 - xi / m) / 27.78);
}

TEST(AcuityReference, DesktopXiMatchesFormulaAndPaper) {
  const DisplaySpec* d = find_display_preset("desktop");
  ASSERT_NE(d, nullptr);
  const double h = 2 * std::atan(20.0 / 40.0) * 180 / M_PI, v = 2 * std::atan(15.0 / 40.0) * 180 / M_PI;
  EXPECT_NEAR(fov_h_deg(d->views[0]), 53.13, 0.01);
  EXPECT_NEAR(fov_v_deg(d->views[0]), 41.11, 0.01);
  EXPECT_NEAR(xi_h_cpd(d->views[0]), 1280 / (2 * h), 0.01);
  EXPECT_NEAR(xi_v_cpd(d->views[0]), 1024 / (2 * v), 0.01);
  EXPECT_NEAR(xi_h_cpd(d->views[0]), 12.05, 0.01);
  EXPECT_NEAR(xi_v_cpd(d->views[0]), 12.45, 0.01);
  EXPECT_NEAR(xi_cpd(*d), 12.45, 0.01);
  EXPECT_NEAR(xi_h_cpd(d->views[0]), 12.0, 0.05);  // paper: 12.0 x 12.5
  EXPECT_NEAR(xi_v_cpd(d->views[0]), 12.5, 0.05);
}

TEST(AcuityReference, DesktopThresholds) {
  const double xi = xi_cpd(*find_display_preset("desktop"));
  EXPECT_NEAR(eccentricity_threshold_deg(xi), e_thr_formula(xi), 0.01);
  EXPECT_NEAR(eccentricity_threshold_deg(xi), 16.69, 0.01);  // paper: about 17
  EXPECT_NEAR(velocity_threshold_dps(xi), v_thr_formula(xi, 0), 0.01);
  EXPECT_NEAR(velocity_threshold_dps(xi), 42.50, 0.01);  // paper: about 42
  EXPECT_NEAR(velocity_threshold_dps(xi, 10.0), v_thr_formula(xi, 10), 0.01);
  EXPECT_NEAR(velocity_threshold_dps(xi, 10.0), 13.15, 0.01);  // paper: roughly 13
}

TEST(AcuityReference, IGlassesXiAndThresholds) {
  const DisplaySpec* d = find_display_preset("iglasses");
  ASSERT_NE(d, nullptr);
  EXPECT_NEAR(xi_h_cpd(d->views[0]), 263 / 60.0, 0.01);
  EXPECT_NEAR(xi_v_cpd(d->views[0]), 230 / 48.0, 0.01);
  EXPECT_NEAR(xi_h_cpd(d->views[0]), 4.38, 0.01);  // paper: 4.4 x 4.8
  EXPECT_NEAR(xi_v_cpd(d->views[0]), 4.79, 0.01);
  const double xi = xi_cpd(*d);
  EXPECT_NEAR(eccentricity_threshold_deg(xi), e_thr_formula(xi), 0.01);
  EXPECT_NEAR(eccentricity_threshold_deg(xi), 28.95, 0.01);  // ~29
  EXPECT_NEAR(velocity_threshold_dps(xi), 80.20, 0.01);      // ~80
  EXPECT_NEAR(velocity_threshold_dps(xi, 15.0), v_thr_formula(xi, 15), 0.01);
  EXPECT_NEAR(velocity_threshold_dps(xi, 15.0), 23.99, 0.01);  // ~24
}

TEST(AcuityReference, ThresholdIsWhereHFallsBelowXi) {
  for (double xi : {4.79, 12.45, 30.0, 59.0}) {
    const double e = eccentricity_threshold_deg(xi);
    EXPECT_GE(spatiotemporal_acuity_cpd(0, e - 1e-6), xi);
    EXPECT_LT(spatiotemporal_acuity_cpd(0, e + 1e-6), xi);
    const double v = velocity_threshold_dps(xi);
    EXPECT_GE(spatiotemporal_acuity_cpd(v - 1e-6, 0), xi);
    EXPECT_LT(spatiotemporal_acuity_cpd(v + 1e-6, 0), xi);
    const double vj = velocity_threshold_dps(xi, 20.0);
    if (xi > 60.0 * eccentricity_factor(20.0)) {  // already invisible at rest at 20 deg
      EXPECT_EQ(vj, 0.0);
      continue;
    }
    EXPECT_GE(spatiotemporal_acuity_cpd(vj * (1 - 1e-9), 20.0), xi * (1 - 1e-9));
    EXPECT_LT(spatiotemporal_acuity_cpd(vj * (1 + 1e-6), 20.0), xi);
  }
}

TEST(AcuityInverse, EdgeFrequencies) {
  EXPECT_EQ(eccentricity_threshold_deg(61.0), 0.0);  // display beyond the eye: 0
  EXPECT_EQ(velocity_threshold_dps(61.0), 0.0);
  EXPECT_EQ(eccentricity_threshold_deg(0.0), kInf);  // nothing falls below 0
  EXPECT_EQ(velocity_threshold_dps(-1.0), kInf);
  EXPECT_EQ(eccentricity_threshold_deg(kNaN), kInf);
  EXPECT_DOUBLE_EQ(eccentricity_threshold_deg(60.0), kEccentricitySeamDeg);
  EXPECT_DOUBLE_EQ(velocity_threshold_dps(60.0), velocity_seam_repaired_dps());
  EXPECT_EQ(eccentricity_threshold_deg(10.0, kInf), 0.0);  // G = 0 at infinite speed
  // Within the visual field only: at 1/360 c/deg (1 px over 179 deg) the formula gives 1334 deg,
  // past the opposite direction; H never falls that low in the visual field.
  EXPECT_EQ(eccentricity_threshold_deg(1.0 / 360.0), kInf);
  // The seam at 180 deg: M(180) * 60 c/deg, just above and below.
  const double at_180 = eccentricity_factor(kMaxEccentricityDeg) * 60.0;
  EXPECT_NEAR(eccentricity_threshold_deg(at_180 * (1 + 1e-9)), kMaxEccentricityDeg, 1e-3);
  EXPECT_EQ(eccentricity_threshold_deg(at_180 * (1 - 1e-6)), kInf);
}

// --- hard cases for v ---------------------------------------------------------------------
TEST(AcuityVelocity, Zero) {
  EXPECT_EQ(velocity_acuity_cpd(0.0), 60.0);
}
TEST(AcuityVelocity, Denormal) {
  EXPECT_EQ(velocity_acuity_cpd(std::numeric_limits<double>::denorm_min()), 60.0);
}
TEST(AcuityVelocity, Tiny1em30) {
  EXPECT_EQ(velocity_acuity_cpd(1e-30), 60.0);
}
TEST(AcuityVelocity, SeamPlusMinusOneUlp) {
  const double below = std::nextafter(0.825, 0.0), above = std::nextafter(0.825, 1.0);
  EXPECT_EQ(velocity_acuity_cpd(below), 60.0);
  EXPECT_EQ(velocity_acuity_cpd(0.825), 60.0);
  EXPECT_LE(velocity_acuity_cpd(above), 60.0);  // raw formula gives 60.0109
  EXPECT_LE(velocity_acuity_cpd(above), velocity_acuity_cpd(below));
}
TEST(AcuityVelocity, ZeroCrossing119PlusMinusEps) {
  const double v0 = velocity_zero_dps();
  EXPECT_NEAR(v0, 119.31, 0.01);
  for (double v : {std::nextafter(v0, 0.0), v0, std::nextafter(v0, 1e9), 119.31 - 1e-9, 119.31 + 1e-9}) {
    const double g = velocity_acuity_cpd(v);
    EXPECT_GE(g, 0.0) << v;
    EXPECT_LT(g, 1e-3) << v;
  }
  EXPECT_GE(velocity_acuity_cpd(std::nextafter(v0, 0.0)), velocity_acuity_cpd(std::nextafter(v0, 1e9)));
}
TEST(AcuityVelocity, Huge1e6) {
  EXPECT_EQ(velocity_acuity_cpd(1e6), 0.0);
}
TEST(AcuityVelocity, Infinite) {
  EXPECT_EQ(velocity_acuity_cpd(kInf), 0.0);
  EXPECT_EQ(acuity_cpd(kInf, 0.0, 12.0), 0.0);
}
TEST(AcuityVelocity, NaNIsConservativeAndRefused) {
  EXPECT_EQ(velocity_acuity_cpd(kNaN), 60.0);
  EXPECT_FALSE(std::isnan(acuity_cpd(kNaN, kNaN, 12.0)));
  EXPECT_NE(validate_acuity_inputs(kNaN, 0, 12, 1).find("velocity"), std::string::npos);
  EXPECT_NE(validate_acuity_inputs(-1, 0, 12, 1).find("velocity"), std::string::npos);
  EXPECT_EQ(validate_acuity_inputs(kInf, 0, 12, 1), "");
}

// --- hard cases for E ---------------------------------------------------------------------
TEST(AcuityEccentricity, Zero) {
  EXPECT_EQ(eccentricity_factor(0.0), 1.0);
}
TEST(AcuityEccentricity, SeamPlusMinusEps) {
  const double below = std::nextafter(5.79, 0.0), above = std::nextafter(5.79, 10.0);
  EXPECT_EQ(eccentricity_factor(below), 1.0);
  EXPECT_EQ(eccentricity_factor(5.79), 1.0);
  EXPECT_LE(eccentricity_factor(above), 1.0);
  EXPECT_NEAR(eccentricity_factor(above), 0.99984, 1e-5);
}
TEST(AcuityEccentricity, Ninety) {
  EXPECT_NEAR(eccentricity_factor(90.0), 7.49 / (28.0 * 28.0), 1e-12);
}
TEST(AcuityEccentricity, OneEighty) {
  EXPECT_NEAR(eccentricity_factor(180.0), 7.49 / (55.0 * 55.0), 1e-12);
  EXPECT_GT(eccentricity_factor(180.0), 0.0);
}
TEST(AcuityEccentricity, NegativeIsConservativeAndRefused) {
  EXPECT_EQ(eccentricity_factor(-5.0), 1.0);
  EXPECT_NE(validate_acuity_inputs(0, -5, 12, 1).find("eccentricity"), std::string::npos);
}
TEST(AcuityEccentricity, NaNIsConservativeAndRefused) {
  EXPECT_EQ(eccentricity_factor(kNaN), 1.0);
  EXPECT_NE(validate_acuity_inputs(0, kNaN, 12, 1).find("eccentricity"), std::string::npos);
  EXPECT_NE(validate_acuity_inputs(0, 181, 12, 1).find("eccentricity"), std::string::npos);
}

TEST(AcuityScale, GlobalScaleAndXi) {
  EXPECT_DOUBLE_EQ(acuity_cpd(0, 0, 12.0, 0.5), 6.0);
  EXPECT_DOUBLE_EQ(acuity_cpd(0, 0, 100.0, 1.0), 60.0);
  EXPECT_DOUBLE_EQ(acuity_cpd(0, 0, 12.0, kNaN), 12.0);
  EXPECT_DOUBLE_EQ(acuity_cpd(0, 0, 12.0, 7.0), 12.0);
  EXPECT_NE(validate_acuity_inputs(0, 0, 12, 0.0).find("scale"), std::string::npos);
  EXPECT_NE(validate_acuity_inputs(0, 0, 0.0, 1.0).find("xi"), std::string::npos);
  EXPECT_EQ(validate_acuity_inputs(0, 0, 12, 1), "");
}

// --- monotonicity over dense grids, seams included ------------------------------------------
TEST(AcuityMonotone, VelocityGridWithSeams) {
  std::vector<double> vs;
  for (double v = 0.0; v <= 200.0; v += 1e-3) vs.push_back(v);
  for (double seam : {0.825, velocity_seam_repaired_dps(), velocity_zero_dps(), 119.31}) {
    double x = seam;
    for (int i = 0; i < 200; ++i) x = std::nextafter(x, 0.0);
    for (int i = 0; i < 400; ++i, x = std::nextafter(x, 1e9)) vs.push_back(x);
  }
  std::sort(vs.begin(), vs.end());
  for (double ecc : {0.0, 5.79, 10.0, 60.0}) {
    double prev = kInf;
    for (double v : vs) {
      const double a = acuity_cpd(v, ecc, 100.0);
      ASSERT_LE(a, prev) << "v " << v << " E " << ecc;
      ASSERT_GE(a, 0.0);
      prev = a;
    }
  }
}

TEST(AcuityMonotone, EccentricityGridWithSeam) {
  std::vector<double> es;
  for (double e = 0.0; e <= 180.0; e += 1e-3) es.push_back(e);
  double x = 5.79;
  for (int i = 0; i < 200; ++i) x = std::nextafter(x, 0.0);
  for (int i = 0; i < 400; ++i, x = std::nextafter(x, 1e9)) es.push_back(x);
  std::sort(es.begin(), es.end());
  for (double v : {0.0, 0.825, 10.0, 100.0}) {
    double prev = kInf;
    for (double e : es) {
      const double a = acuity_cpd(v, e, 100.0);
      ASSERT_LE(a, prev) << "E " << e << " v " << v;
      ASSERT_GE(a, 0.0);
      prev = a;
    }
  }
}

TEST(AcuityMonotone, InversesNonIncreasingInFrequency) {
  double pe = kInf, pv = kInf, pj = kInf;
  for (double f = 1e-3; f <= 61.0; f += 1e-3) {
    const double e = eccentricity_threshold_deg(f), v = velocity_threshold_dps(f), j = velocity_threshold_dps(f, 15.0);
    ASSERT_LE(e, pe) << f;
    ASSERT_LE(v, pv) << f;
    ASSERT_LE(j, pj) << f;
    ASSERT_GE(e, 0.0);
    ASSERT_GE(v, 0.0);
    pe = e, pv = v, pj = j;
  }
}

}  // namespace
}  // namespace gazelod::lod
