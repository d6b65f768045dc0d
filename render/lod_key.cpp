// SPDX-License-Identifier: Apache-2.0
#include "render/lod_key.hpp"

#include "render/lod_palette.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace gazelod::render {
namespace {

// A 5 x 7 pixel font for what the key writes: L, +, and the digits (one row a byte, the high
// five bits of each row from left to right).
const std::array<std::uint8_t, 7>* glyph(char c) {
  static const std::array<std::uint8_t, 7> digits[10] = {
      {0x70, 0x88, 0x98, 0xA8, 0xC8, 0x88, 0x70}, {0x20, 0x60, 0x20, 0x20, 0x20, 0x20, 0x70},
      {0x70, 0x88, 0x08, 0x10, 0x20, 0x40, 0xF8}, {0xF8, 0x10, 0x20, 0x10, 0x08, 0x88, 0x70},
      {0x10, 0x30, 0x50, 0x90, 0xF8, 0x10, 0x10}, {0xF8, 0x80, 0xF0, 0x08, 0x08, 0x88, 0x70},
      {0x30, 0x40, 0x80, 0xF0, 0x88, 0x88, 0x70}, {0xF8, 0x08, 0x10, 0x20, 0x40, 0x40, 0x40},
      {0x70, 0x88, 0x88, 0x70, 0x88, 0x88, 0x70}, {0x70, 0x88, 0x88, 0x78, 0x08, 0x10, 0x60}};
  static const std::array<std::uint8_t, 7> letter_l{0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0xF8};
  static const std::array<std::uint8_t, 7> plus{0x00, 0x20, 0x20, 0xF8, 0x20, 0x20, 0x00};
  if (c >= '0' && c <= '9') return &digits[c - '0'];
  if (c == 'L') return &letter_l;
  if (c == '+') return &plus;
  return nullptr;
}

void put(RgbaImage& img, std::uint32_t x, std::uint32_t y, std::array<std::uint8_t, 3> rgb) {
  if (x >= img.width || y >= img.height) return;
  const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 4u;
  img.pixels[i] = rgb[0], img.pixels[i + 1] = rgb[1], img.pixels[i + 2] = rgb[2], img.pixels[i + 3] = 255;
}

std::array<std::uint8_t, 3> bytes(const glm::vec3& c) {
  const auto b = [](float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return {b(c.r), b(c.g), b(c.b)};
}

}  // namespace

RgbaImage with_lod_key(const RgbaImage& frame, std::uint32_t levels) {
  RgbaImage out;
  out.width = frame.width;
  out.height = frame.height + lod_key_height_px(frame.width);
  out.pixels = frame.pixels;
  out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 4u, 0);
  const std::array<std::uint8_t, 3> strip{40, 40, 40}, ink{235, 235, 235};
  for (std::uint32_t y = frame.height; y < out.height; ++y)
    for (std::uint32_t x = 0; x < out.width; ++x) put(out, x, y, strip);
  const std::uint32_t shown =
      std::min<std::uint32_t>(std::max<std::uint32_t>(levels, 1), static_cast<std::uint32_t>(kLodPaletteSize));
  const std::uint32_t s = lod_key_scale(frame.width);
  const std::uint32_t kSwatch = 14 * s, kStep = 56 * s;
  const std::uint32_t top = frame.height + (lod_key_height_px(frame.width) - kSwatch) / 2;
  for (std::uint32_t k = 0; k < shown; ++k) {
    const std::uint32_t x0 = 6 * s + k * kStep;
    if (x0 + kStep > out.width + 8 * s) break;
    const auto tint = bytes(lod_colour(k));
    for (std::uint32_t y = top; y < top + kSwatch; ++y)
      for (std::uint32_t x = x0; x < x0 + kSwatch; ++x) put(out, x, y, tint);
    std::string label = "L" + std::to_string(k);
    if (k + 1 == shown && levels > kLodPaletteSize) label += "+";
    std::uint32_t gx = x0 + kSwatch + 4 * s;
    for (char c : label) {
      if (const auto* g = glyph(c))
        for (std::uint32_t row = 0; row < 7; ++row)
          for (std::uint32_t col = 0; col < 5; ++col)
            if ((*g)[row] & (0x80u >> col))
              for (std::uint32_t dy = 0; dy < s; ++dy)
                for (std::uint32_t dx = 0; dx < s; ++dx) put(out, gx + col * s + dx, top + (3 + row) * s + dy, ink);
      gx += 6 * s;
    }
  }
  return out;
}

RgbaImage without_lod_key(const RgbaImage& image) {
  const std::uint32_t key = lod_key_height_px(image.width);
  if (image.height <= key) return image;
  RgbaImage out;
  out.width = image.width;
  out.height = image.height - key;
  out.pixels.assign(
      image.pixels.begin(),
      image.pixels.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(out.width) * out.height * 4u));
  return out;
}

}  // namespace gazelod::render
