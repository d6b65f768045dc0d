// SPDX-License-Identifier: Apache-2.0
// The "scene" part of a scenario: explicit objects and generators (random_field: Reddy 1998's
// random field of objects with a forward path through it), with path-naming errors, and the
// limits on a scenario as a whole (docs/hardening.md, "Scenario limits"), checked while
// reading, before the objects they imply are allocated.
#pragma once

#include "sim/json_fields.hpp"
#include "sim/simulator.hpp"

#include <cstddef>

namespace gazelod::sim {

// Limits on one scenario. Each is checked before anything it counts is allocated, and its
// error names the JSON path and the limit.
inline constexpr std::size_t kMaxScenarioBytes = std::size_t{64} << 20;  // the JSON text (64 MiB)
inline constexpr int kMaxJsonDepth = 64;                                 // nesting of arrays / objects
inline constexpr std::size_t kMaxObjects = 1'000'000;                    // scene objects in all (explicit + generated)
inline constexpr std::size_t kMaxLevels = 4'000'000;                     // LOD levels of all objects together
inline constexpr std::size_t kMaxEffects = 256;                          // entries of "effects"
// The scenario's estimated memory: objects (scenario_object_bytes) and head_track traces
// (4 bytes of memory per byte of trace file, a conservative bound for its rows).
inline constexpr std::size_t kMaxScenarioMemoryBytes = std::size_t{1} << 30;  // 1 GiB
inline constexpr double kMaxTrackerLatencyMs = 1000.0;                        // all tracker_latency effects together

// What a scenario holds so far; read_scene adds to it and refuses to go past the limits.
struct ScenarioTally {
  std::size_t objects = 0;
  std::size_t levels = 0;
  std::size_t memory_bytes = 0;
};

// Estimated memory of one scene object: the object, its name, its levels and its state in
// the simulator.
std::size_t scenario_object_bytes(std::size_t name_length, std::size_t levels);

// "1.5 GiB", "528 MiB", "12 KiB" for messages.
std::string bytes_text(std::size_t bytes);

// Fills scenario.objects and scenario.head_path from the JSON object at `path` ("scene").
// Uses scenario.seed for generators. Every object's chain passes lod::validate_chain. All
// objects and generators are counted against the limits (adding to `tally`) before the first
// object is made.
void read_scene(const nlohmann::json& scene, const std::string& path, const std::string& source, Scenario& scenario,
                ScenarioTally& tally);

// A LOD chain of `levels` levels, triangles dropping by `ratio` per level, detail as
// removed_cycles_per_diameter = sqrt(triangles of the level) / 2 (a mesh of T triangles
// carries about sqrt(T) samples across, i.e. sqrt(T)/2 cycles per diameter; level 0: 0).
std::vector<lod::LodLevel> make_lod_chain(std::uint32_t full_triangles, int levels, double ratio);

}  // namespace gazelod::sim
