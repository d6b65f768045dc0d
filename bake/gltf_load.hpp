// SPDX-License-Identifier: Apache-2.0
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

// How a glTF's external files (buffer and image `uri`s) may be read. By default only regular
// files inside the glTF's own folder (after resolving `..` and symbolic links): a file that
// names /etc/passwd or ../../secret, a FIFO (which would hang) or a directory is refused with
// the uri and the reason.
struct GltfLoadOptions {
  bool allow_outside_folder = false;  // `bake --allow-outside-uris`: absolute paths and escapes too
};

// Throws BakeError "PATH: ..." for an unreadable, truncated or malformed file.
LoadedGltf load_gltf(const std::string& path, GltfLoadOptions options = {});

}  // namespace gazelod::bake
