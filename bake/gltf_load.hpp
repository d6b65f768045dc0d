// Reads a .gltf or .glb (told apart by the GLB magic, not the file name) with tinygltf.
// Images are kept as their encoded bytes (never decoded and re-encoded), so textures survive
// the bake bit for bit.
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace gazelod::bake {

struct LoadedGltf {
  tinygltf::Model model;
  std::vector<std::string> warnings;  // tinygltf's, e.g. an external image it could not read
};

// Throws BakeError "PATH: ..." for an unreadable, truncated or malformed file.
LoadedGltf load_gltf(const std::string& path);

}  // namespace gazelod::bake
