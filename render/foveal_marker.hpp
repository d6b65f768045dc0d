// SPDX-License-Identifier: Apache-2.0
// The debug view's foveal circle: a ring of small dots at a fixed angle around the gaze ray,
// drawn with the same pipeline as the objects (marker tint, not an LOD colour). `gazelod run`
// draws the plugin's foveal cone with it (FrameDiagnostics::foveal_cone: out to where Reddy
// 1998's M(E) leaves 1, widened by the gaze error).
#pragma once

#include "render/frame_renderer.hpp"
#include "render/lod_palette.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

namespace gazelod::render {

inline constexpr std::size_t kFovealMarkerDots = 48;

// Fills `out` with dots (lod_level kMarkerLevel) on the circle `radius_deg` from the gaze ray,
// `distance_m` from the eye, each `dot_deg` in angular radius. Writes nothing (returns 0)
// when the gaze direction is zero or not finite. Returns the number of items written.
std::size_t foveal_circle(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, double radius_deg, std::uint32_t mesh,
                          std::span<DrawItem> out, double distance_m = 0.25, double dot_deg = 0.2);

}  // namespace gazelod::render
