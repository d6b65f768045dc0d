// SPDX-License-Identifier: Apache-2.0
// MSFT_lod nodes, meshes and index accessors (see msft_lod_writer.hpp).
#include "bake/msft_lod_writer.hpp"

#include "bake/bake_error.hpp"
#include "bake/detail.hpp"
#include "bake/gltf_pack.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

namespace gazelod::bake {
namespace {

using Object = tinygltf::Value::Object;

int add_index_accessor(tinygltf::Model& m, const std::vector<std::uint32_t>& idx, std::size_t vertex_count) {
  tinygltf::Accessor a;
  a.type = TINYGLTF_TYPE_SCALAR;
  a.count = idx.size();
  if (vertex_count <= 65536) {  // 16-bit indices halve the index data when they fit
    std::vector<std::uint16_t> s(idx.begin(), idx.end());
    a.bufferView = append_buffer_view(m, s.data(), s.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  } else {
    a.bufferView = append_buffer_view(m, idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  }
  m.accessors.push_back(std::move(a));
  return static_cast<int>(m.accessors.size() - 1);
}

std::size_t vertex_count_of(const tinygltf::Model& m, const tinygltf::Primitive& p) {
  const auto it = p.attributes.find("POSITION");
  return it == p.attributes.end() ? 0 : m.accessors.at(static_cast<std::size_t>(it->second)).count;
}

// Adds gazelod_lod to a node's extras, keeping whatever object was there.
void set_lod_extras(tinygltf::Node& node, int node_index, tinygltf::Value v) {
  Object obj;
  if (node.extras.IsObject())
    obj = node.extras.Get<Object>();
  else if (node.extras.Type() != tinygltf::NULL_TYPE)
    throw BakeError("node " + std::to_string(node_index) + " '" + node.name +
                    "': extras is not a JSON object, gazelod_lod cannot be added");
  obj["gazelod_lod"] = std::move(v);
  node.extras = tinygltf::Value(std::move(obj));
}

// Counts as JSON integers (tinygltf's integer Value is an int; larger ones stay exact as double).
tinygltf::Value count_value(std::uint32_t n) {
  return n <= static_cast<std::uint32_t>(INT_MAX) ? tinygltf::Value(static_cast<int>(n))
                                                  : tinygltf::Value(static_cast<double>(n));
}

}  // namespace

tinygltf::Value lod_extras(int level, const MeshLevel& l, double diameter_m) {
  Object o;
  o["level"] = tinygltf::Value(level);
  o["triangles"] = count_value(l.triangles);
  o["vertices"] = count_value(l.vertices);
  o["error_relative"] = tinygltf::Value(l.error_relative);
  o["error_m"] = tinygltf::Value(l.error_m);
  o["diameter_m"] = tinygltf::Value(diameter_m);
  o["detail_cycles_per_diameter"] =
      tinygltf::Value(level == 0 ? 0.0 : detail_cycles_per_diameter(diameter_m, l.error_m));
  if (l.rendered_cycles_per_diameter >= 0.0 && std::isfinite(l.rendered_cycles_per_diameter))
    o["rendered_cycles_per_diameter"] = tinygltf::Value(level == 0 ? 0.0 : l.rendered_cycles_per_diameter);
  return tinygltf::Value(std::move(o));
}

void write_msft_lod(tinygltf::Model& m, const std::vector<MeshChain>& chains) {
  // Coarser meshes first: lod_mesh[mesh][k] is the mesh index of level k (k >= 1).
  std::vector<std::vector<int>> lod_mesh(m.meshes.size());
  const std::size_t mesh_count = m.meshes.size();
  for (std::size_t mi = 0; mi < mesh_count && mi < chains.size(); ++mi) {
    const MeshChain& c = chains[mi];
    for (std::size_t k = 1; k < c.levels.size(); ++k) {
      tinygltf::Mesh lod = m.meshes[mi];  // copy: materials, targets, weights, extras survive
      lod.name = (lod.name.empty() ? "mesh" + std::to_string(mi) : lod.name) + "_lod" + std::to_string(k);
      lod.primitives.clear();
      for (std::size_t p = 0; p < m.meshes[mi].primitives.size(); ++p) {
        const std::vector<std::uint32_t>& idx = c.levels[k].primitive_indices.at(p);
        if (idx.empty()) continue;
        tinygltf::Primitive prim = m.meshes[mi].primitives[p];
        prim.indices = add_index_accessor(m, idx, vertex_count_of(m, prim));
        prim.mode = TINYGLTF_MODE_TRIANGLES;  // strips and fans were read as lists
        lod.primitives.push_back(std::move(prim));
      }
      m.meshes.push_back(std::move(lod));
      lod_mesh[mi].push_back(static_cast<int>(m.meshes.size() - 1));
    }
  }
  const std::size_t node_count = m.nodes.size();
  for (std::size_t ni = 0; ni < node_count; ++ni) {
    const int mesh = m.nodes[ni].mesh;
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= chains.size() ||
        chains[static_cast<std::size_t>(mesh)].levels.empty())
      continue;
    const MeshChain& c = chains[static_cast<std::size_t>(mesh)];
    tinygltf::Value::Array ids;
    for (std::size_t k = 1; k < c.levels.size(); ++k) {
      tinygltf::Node lod = m.nodes[ni];  // same transform, skin, name-derived name
      lod.name = (lod.name.empty() ? "node" + std::to_string(ni) : lod.name) + "_lod" + std::to_string(k);
      lod.mesh = lod_mesh[static_cast<std::size_t>(mesh)][k - 1];
      lod.children.clear();  // children stay under the finest node only
      lod.extensions.erase("MSFT_lod");
      const int index = static_cast<int>(m.nodes.size());
      set_lod_extras(lod, index, lod_extras(static_cast<int>(k), c.levels[k], c.diameter_m));
      m.nodes.push_back(std::move(lod));
      ids.emplace_back(index);
    }
    tinygltf::Node& node = m.nodes[ni];
    set_lod_extras(node, static_cast<int>(ni), lod_extras(0, c.levels[0], c.diameter_m));
    if (!ids.empty()) node.extensions["MSFT_lod"] = tinygltf::Value(Object{{"ids", tinygltf::Value(std::move(ids))}});
  }
  if (std::find(m.extensionsUsed.begin(), m.extensionsUsed.end(), "MSFT_lod") == m.extensionsUsed.end())
    m.extensionsUsed.push_back("MSFT_lod");
}

}  // namespace gazelod::bake
