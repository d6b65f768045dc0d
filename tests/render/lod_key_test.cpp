// SPDX-License-Identifier: Apache-2.0
// frame.png's colour key (render/lod_key.hpp): the frame's pixels unchanged above it, one
// swatch per level in its tint (nearest_lod reads them back), labels in ink, and the strip
// taken off again by without_lod_key.
#include "render/lod_key.hpp"

#include "render/lod_palette.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace gazelod::render {
namespace {

RgbaImage frame(std::uint32_t w, std::uint32_t h) {
  RgbaImage img;
  img.width = w, img.height = h;
  img.pixels.resize(static_cast<std::size_t>(w) * h * 4u);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = static_cast<std::uint8_t>(i * 7);
  return img;
}

std::set<int> levels_in_strip(const RgbaImage& keyed, std::uint32_t frame_height) {
  std::set<int> found;
  for (std::uint32_t y = frame_height; y < keyed.height; ++y)
    for (std::uint32_t x = 0; x < keyed.width; ++x) {
      const auto p = keyed.at(x, y);
      const glm::vec3 c(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
      const int l = nearest_lod(c);
      // Exact swatch colours only (the strip's grey and the ink are nearer other tints).
      if (l >= 0 && glm::length(c - lod_colour(static_cast<std::uint32_t>(l))) < 0.01f) found.insert(l);
    }
  return found;
}

TEST(LodKey, SwatchesForEachLevelUnderAnUnchangedFrame) {
  const RgbaImage f = frame(640, 100);
  const RgbaImage keyed = with_lod_key(f, 4);
  ASSERT_EQ(keyed.width, f.width);
  ASSERT_EQ(keyed.height, f.height + lod_key_height_px(640));
  EXPECT_TRUE(std::equal(f.pixels.begin(), f.pixels.end(), keyed.pixels.begin())) << "the frame's own pixels";
  EXPECT_EQ(levels_in_strip(keyed, f.height), (std::set<int>{0, 1, 2, 3}));
  // Labels: some light ink pixels in the strip.
  std::size_t ink = 0;
  for (std::uint32_t y = f.height; y < keyed.height; ++y)
    for (std::uint32_t x = 0; x < keyed.width; ++x) ink += keyed.at(x, y)[0] == 235 && keyed.at(x, y)[1] == 235;
  EXPECT_GT(ink, 4u * 10u) << "an L and a digit per swatch";
  const RgbaImage back = without_lod_key(keyed);
  EXPECT_EQ(back.height, f.height);
  EXPECT_EQ(back.pixels, f.pixels);
}

TEST(LodKey, EveryTintAtMostAndNarrowFrames) {
  EXPECT_EQ(levels_in_strip(with_lod_key(frame(640, 10), 200), 10).size(), kLodPaletteSize);
  EXPECT_EQ(levels_in_strip(with_lod_key(frame(640, 10), 0), 10), (std::set<int>{0})) << "at least full detail";
  const RgbaImage narrow = with_lod_key(frame(120, 10), 8);
  EXPECT_EQ(narrow.height, 10u + lod_key_height_px(120));
  EXPECT_LE(levels_in_strip(narrow, 10).size(), 3u) << "only the swatches that fit";
  EXPECT_EQ(without_lod_key(frame(8, 5)).height, 5u) << "shorter than a strip: left as it is";
  // A wide frame: a larger key, taken off whole.
  const RgbaImage wide = frame(1800, 50);
  const RgbaImage keyed = with_lod_key(wide, 4);
  EXPECT_EQ(lod_key_scale(1800), 3u);
  EXPECT_EQ(keyed.height, 50u + 72u);
  EXPECT_EQ(levels_in_strip(keyed, 50), (std::set<int>{0, 1, 2, 3}));
  EXPECT_EQ(without_lod_key(keyed).pixels, wide.pixels);
}

}  // namespace
}  // namespace gazelod::render
