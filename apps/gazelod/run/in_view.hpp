// SPDX-License-Identifier: Apache-2.0
// What is in view each frame of `gazelod run`: the objects whose bounding sphere overlaps the
// frustum, and each criteria set's triangles and levels over them (the Reddy 1998 tables and
// the audit count objects in view).
#pragma once

#include "lod/display.hpp"
#include "lod/lod_chain.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::cli {

// The sets an evaluation reports, in this order in InViewFrame's arrays.
enum EvalSet : std::size_t { kSetNone, kSetSize, kSetSizeEcc, kSetSizeVel, kSetDrawn, kSetLodMap, kEvalSets };

// Sums over the objects whose bounding sphere overlaps the view frustum (the display's first
// view, from the head pose): what a renderer with frustum culling (Reddy 1998's Performer)
// draws, and the objects Reddy 1998's average LOD is about.
struct InViewFrame {
  std::int64_t objects = 0;
  std::array<std::uint64_t, kEvalSets> triangles{};
  std::array<std::uint64_t, kEvalSets> lod_sum{};
};

// Whether a sphere (world) overlaps the frustum of `fov` seen from `eye` with orientation
// `head` (world from head; OpenXR axes: -Z forward, +X right, +Y up). A sphere around the eye
// is in view. Angles via atan2.
bool sphere_in_view(const glm::dvec3& center_m, double radius_m, const glm::dvec3& eye_m, const glm::dquat& head,
                    const lod::FovRad& fov);

InViewFrame in_view_frame(const std::vector<std::vector<lod::LodLevel>>& chains,
                          std::span<const sim::ObjectState> objects, std::span<const double> radii,
                          const FrameDecisions& decisions, const FrameDiagnostics& d,
                          std::span<const std::uint8_t> lod_map_levels, const glm::dvec3& eye_m, const glm::dquat& head,
                          const lod::FovRad& fov);

// Sum of the levels in `lods` (0 for an empty span).
std::uint64_t lod_sum(std::span<const std::uint8_t> lods);

}  // namespace gazelod::cli
