// The "scene" part of a scenario: explicit objects and generators (random_field: Reddy 1998's
// random field of objects with a forward path through it), with path-naming errors.
#pragma once

#include "sim/json_fields.hpp"
#include "sim/simulator.hpp"

namespace gazelod::sim {

// Fills scenario.objects and scenario.head_path from the JSON object at `path` ("scene").
// Uses scenario.seed for generators.
void read_scene(const nlohmann::json& scene, const std::string& path, const std::string& source,
                Scenario& scenario);

// A LOD chain of `levels` levels, triangles dropping by `ratio` per level, detail as
// removed_cycles_per_diameter = sqrt(triangles of the level) / 2 (a mesh of T triangles
// carries about sqrt(T) samples across, i.e. sqrt(T)/2 cycles per diameter; level 0: 0).
std::vector<lod::LodLevel> make_lod_chain(std::uint32_t full_triangles, int levels, double ratio);

}  // namespace gazelod::sim
