// SPDX-License-Identifier: Apache-2.0
// Writes a model as one .glb atomically (auxiliary/atomic_file.hpp: a temporary in the same
// folder, fsynced, then renamed over the destination), so a failure never leaves a partial
// output or a temporary.
#pragma once

#include <tiny_gltf.h>

#include <string>

namespace gazelod::bake {

// The model must be packed (gltf_pack.hpp). Throws BakeError "PATH: ..." when the folder is
// missing or not writable, or the write/rename fails; the temporary is removed on failure.
void write_glb_atomic(const tinygltf::Model& model, const std::string& path);

}  // namespace gazelod::bake
