// SPDX-License-Identifier: Apache-2.0
// The debug tint per LOD level, so a screenshot shows which level each object got:
// level 0 (full detail) red, then orange, yellow, green, cyan, blue, violet, grey; deeper
// levels reuse the last colour. Colours are sRGB display values in 0..1.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

namespace gazelod::render {

inline constexpr std::size_t kLodPaletteSize = 8;

// Not an LOD: debug markers (the foveal circle), drawn white and not counted as scene triangles.
inline constexpr std::uint32_t kMarkerLevel = 0xFFFFFFFFu;

// The tint of `level`; white for kMarkerLevel.
glm::vec3 lod_colour(std::uint32_t level);

// Cleared background (dark blue-grey), distinct from every level's colour.
glm::vec3 background_colour();

// The level whose colour is nearest to an sRGB pixel (Euclidean in 0..1 RGB), for reading
// screenshots back; the background counts as "no object" and returns -1.
int nearest_lod(const glm::vec3& srgb);

// sRGB transfer function (IEC 61966-2-1), for targets whose format encodes sRGB on write.
float srgb_to_linear(float c);

}  // namespace gazelod::render
