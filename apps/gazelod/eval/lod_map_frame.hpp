// SPDX-License-Identifier: Apache-2.0
// The thesis's LOD map (apps/gazelod/eval/lod_map.hpp) evaluated beside the plugin in `gazelod run`: per frame,
// the same objects, eye, gaze and head motion the plugin used, run through the map policy
// offline (nothing it picks is drawn), so reports can compare its triangles and average LOD
// with Reddy's criteria sets. Eccentricity, retinal speed and angular radius come from
// lod::select_lods' diagnostics, i.e. exactly the plugin's geometry.
#pragma once

#include "lod/lod_chain.hpp"
#include "lod/display.hpp"
#include "apps/gazelod/eval/lod_map.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::cli {

struct LodMapFrame {
  std::uint64_t triangles = 0;       // per eye
  std::uint64_t lod_sum = 0;         // sum of the chosen levels (average = lod_sum / objects)
  std::vector<std::uint8_t> levels;  // per object
};

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

// The map's choice for one frame. `objects` and `radii` are indexed like `chains`;
// `eye_velocity_m_s` is the head's translation (the simulator's truth). Objects the
// selection rejects (non-finite data) keep level 0.
LodMapFrame lod_map_frame(const std::vector<std::vector<lod::LodLevel>>& chains,
                          std::span<const sim::ObjectState> objects, std::span<const double> radii,
                          const FrameDiagnostics& d, const glm::dvec3& eye_velocity_m_s,
                          const lod::LodMapParams& params = {});

}  // namespace gazelod::cli
