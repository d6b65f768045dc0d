// SPDX-License-Identifier: Apache-2.0
// Makes a model GLB-ready before anything is appended: all buffers merged into buffer 0 (the
// GLB BIN chunk; tinygltf would otherwise base64 the others), and every image that came from
// a URI (file or data:) moved, still encoded, into a bufferView of that buffer.
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace gazelod::bake {

// Returns warnings (an external image tinygltf could not read stays a URI reference).
std::vector<std::string> pack_single_buffer(tinygltf::Model& model);

// Appends `bytes` to buffer 0 at a 4-byte aligned offset (creating the buffer if needed) and
// returns the new bufferView's index. `target` 0 = none.
int append_buffer_view(tinygltf::Model& model, const void* bytes, std::size_t size, int target);

}  // namespace gazelod::bake
