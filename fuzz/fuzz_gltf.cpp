// SPDX-License-Identifier: Apache-2.0
// Fuzzes bake's glTF loading path: load_gltf (tinygltf, .gltf or .glb by magic) and then
// extract_primitive on every triangle primitive, which is what `gazelod bake` reads before
// simplifying. load_gltf takes a path, so the input goes through a temporary file.
// Invariants: an extracted primitive has whole triangles, in-range indices, finite positions.
#include "fuzz/fuzz_entry.hpp"

#include "bake/bake_error.hpp"
#include "bake/gltf_load.hpp"
#include "bake/mesh_extract.hpp"

#include <cmath>
#include <fstream>
#include <string>
#include <unistd.h>

namespace gazelod::fuzz {
namespace {

std::string temp_path() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/gazelod_fuzz_gltf_" + std::to_string(::getpid()) + ".glb";
}

}  // namespace

int gltf(const std::uint8_t* data, std::size_t size) {
  static const std::string path = temp_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  bake::LoadedGltf loaded;
  try {
    loaded = bake::load_gltf(path);
  } catch (const bake::BakeError&) {
    std::remove(path.c_str());
    return 0;  // the documented rejection
  }
  std::remove(path.c_str());
  const tinygltf::Model& model = loaded.model;
  for (int m = 0; m < static_cast<int>(model.meshes.size()); ++m) {
    for (int p = 0; p < static_cast<int>(model.meshes[m].primitives.size()); ++p) {
      try {
        const bake::PrimitiveGeometry g = bake::extract_primitive(model, m, p);
        check(g.positions_xyz.size() % 3 == 0, "positions not whole vec3s");
        check(g.indices.size() % 3 == 0, "indices not whole triangles");
        const std::size_t vertices = g.positions_xyz.size() / 3;
        for (std::uint32_t i : g.indices) check(i < vertices, "index out of range");
        for (float f : g.positions_xyz) check(std::isfinite(f), "non-finite position");
      } catch (const bake::BakeError&) {
      }
    }
  }
  return 0;
}

}  // namespace gazelod::fuzz

GAZELOD_FUZZ_TARGET(gltf)
