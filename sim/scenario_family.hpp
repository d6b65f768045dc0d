// SPDX-License-Identifier: Apache-2.0
// A family of random but plausible scenarios, one per seed, for tuning and evaluating on
// scenes nobody hand-picked ("a policy fitted to three files fails on the fourth"). Each seed
// draws, independently:
//   - a display among the eye-tracked presets;
//   - a head-motion profile: still, sweeps, sweeps with fast turns, or walking (0.8-1.6 m/s)
//     with sweeps and a turn and back;
//   - the eyes: fixations and main-sequence saccades (fixation lengths and amplitudes drawn),
//     held in the world by the vestibulo-ocular reflex or, in a quarter of the moving-head
//     seeds, carried by the head; a pursuit of a target crossing at 5-30 deg/s in 60 % of them;
//   - the tracker: 60-250 Hz, 5-80 ms latency, 0.2-1.5 deg noise, blinks, sometimes dropouts;
//   - an object field: near clutter, an open field or a deep one (counts, sizes, depths, LOD
//     chains of 3-5 levels dropping 2-4x a level).
// The result is scenario JSON (sim/scenarios/README.md) that load_scenario_json accepts for
// every seed; the same seed gives the same text, bit for bit (auxiliary/random.hpp).
#pragma once

#include <cstdint>
#include <string>

namespace gazelod::sim {

struct FamilyScenario {
  std::string json;     // the scenario, version 1
  std::string summary;  // one line: "walk 1.3 m/s, vor, pursuit 18 deg/s, psvr2, 120 Hz 35 ms 0.8 deg, open field"
};

// A what-if for measuring what the tracker costs: the seed's scenario with parts of its tracker
// made ideal. Everything else (head, eyes, blinks, dropouts, display, objects) is the seed's
// own draw, unchanged: each draw has its own key (auxiliary/random.hpp), so skipping a value
// moves no other.
struct IdealTracker {
  bool latency = false;  // 0 ms from the eye to the sample
  bool noise = false;    // 0 deg of noise
  bool rate = false;     // 1000 Hz (the display still polls it once a frame)
  bool any() const { return latency || noise || rate; }
};

// 20 s of the seed's draw; `duration_s` > 0 shortens or lengthens it (effects keep their times).
// calibration_offset_deg > 0 (a what-if for the tracker's accuracy, at most 30): every sample
// is off by about that angle (a yaw and a pitch offset; the yaw's arc shrinks with the cosine
// of the gaze's pitch), in a direction drawn for the seed, as a tracker's calibration error is
// (the calibration_offset effect, appended last so that no other effect's random stream moves).
// The family's trackers are otherwise unbiased: their error is noise only.
FamilyScenario family_scenario(std::uint64_t seed, double duration_s = 20.0, IdealTracker ideal = {},
                               double calibration_offset_deg = 0.0);

// "latency", "noise", "rate" (comma-separated, any order) or "all"; "" or "none": none. Returns
// false, leaving `out` as it was, for anything else.
bool parse_ideal_tracker(const std::string& text, IdealTracker& out);
// What parse_ideal_tracker accepts, for a refusal's message.
inline constexpr const char* kIdealTrackerNames = "latency, noise, rate (comma-separated), all or none";

}  // namespace gazelod::sim
