// SPDX-License-Identifier: Apache-2.0
// Reads a .gltf or .glb (told apart by the GLB magic, not the file name) with tinygltf.
// Images are kept as their encoded bytes (never decoded and re-encoded), so textures survive
// the bake bit for bit.
#pragma once

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::bake {

struct LoadedGltf {
  tinygltf::Model model;
  std::vector<std::string> warnings;                  // tinygltf's, e.g. an external image it could not read
  std::vector<std::filesystem::path> external_files;  // the buffers and images read, resolved
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

// Throws BakeError when `out` is one of the files `in` was read from (itself, a buffer, an
// image, by any name): the bake would write over its own input.
void refuse_output_over_input(const std::string& in, const LoadedGltf& loaded, const std::string& out);

}  // namespace gazelod::bake
