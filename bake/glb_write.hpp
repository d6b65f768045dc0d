// SPDX-License-Identifier: Apache-2.0
// Writes a model as one .glb atomically: to "<out>.tmp-<pid>" in the same folder, then
// rename() over the destination, so a failure never leaves a partial output.
#pragma once

#include <tiny_gltf.h>

#include <string>

namespace gazelod::bake {

// The model must be packed (gltf_pack.hpp). Throws BakeError "PATH: ..." when the folder is
// missing or not writable, or the write/rename fails; the temporary is removed on failure.
void write_glb_atomic(const tinygltf::Model& model, const std::string& path);

}  // namespace gazelod::bake
