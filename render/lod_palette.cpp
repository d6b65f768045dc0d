// SPDX-License-Identifier: Apache-2.0
#include "render/lod_palette.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gazelod::render {
namespace {

constexpr std::array<glm::vec3, kLodPaletteSize> kPalette{{
    {0.90f, 0.10f, 0.10f},  // 0 red: full detail
    {0.95f, 0.55f, 0.05f},  // 1 orange
    {0.95f, 0.90f, 0.10f},  // 2 yellow
    {0.15f, 0.80f, 0.20f},  // 3 green
    {0.10f, 0.85f, 0.90f},  // 4 cyan
    {0.15f, 0.30f, 0.95f},  // 5 blue
    {0.65f, 0.20f, 0.90f},  // 6 violet
    {0.75f, 0.75f, 0.75f},  // 7 grey: coarsest
}};

}  // namespace

glm::vec3 lod_colour(std::uint32_t level) {
  if (level == kMarkerLevel) return {1.0f, 1.0f, 1.0f};
  return kPalette[std::min<std::size_t>(level, kPalette.size() - 1)];
}

glm::vec3 background_colour() {
  return {0.08f, 0.08f, 0.12f};
}

int nearest_lod(const glm::vec3& srgb) {
  int best = -1;
  float best_d = glm::distance(srgb, background_colour());
  for (std::size_t i = 0; i < kPalette.size(); ++i) {
    const float d = glm::distance(srgb, kPalette[i]);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

float srgb_to_linear(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace gazelod::render
