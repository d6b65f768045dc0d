// SPDX-License-Identifier: Apache-2.0
// gazelod bake: a glTF scene in, the same scene with an MSFT_lod chain per mesh node out.
// Pipeline: gltf_load -> mesh_extract -> simplify_chain (per primitive) -> mesh chain (here)
// -> gltf_pack + msft_lod_writer -> glb_write. With options.profile_viewpoints 6 or 18 each
// chain is also rendered (Reddy 3.3, profile_render.hpp) and the figure stored beside the
// geometric one. `gazelod bake --clusters` (a cluster hierarchy per primitive instead of a
// chain per node) is bake/cluster/cluster_bake.hpp.
#pragma once

#include "bake/gltf_load.hpp"
#include "bake/simplify_chain.hpp"

#include <tiny_gltf.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gazelod::bake {

struct BakeOptions {
  ChainOptions chain;
  std::function<void(const std::string&)> progress;  // one line per call; may be empty
  int profile_viewpoints = 0;                        // 0: no rendered profile; 6 or 18 viewpoints (needs Vulkan)
  GltfLoadOptions load;                              // where external uris may point
};

struct LevelReport {
  std::uint32_t triangles = 0, vertices = 0;
  double error_relative = 0.0, error_m = 0.0, detail_cycles_per_diameter = 0.0;
  bool sloppy = false;
  double rendered_cycles_per_diameter = -1.0;  // < 0: not profiled
};

struct MeshReport {
  int mesh = -1;
  std::string name;
  std::size_t primitives = 0;
  double diameter_m = 0.0;
  double seconds = 0.0;
  double profile_seconds = 0.0;     // part of `seconds` spent on the rendered profile
  std::vector<LevelReport> levels;  // levels[0] is the input
  std::string note;                 // why the chain is shorter than asked, if it is
};

struct BakeReport {
  std::vector<MeshReport> meshes;  // meshes used by at least one node, in mesh order
  std::vector<std::string> warnings;
  std::size_t lod_nodes = 0;  // nodes that got an MSFT_lod chain
  std::uint64_t input_triangles = 0;
  double seconds = 0.0;
};

// Bakes a loaded model in place (packs it, adds the chains). Throws BakeError naming the mesh
// and primitive for geometry it cannot handle; the model is then unusable. With a profile,
// throws render::NoVulkanDevice without Vulkan, std::invalid_argument for bad viewpoints.
BakeReport bake_model(tinygltf::Model& model, const BakeOptions& options);

// Loads `in`, bakes, writes `out` atomically. Throws BakeError; `out` is untouched on failure.
BakeReport bake_file(const std::string& in, const std::string& out, const BakeOptions& options);

// Ratios for --levels N (N levels in all, N >= 2): each coarser level has a quarter of the
// triangles of the one before (Reddy's chain 3928, 834, 254, 76 falls by 3.3x to 4.7x).
std::vector<double> ratios_for_levels(int levels);

}  // namespace gazelod::bake
