// SPDX-License-Identifier: Apache-2.0
// Where a glTF scene puts its meshes: node transforms (glTF 2.0 spec 3.5.3) composed from the
// roots of the scene(s) a viewer sees, in double precision.
#pragma once

#include <tiny_gltf.h>

#include <glm/mat4x4.hpp>

#include <vector>

namespace gazelod::bake {

// A node's own transform: `matrix` when given (column-major, as glTF), else T * R * S.
glm::dmat4 node_local_matrix(const tinygltf::Node& node);

struct MeshInstance {
  int node = -1, mesh = -1;
  glm::dmat4 world{1.0};  // mesh space -> glTF world
};

// Every node with a mesh under the default scene (all scenes when there is none), with its
// world transform. Tolerant: a missing node or mesh reference or a cycle is skipped, not
// reported (load_baked reports them); this only tells the bake where meshes meet.
std::vector<MeshInstance> mesh_instances(const tinygltf::Model& model);

}  // namespace gazelod::bake
