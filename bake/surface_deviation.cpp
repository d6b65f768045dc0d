// SPDX-License-Identifier: Apache-2.0
// World-space soups and their one-sided distances (see surface_deviation.hpp).
#include "bake/surface_deviation.hpp"

#include "bake/cluster_distance.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/node_world.hpp"
#include "bake/parallel_for.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gazelod::bake {
namespace {

std::vector<std::uint32_t> used_vertices(const TriangleSoup& soup) {
  std::vector<std::uint8_t> seen(soup.positions_xyz.size() / 3, 0);
  std::vector<std::uint32_t> used;
  for (std::uint32_t v : soup.indices)
    if (!seen[v]) seen[v] = 1, used.push_back(v);
  return used;
}

}  // namespace

void append_placed(TriangleSoup& soup, const std::vector<float>& positions_xyz,
                   const std::vector<std::uint32_t>& indices, const glm::dmat4& world) {
  const auto base = static_cast<std::uint32_t>(soup.positions_xyz.size() / 3);
  for (std::size_t v = 0; v + 2 < positions_xyz.size(); v += 3) {
    const glm::dvec4 p = world * glm::dvec4(positions_xyz[v], positions_xyz[v + 1], positions_xyz[v + 2], 1.0);
    soup.positions_xyz.insert(soup.positions_xyz.end(), {float(p.x), float(p.y), float(p.z)});
  }
  for (std::uint32_t i : indices) soup.indices.push_back(base + i);
}

TriangleSoup world_triangles(const tinygltf::Model& model) {
  TriangleSoup soup;
  for (const MeshInstance& inst : mesh_instances(model)) {
    const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(inst.mesh)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      if (!draws_triangles(mesh.primitives[p])) continue;
      const PrimitiveGeometry g = extract_primitive(model, inst.mesh, static_cast<int>(p));
      append_placed(soup, g.positions_xyz, g.indices, inst.world);
    }
  }
  return soup;
}

SurfaceDeviation surface_deviation(const TriangleSoup& from, const TriangleSoup& to, unsigned threads) {
  SurfaceDeviation d;
  const std::vector<std::uint32_t> used = used_vertices(from);
  d.vertices = used.size();
  if (used.empty()) return d;
  if (to.indices.empty()) {
    d.max_m = d.p99_m = d.mean_m = std::numeric_limits<double>::infinity();
    return d;
  }
  TriangleGrid grid;
  grid.build(to.positions_xyz, to.indices);
  const unsigned n = thread_count(threads);
  std::vector<GridSearch> search(n);
  std::vector<double> dist(used.size());
  constexpr std::size_t kRun = 4096;  // spatial runs of queries per task (the hint helps there)
  parallel_for((used.size() + kRun - 1) / kRun, n, [&](std::size_t run, unsigned t) {
    search[t].restart();
    std::uint32_t hint = ~0u;
    for (std::size_t i = run * kRun; i < std::min(used.size(), (run + 1) * kRun); ++i) {
      const NearestTriangle near = search[t].nearest(grid, &from.positions_xyz[3 * std::size_t{used[i]}], 0.0, hint);
      dist[i] = near.distance_m, hint = near.triangle;
    }
  });
  double sum = 0.0;
  for (double x : dist) sum += x;
  d.mean_m = sum / double(dist.size());
  std::sort(dist.begin(), dist.end());
  d.max_m = dist.back();
  d.p99_m = dist[std::min(dist.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * double(dist.size()))) - 1)];
  return d;
}

double soup_extent_m(const TriangleSoup& soup) {
  const std::vector<std::uint32_t> used = used_vertices(soup);
  if (used.empty()) return 0.0;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = soup.positions_xyz[3 * std::size_t{used[0]} + k];
  for (std::uint32_t v : used)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(soup.positions_xyz[3 * std::size_t{v} + k]));
      hi[k] = std::max(hi[k], double(soup.positions_xyz[3 * std::size_t{v} + k]));
    }
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

}  // namespace gazelod::bake
