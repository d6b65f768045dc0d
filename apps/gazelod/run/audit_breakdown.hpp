// SPDX-License-Identifier: Apache-2.0
// Where the audit's figures come from: the object-frames of a run split three ways, so that a
// triangle ratio above 1 or a switch rate above the oracle's can be traced to a cause.
//   - the true gaze state (from the simulator, never the plugin's estimate): a fixation with a
//     still head, a fixation held through head motion by the vestibulo-ocular reflex, the eyes
//     carried by a moving head (gaze moving in the world with it), pursuit, a saccade with the
//     suppression after it, a blink;
//   - the object's class: near or far (kNearM from the eye to the sphere's surface) and in or
//     outside the foveal cone (true eccentricity of its nearest point within M(E)'s seam);
//   - the plugin's own reading of the eye (the conditioner's fixation, saccade, pursuit, loss),
//     where a misread shows as excess or switches against the true state;
//   - the criterion that set the oracle's level (lod::Criterion): which part of Reddy's rule
//     the plugin failed to exploit where it drew finer than the oracle.
// Each drawn-finer object-frame's excess triangles (drawn - oracle) are split further into the
// part the switch policy held (drawn finer than the plugin's own perceptual level) and the
// part its selection chose (perceptual finer than the oracle: gaze uncertainty, latency, a
// misread eye state). Switches count raw, "visible" (the coarser of the two levels is coarser
// than the oracle allows now, so the change itself is above threshold) and the oracle's own.
#pragma once

#include "lod/lod_chain.hpp"
#include "sim/simulator.hpp"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <ostream>
#include <span>
#include <vector>

namespace gazelod::cli {

enum class TrueGaze : std::uint8_t { fixation, vor, carried, pursuit, saccade, blink };
inline constexpr std::size_t kTrueGazeCount = 6;
const char* to_string(TrueGaze g);

// Below this head speed the head counts as still (a fixation, not VOR or carried): the
// head's own tremor and the simulator's sway stay under it.
inline constexpr double kHeadStillDps = 5.0;
// An object whose nearest point is closer than this is "near" (arm's length to a room).
inline constexpr double kNearM = 10.0;

// blink > saccade or its suppression window > pursuit > head still (fixation) > the gaze
// moving in the world at less than half the head's speed (VOR) > carried.
TrueGaze classify_true_gaze(const sim::EyeTruth& truth, bool suppressed, double head_speed_dps,
                            double gaze_world_speed_dps);

enum class ObjectClass : std::uint8_t { near_in_cone, near_outside, far_in_cone, far_outside };
inline constexpr std::size_t kObjectClassCount = 4;
const char* to_string(ObjectClass c);

struct BreakdownCell {
  std::int64_t object_frames = 0;  // in view
  std::int64_t degraded = 0;       // drawn coarser than the oracle
  std::uint64_t drawn_triangles = 0, oracle_triangles = 0;
  std::uint64_t excess_held = 0;      // drawn finer than perceptual (the switch policy's hold)
  std::uint64_t excess_selected = 0;  // perceptual finer than the oracle (the selection's margin)
  std::int64_t switches = 0, visible_switches = 0, oracle_switches = 0;
  double object_s = 0.0;
};

struct AuditBreakdown {
  std::array<BreakdownCell, kTrueGazeCount> gaze{};
  std::array<BreakdownCell, kObjectClassCount> objects{};
  std::array<BreakdownCell, 4> estimate{};   // indexed by gaze::EyeMotion (the plugin's reading)
  std::array<BreakdownCell, 6> criterion{};  // indexed by lod::Criterion (the oracle's)
};

struct BreakdownFrameInput {
  const std::vector<std::vector<lod::LodLevel>>* chains = nullptr;
  std::span<const std::uint8_t> drawn, previous;          // previous empty on the first frame
  std::span<const std::uint8_t> perceptual;               // the plugin's level before switching
  std::span<const std::uint8_t> oracle, previous_oracle;  // previous_oracle empty on the first frame
  std::span<const std::uint8_t> oracle_limited_by;        // lod::Criterion
  std::span<const std::uint8_t> in_view;
  std::span<const float> eccentricity_deg;  // the oracle's, to the nearest point
  std::span<const float> distance_m;        // eye to the sphere's surface
  TrueGaze gaze = TrueGaze::fixation;
  std::uint8_t estimate = 0;  // gaze::EyeMotion, FrameDiagnostics::eye_motion
  double frame_s = 0.0;
};

// Adds one frame; objects past the shortest span are ignored. No allocation.
void add_breakdown_frame(const BreakdownFrameInput& in, AuditBreakdown& b);

// Whether a switch between levels a and b is visible when the oracle allows `oracle`: the
// coarser of the two removes detail the eye would see.
inline bool switch_visible(std::uint8_t a, std::uint8_t b, std::uint8_t oracle) {
  return a != b && (a > b ? a : b) > oracle;
}

// {"by_true_gaze": {"fixation": {...}, ...}, "by_object": {...}, "by_plugin_estimate": {...},
//  "by_oracle_criterion": {...}}.
nlohmann::json breakdown_json(const AuditBreakdown& b);
// The terminal table: one row per non-empty cell.
void print_breakdown(const AuditBreakdown& b, std::ostream& out);

}  // namespace gazelod::cli
