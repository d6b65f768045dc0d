// SPDX-License-Identifier: Apache-2.0
#include "bake/generated_scene.hpp"

#include "bake/glb_write.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace gazelod::bake {
namespace {

constexpr std::size_t kMaxBufferBytes = std::size_t{1} << 31;  // what a GLB chunk length holds safely

void check(const GeneratedMesh& m, std::size_t index) {
  const std::string who = "generated mesh " + std::to_string(index) + " '" + m.name + "': ";
  if (m.positions.empty() || m.positions.size() % 3 != 0)
    throw std::invalid_argument(who + "positions: need a non-empty multiple of 3, got " +
                                std::to_string(m.positions.size()));
  if (m.normals.size() != m.positions.size())
    throw std::invalid_argument(who + "normals: need one per vertex (" + std::to_string(m.positions.size()) +
                                " values), got " + std::to_string(m.normals.size()));
  if (m.indices.empty() || m.indices.size() % 3 != 0)
    throw std::invalid_argument(who + "indices: need a non-empty multiple of 3, got " +
                                std::to_string(m.indices.size()));
  const std::size_t vertices = m.positions.size() / 3;
  if (vertices > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(who + "more vertices than 32-bit indices reach");
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    if (!std::isfinite(m.positions[i]) || !std::isfinite(m.normals[i]))
      throw std::invalid_argument(who + "vertex " + std::to_string(i / 3) + " is not finite");
  for (std::size_t i = 0; i < m.indices.size(); ++i)
    if (m.indices[i] >= vertices)
      throw std::invalid_argument(who + "index " + std::to_string(i) + " is " + std::to_string(m.indices[i]) +
                                  ", but there are only " + std::to_string(vertices) + " vertices");
}

int add_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  auto& buffer = model.buffers[0].data;
  const std::size_t offset = (buffer.size() + 3) & ~std::size_t{3};  // 4-byte aligned accessors
  if (offset + bytes > kMaxBufferBytes)
    throw std::invalid_argument("generated scene: more than 2 GiB of vertex and index data");
  buffer.resize(offset + bytes);
  std::memcpy(buffer.data() + offset, data, bytes);
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = offset;
  v.byteLength = bytes;
  v.target = target;
  model.bufferViews.push_back(v);
  return static_cast<int>(model.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, std::size_t count) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = component;
  a.type = type;
  a.count = count;
  model.accessors.push_back(a);
  return static_cast<int>(model.accessors.size() - 1);
}

}  // namespace

GeneratedStats generated_stats(const std::vector<GeneratedMesh>& meshes) {
  GeneratedStats s;
  s.meshes = meshes.size();
  bool first = true;
  for (const GeneratedMesh& m : meshes) {
    s.triangles += m.triangles();
    s.vertices += m.positions.size() / 3;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const double v = m.positions[i];
      const std::size_t c = i % 3;
      s.min_m[c] = first ? v : std::min(s.min_m[c], v);
      s.max_m[c] = first ? v : std::max(s.max_m[c], v);
      if (c == 2) first = false;
    }
  }
  return s;
}

tinygltf::Model generated_model(const std::vector<GeneratedMesh>& meshes) {
  if (meshes.empty()) throw std::invalid_argument("generated scene: no meshes");
  for (std::size_t i = 0; i < meshes.size(); ++i) check(meshes[i], i);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "gazelod scene generate";
  model.buffers.emplace_back();
  tinygltf::Scene scene;
  scene.name = "generated";
  for (const GeneratedMesh& m : meshes) {
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    const std::size_t vertices = m.positions.size() / 3;
    const int pos = add_accessor(
        model, add_view(model, m.positions.data(), m.positions.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices);
    // glTF requires POSITION's bounds.
    auto& a = model.accessors[static_cast<std::size_t>(pos)];
    a.minValues = {m.positions[0], m.positions[1], m.positions[2]};
    a.maxValues = a.minValues;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      a.minValues[i % 3] = std::min(a.minValues[i % 3], static_cast<double>(m.positions[i]));
      a.maxValues[i % 3] = std::max(a.maxValues[i % 3], static_cast<double>(m.positions[i]));
    }
    p.attributes["POSITION"] = pos;
    p.attributes["NORMAL"] = add_accessor(
        model, add_view(model, m.normals.data(), m.normals.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices);
    p.indices = add_accessor(model,
                             add_view(model, m.indices.data(), m.indices.size() * sizeof(std::uint32_t),
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, m.indices.size());
    tinygltf::Mesh mesh;
    mesh.name = m.name;
    mesh.primitives.push_back(std::move(p));
    model.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.name = m.name;
    node.mesh = static_cast<int>(model.meshes.size() - 1);
    model.nodes.push_back(std::move(node));
    scene.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
  }
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;
  return model;
}

void write_generated_glb(const std::vector<GeneratedMesh>& meshes, const std::string& path) {
  write_glb_atomic(generated_model(meshes), path);
}

}  // namespace gazelod::bake
