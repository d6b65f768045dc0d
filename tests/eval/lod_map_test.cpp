// SPDX-License-Identifier: Apache-2.0
// The LOD-map thesis's policy: hand-computed scores, the published weights, colour salience,
// the level mapping and its guards.
#include "apps/gazelod/eval/lod_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace gazelod::lod {
namespace {

TEST(LodMap, EccentricityScoreIsThesisEquation4) {
  EXPECT_DOUBLE_EQ(lod_map_eccentricity_score(0.0), 1.0);
  EXPECT_NEAR(lod_map_eccentricity_score(10.0), 1.0 / 3.9, 1e-12);  // 1 / (1 + 2.9)
  EXPECT_NEAR(lod_map_eccentricity_score(100.0), 1.0 / 30.0, 1e-12);
  EXPECT_DOUBLE_EQ(lod_map_eccentricity_score(-3.0), 1.0);  // negative: clamped to the fovea
  EXPECT_DOUBLE_EQ(lod_map_eccentricity_score(std::numeric_limits<double>::quiet_NaN()), 0.0);
  for (double e = 0.0; e < 90.0; e += 0.5)
    EXPECT_GE(lod_map_eccentricity_score(e), lod_map_eccentricity_score(e + 0.5)) << e;
}

TEST(LodMap, MotionRisesTo20DegPerSecondThenFallsToZeroAt80) {
  const LodMapParams p;
  EXPECT_DOUBLE_EQ(lod_map_motion_score(0.0, p), 0.0);
  EXPECT_DOUBLE_EQ(lod_map_motion_score(10.0, p), 0.5);
  EXPECT_DOUBLE_EQ(lod_map_motion_score(20.0, p), 1.0);  // the seam: both pieces give 1
  EXPECT_NEAR(lod_map_motion_score(20.0 + 1e-9, p), 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(lod_map_motion_score(50.0, p), 0.5);
  EXPECT_DOUBLE_EQ(lod_map_motion_score(80.0, p), 0.0);
  EXPECT_DOUBLE_EQ(lod_map_motion_score(500.0, p), 0.0);
  EXPECT_DOUBLE_EQ(lod_map_motion_score(std::numeric_limits<double>::infinity(), p), 0.0);
}

TEST(LodMap, SizeScoreIsClampedRatio) {
  const LodMapParams p;  // 5 deg scores 1
  EXPECT_DOUBLE_EQ(lod_map_size_score(2.5, p), 0.5);
  EXPECT_DOUBLE_EQ(lod_map_size_score(50.0, p), 1.0);
  EXPECT_DOUBLE_EQ(lod_map_size_score(-1.0, p), 0.0);
  EXPECT_DOUBLE_EQ(lod_map_size_score(std::nan(""), p), 0.0);
}

TEST(LodMap, PublishedWeightsWithoutColourAreRenormalised) {
  // size 0.5, eccentricity 1/3.9, motion 0.5 with weights 30/14/26 over 70:
  // (0.15 + 0.14/3.9 + 0.13) / 0.70 = 0.451282...
  const LodMapParams p;
  const LodMapInput in{2.5, 10.0, 10.0, -1};
  const double expected = (0.30 * 0.5 + 0.14 / 3.9 + 0.26 * 0.5) / 0.70;
  EXPECT_NEAR(lod_map_detail(in, false, false, p), expected, 1e-12);
  // With colour in play and the object not salient the denominator is 1.0.
  EXPECT_NEAR(lod_map_detail(in, true, false, p), expected * 0.70, 1e-12);
  EXPECT_NEAR(lod_map_detail(in, true, true, p), expected * 0.70 + 0.30, 1e-12);
  // 4 levels: round((1 - 0.4513) * 3) = round(1.646) = 2.
  EXPECT_EQ(lod_map_level(expected, 4), 2);
}

TEST(LodMap, LevelMappingEndsAndGuards) {
  EXPECT_EQ(lod_map_level(1.0, 4), 0);
  EXPECT_EQ(lod_map_level(0.0, 4), 3);
  EXPECT_EQ(lod_map_level(0.5, 4), 2);  // round(1.5) = 2 (half away from zero)
  EXPECT_EQ(lod_map_level(2.0, 4), 0);
  EXPECT_EQ(lod_map_level(-1.0, 4), 3);
  EXPECT_EQ(lod_map_level(std::nan(""), 4), 0);  // unknown: keep detail
  EXPECT_EQ(lod_map_level(0.0, 1), 0);
  EXPECT_EQ(lod_map_level(0.0, 0), 0);
}

TEST(LodMap, ColourIsSalientWhenFewerThan20PercentShareIt) {
  // 10 objects: one in group 1 (10% < 20%: salient), nine in group 0 (not salient).
  std::vector<LodMapInput> in(10, LodMapInput{0.0, 90.0, 0.0, 0});
  in[3].colour_group = 1;
  const std::vector<std::uint8_t> counts(10, 4);
  std::vector<std::uint8_t> out(10, 99);
  ASSERT_EQ(lod_map_select(in, counts, LodMapParams{}, out), "");
  // Salient: detail = 0.30 + 0.14 / (1 + 0.29 * 90) = 0.30517 -> round(0.6948 * 3) = 2.
  EXPECT_EQ(out[3], 2);
  // Others: detail = 0.00517 -> level 3.
  for (int i : {0, 1, 2, 4, 5, 6, 7, 8, 9}) EXPECT_EQ(out[i], 3) << i;
}

TEST(LodMap, SelectRejectsMismatchedSpans) {
  const std::vector<LodMapInput> in(3);
  const std::vector<std::uint8_t> counts(2, 4);
  std::vector<std::uint8_t> out(3, 7);
  EXPECT_NE(lod_map_select(in, counts, LodMapParams{}, out).find("3 objects"), std::string::npos);
  EXPECT_EQ(out[0], 7);  // untouched
}

TEST(LodMap, DetailNeverLeavesUnitInterval) {
  const LodMapParams p;
  for (double r : {0.0, 1.0, 10.0, 1e9})
    for (double e : {0.0, 5.0, 1e9})
      for (double v : {0.0, 20.0, 1e9}) {
        const double d = lod_map_detail({r, e, v, -1}, false, false, p);
        EXPECT_GE(d, 0.0);
        EXPECT_LE(d, 1.0);
      }
}

}  // namespace
}  // namespace gazelod::lod
