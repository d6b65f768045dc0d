// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/eval_baseline.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_lod_gltf.hpp"
#include "bake/glb_write.hpp"
#include "bake/gltf_load.hpp"
#include "bake/gltf_pack.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/simplify_chain.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::cli {

lod::ClusterHierarchy chain_hierarchy(std::span<const float> p,
                                      const std::vector<std::vector<std::uint32_t>>& level_indices,
                                      std::span<const double> error_m, std::vector<std::uint32_t>& indices) {
  // One sphere for every level: the centre of the bounds, the radius to the farthest vertex
  // (computed about the float centre and rounded up, so it holds every vertex in float).
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t c = i % 3;
    lo[c] = i < 3 ? p[i] : std::min(lo[c], p[i]);
    hi[c] = i < 3 ? p[i] : std::max(hi[c], p[i]);
  }
  const float centre[3] = {0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2])};
  double radius2 = 0.0;
  for (std::size_t v = 0; v + 2 < p.size(); v += 3) {
    const double dx = p[v] - centre[0], dy = p[v + 1] - centre[1], dz = p[v + 2] - centre[2];
    radius2 = std::max(radius2, dx * dx + dy * dy + dz * dz);
  }
  const float radius = std::nextafter(static_cast<float>(std::sqrt(radius2)), HUGE_VALF);

  lod::ClusterHierarchy h;
  indices.clear();
  for (std::size_t k = 0; k < level_indices.size() && k < error_m.size(); ++k) {
    if (level_indices[k].empty()) continue;
    h.self_center_x_m.push_back(centre[0]);
    h.self_center_y_m.push_back(centre[1]);
    h.self_center_z_m.push_back(centre[2]);
    h.self_radius_m.push_back(radius);
    // A float error rounded up never falls below the level before's.
    h.self_error_m.push_back(k == 0 ? 0.0f : std::nextafter(static_cast<float>(error_m[k]), HUGE_VALF));
    h.first_index.push_back(static_cast<std::uint32_t>(indices.size()));
    h.index_count.push_back(static_cast<std::uint32_t>(level_indices[k].size()));
    h.depth.push_back(static_cast<std::uint8_t>(std::min<std::size_t>(h.depth.size(), 255)));
    indices.insert(indices.end(), level_indices[k].begin(), level_indices[k].end());
  }
  // The parent of each level is the next kept one; the coarsest has none.
  const std::size_t n = h.self_error_m.size();
  for (std::size_t c = 0; c < n; ++c) {
    h.parent_center_x_m.push_back(centre[0]);
    h.parent_center_y_m.push_back(centre[1]);
    h.parent_center_z_m.push_back(centre[2]);
    h.parent_radius_m.push_back(radius);
    h.parent_error_m.push_back(c + 1 < n ? std::max(h.self_error_m[c + 1], h.self_error_m[c]) : lod::kNoParentError);
  }
  return h;
}

std::size_t bake_chain_as_clusters(const std::string& in, const std::string& out) {
  bake::LoadedGltf loaded;
  try {
    loaded = bake::load_gltf(in);  // its errors name the file
  } catch (const bake::BakeError& e) {
    throw UsageError(e.what(), 2);
  }
  std::size_t primitives = 0;
  try {
    tinygltf::Model& m = loaded.model;
    bake::pack_single_buffer(m);
    std::vector<bool> used(m.meshes.size(), false);
    for (const tinygltf::Node& node : m.nodes)
      if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < m.meshes.size())
        used[static_cast<std::size_t>(node.mesh)] = true;
    const bake::ChainOptions chain;  // `gazelod bake`'s defaults: 1/4, 1/16, 1/64 of the triangles
    for (std::size_t mi = 0; mi < m.meshes.size(); ++mi) {
      if (!used[mi]) continue;
      for (std::size_t pi = 0; pi < m.meshes[mi].primitives.size(); ++pi) {
        const auto mesh = static_cast<int>(mi), prim = static_cast<int>(pi);
        const bake::PrimitiveGeometry g = bake::extract_primitive(m, mesh, prim);
        if (g.indices.empty()) continue;
        const bake::PrimitiveChain c = bake::simplify_chain(g.positions_xyz, g.indices, chain);
        std::vector<std::vector<std::uint32_t>> levels;
        std::vector<double> errors;
        for (const bake::SimplifiedLevel& l : c.levels) levels.push_back(l.indices), errors.push_back(l.error_m);
        std::vector<std::uint32_t> indices;
        const lod::ClusterHierarchy h = chain_hierarchy(g.positions_xyz, levels, errors, indices);
        bake::write_cluster_lod(m, mesh, prim, h, indices, g.positions_xyz.size() / 3);
        ++primitives;
      }
    }
  } catch (const bake::BakeError& e) {
    throw UsageError(in + ": " + e.what(), 2);
  }
  try {
    bake::write_glb_atomic(loaded.model, out);
  } catch (const bake::BakeError& e) {
    throw UsageError(e.what(), 1);
  }
  return primitives;
}

}  // namespace gazelod::cli
