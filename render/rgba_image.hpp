// SPDX-License-Identifier: Apache-2.0
// A frame read back from the GPU: 8-bit RGBA, rows top to bottom, no padding.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace gazelod::render {

struct RgbaImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4

  std::array<std::uint8_t, 4> at(std::uint32_t x, std::uint32_t y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4u;
    return {pixels.at(i), pixels.at(i + 1), pixels.at(i + 2), pixels.at(i + 3)};
  }
  // Colour in 0..1 (as stored: sRGB display values for sRGB and UNORM targets alike).
  glm::vec3 rgb(std::uint32_t x, std::uint32_t y) const {
    const auto p = at(x, y);
    return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
  }
};

}  // namespace gazelod::render
