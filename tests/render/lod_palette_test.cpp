// SPDX-License-Identifier: Apache-2.0
// LOD tints: distinct per level, distinct from the background, readable back from pixels.
#include "render/lod_palette.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace gazelod::render {
namespace {

TEST(LodPalette, LevelsAreDistinctFromEachOtherAndTheBackground) {
  for (std::uint32_t i = 0; i < kLodPaletteSize; ++i) {
    EXPECT_GT(glm::distance(lod_colour(i), background_colour()), 0.3f) << i;
    for (std::uint32_t j = i + 1; j < kLodPaletteSize; ++j)
      EXPECT_GT(glm::distance(lod_colour(i), lod_colour(j)), 0.25f) << i << " vs " << j;
  }
}

TEST(LodPalette, DeepLevelsReuseTheCoarsestColour) {
  EXPECT_EQ(lod_colour(kLodPaletteSize), lod_colour(kLodPaletteSize - 1));
  EXPECT_EQ(lod_colour(1000), lod_colour(kLodPaletteSize - 1));
  EXPECT_NE(lod_colour(kLodPaletteSize - 2), lod_colour(kLodPaletteSize - 1));
}

TEST(LodPalette, NearestLevelRoundTripsEvenWhenSlightlyShaded) {
  for (std::uint32_t i = 0; i < kLodPaletteSize; ++i) {
    EXPECT_EQ(nearest_lod(lod_colour(i)), static_cast<int>(i));
    EXPECT_EQ(nearest_lod(lod_colour(i) * 0.92f), static_cast<int>(i));  // a few degrees off the headlight
  }
  EXPECT_EQ(nearest_lod(background_colour()), -1);
}

TEST(LodPalette, SrgbTransferFunction) {
  EXPECT_FLOAT_EQ(srgb_to_linear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgb_to_linear(1.0f), 1.0f);
  EXPECT_NEAR(srgb_to_linear(0.5f), 0.21404f, 1e-5f);  // IEC 61966-2-1 reference value
  // The seam of the piecewise curve is continuous (both pieces give ~0.0031308).
  EXPECT_NEAR(srgb_to_linear(0.04045f), srgb_to_linear(0.04046f), 1e-6f);
  EXPECT_NEAR(srgb_to_linear(0.04045f), 0.0031308f, 1e-6f);
  EXPECT_FLOAT_EQ(srgb_to_linear(2.0f), 1.0f);  // clamped
}

}  // namespace
}  // namespace gazelod::render
