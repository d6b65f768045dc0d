// SPDX-License-Identifier: Apache-2.0
// node_world.hpp: the node transform and the scene walk.
#include "bake/node_world.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace gazelod::bake {
namespace {

void visit(const tinygltf::Model& m, int node, const glm::dmat4& parent, std::vector<bool>& on_path,
           std::vector<MeshInstance>& out) {
  if (node < 0 || static_cast<std::size_t>(node) >= m.nodes.size() || on_path[static_cast<std::size_t>(node)]) return;
  on_path[static_cast<std::size_t>(node)] = true;
  const tinygltf::Node& n = m.nodes[static_cast<std::size_t>(node)];
  const glm::dmat4 world = parent * node_local_matrix(n);
  if (n.mesh >= 0 && static_cast<std::size_t>(n.mesh) < m.meshes.size()) out.push_back({node, n.mesh, world});
  for (int c : n.children) visit(m, c, world, on_path, out);
  on_path[static_cast<std::size_t>(node)] = false;
}

}  // namespace

glm::dmat4 node_local_matrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());
  glm::dmat4 m(1.0);
  if (n.translation.size() == 3)
    m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
  if (n.rotation.size() == 4)  // glTF stores x, y, z, w
    m *= glm::mat4_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
  if (n.scale.size() == 3) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
  return m;
}

std::vector<MeshInstance> mesh_instances(const tinygltf::Model& m) {
  std::vector<MeshInstance> out;
  std::vector<bool> on_path(m.nodes.size(), false);
  for (std::size_t s = 0; s < m.scenes.size(); ++s) {
    if (m.defaultScene >= 0 && static_cast<int>(s) != m.defaultScene) continue;
    for (int root : m.scenes[s].nodes) visit(m, root, glm::dmat4(1.0), on_path, out);
  }
  return out;
}

}  // namespace gazelod::bake
