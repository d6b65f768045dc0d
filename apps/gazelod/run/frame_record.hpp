// SPDX-License-Identifier: Apache-2.0
// One counted frame of `gazelod run` as the report keeps it (run/report.hpp's FrameRecord):
// the triangles and levels of every criteria set, what is in view, and the plugin's reading of
// the gaze. Counting only: nothing here changes what the plugin drew.
#pragma once

#include "apps/gazelod/run/report.hpp"
#include "lod/display.hpp"
#include "lod/lod_chain.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::cli {

// The triangles of `chains` at `lods` (per object; a level past a chain's end is its last).
std::uint64_t chain_triangles(const std::vector<std::vector<lod::LodLevel>>& chains,
                              std::span<const std::uint8_t> lods);

struct FrameRecordInput {
  const std::vector<std::vector<lod::LodLevel>>* chains = nullptr;  // plugin object k's levels
  std::span<const sim::ObjectState> objects;                        // plugin object k, this frame
  std::span<const double> radii;
  const FrameDecisions* decisions = nullptr;
  const FrameDiagnostics* diagnostics = nullptr;
  sim::HeadState head;  // the simulator's head: where the view frustum is
  lod::FovRad fov{};    // the display's first view
  std::uint64_t triangles_full = 0;
  bool lod_map = false;  // evaluate the LOD-map thesis's policy on this frame too (RunOptions::lod_map)
};

// Everything but the timing, the index, the saccade mark and the audit, which the session fills.
FrameRecord record_frame(const FrameRecordInput& in);

}  // namespace gazelod::cli
