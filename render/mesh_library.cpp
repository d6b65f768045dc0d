// SPDX-License-Identifier: Apache-2.0
#include "render/mesh_library.hpp"

#include "render/render_error.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace gazelod::render {
namespace {

// The sphere around the box of a cluster's corners, in double and then rounded outwards to
// float, so that no corner the shader places lies outside it; a cluster with no triangles
// keeps the unit sphere.
void cluster_bound(std::span<const glm::vec3> positions_unit, std::span<const std::uint32_t> indices,
                   MeshRange& range) {
  if (indices.empty()) return;
  glm::dvec3 lo(positions_unit[indices[0]]), hi = lo;
  for (std::uint32_t i : indices) {
    lo = glm::min(lo, glm::dvec3(positions_unit[i]));
    hi = glm::max(hi, glm::dvec3(positions_unit[i]));
  }
  const glm::vec3 center(0.5 * (lo + hi));
  double radius_squared = 0.0;
  for (std::uint32_t i : indices) {
    const glm::dvec3 d = glm::dvec3(positions_unit[i]) - glm::dvec3(center);
    radius_squared = std::max(radius_squared, glm::dot(d, d));
  }
  range.bound_center_unit = center;
  // A relative margin over float rounding of the centre and of the shader's placement.
  range.bound_radius_unit = static_cast<float>(std::sqrt(radius_squared) * (1.0 + 1e-5) + 1e-6);
}

}  // namespace

std::uint32_t MeshLibrary::add_sphere(std::uint32_t target_triangles) {
  if (uploaded()) throw RenderError("MeshLibrary::add_sphere after upload()");
  const SphereResolution res = sphere_resolution(target_triangles);
  const auto key = std::make_pair(res.stacks, res.slices);
  if (auto it = by_resolution_.find(key); it != by_resolution_.end()) return it->second;

  const MeshData mesh = make_sphere(res);
  MeshRange range;
  range.first_index = static_cast<std::uint32_t>(indices_cpu_.size());
  range.index_count = static_cast<std::uint32_t>(mesh.indices.size());
  range.vertex_offset = static_cast<std::int32_t>(positions_.size());
  positions_.insert(positions_.end(), mesh.positions.begin(), mesh.positions.end());
  indices_cpu_.insert(indices_cpu_.end(), mesh.indices.begin(), mesh.indices.end());
  const auto id = static_cast<std::uint32_t>(ranges_.size());
  ranges_.push_back(range);
  by_resolution_.emplace(key, id);
  return id;
}

std::pair<std::int32_t, std::uint32_t> MeshLibrary::append_block(const char* what,
                                                                 std::span<const glm::vec3> positions_unit,
                                                                 std::span<const std::uint32_t> indices) {
  const std::string name = std::string("MeshLibrary::") + what;
  if (uploaded()) throw RenderError(name + " after upload()");
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= positions_unit.size())
      throw RenderError(name + ": index " + std::to_string(i) + " = " + std::to_string(indices[i]) +
                        " is out of range (" + std::to_string(positions_unit.size()) + " vertices)");
  for (std::size_t v = 0; v < positions_unit.size(); ++v)
    if (!std::isfinite(positions_unit[v].x) || !std::isfinite(positions_unit[v].y) ||
        !std::isfinite(positions_unit[v].z))
      throw RenderError(name + ": position " + std::to_string(v) + " is not finite");
  if (positions_.size() + positions_unit.size() > static_cast<std::size_t>(INT32_MAX))
    throw RenderError(name + ": too many vertices for one library");
  if (indices_cpu_.size() + indices.size() > static_cast<std::size_t>(UINT32_MAX))
    throw RenderError(name + ": too many indices for one library");
  const auto block =
      std::make_pair(static_cast<std::int32_t>(positions_.size()), static_cast<std::uint32_t>(indices_cpu_.size()));
  positions_.insert(positions_.end(), positions_unit.begin(), positions_unit.end());
  indices_cpu_.insert(indices_cpu_.end(), indices.begin(), indices.end());
  return block;
}

std::uint32_t MeshLibrary::add_mesh(std::span<const glm::vec3> positions_unit, std::span<const std::uint32_t> indices) {
  if (uploaded()) throw RenderError("MeshLibrary::add_mesh after upload()");
  if (indices.size() % 3 != 0)
    throw RenderError("MeshLibrary::add_mesh: index count " + std::to_string(indices.size()) +
                      " is not a multiple of 3");
  const auto [vertex_offset, first_index] = append_block("add_mesh", positions_unit, indices);
  MeshRange range;
  range.first_index = first_index;
  range.index_count = static_cast<std::uint32_t>(indices.size());
  range.vertex_offset = vertex_offset;
  ranges_.push_back(range);
  return static_cast<std::uint32_t>(ranges_.size() - 1);
}

std::uint32_t MeshLibrary::add_cluster_mesh(std::span<const glm::vec3> positions_unit,
                                            std::span<const std::uint32_t> indices,
                                            std::span<const std::uint32_t> first_index,
                                            std::span<const std::uint32_t> index_count) {
  const std::string name = "MeshLibrary::add_cluster_mesh";
  if (uploaded()) throw RenderError(name + " after upload()");
  if (first_index.empty()) throw RenderError(name + ": no clusters");
  if (first_index.size() != index_count.size())
    throw RenderError(name + ": " + std::to_string(first_index.size()) + " first indices but " +
                      std::to_string(index_count.size()) + " index counts");
  for (std::size_t c = 0; c < first_index.size(); ++c) {
    // In 64 bits: first + count cannot wrap.
    const std::uint64_t end = std::uint64_t{first_index[c]} + index_count[c];
    if (index_count[c] % 3 != 0)
      throw RenderError(name + ": cluster " + std::to_string(c) + " has " + std::to_string(index_count[c]) +
                        " indices, not a multiple of 3");
    if (end > indices.size())
      throw RenderError(name + ": cluster " + std::to_string(c) + " ends at index " + std::to_string(end) +
                        ", past the " + std::to_string(indices.size()) + " indices");
  }
  const auto [vertex_offset, base] = append_block("add_cluster_mesh", positions_unit, indices);
  const auto first_id = static_cast<std::uint32_t>(ranges_.size());
  for (std::size_t c = 0; c < first_index.size(); ++c) {
    MeshRange range;
    range.first_index = base + first_index[c];
    range.index_count = index_count[c];
    range.vertex_offset = vertex_offset;
    cluster_bound(positions_unit, indices.subspan(first_index[c], index_count[c]), range);
    ranges_.push_back(range);
  }
  return first_id;
}

void MeshLibrary::upload(const DeviceContext& ctx) {
  if (uploaded()) throw RenderError("MeshLibrary::upload called twice");
  const VkDeviceSize vbytes = positions_.size() * sizeof(glm::vec3);
  const VkDeviceSize ibytes = indices_cpu_.size() * sizeof(std::uint32_t);
  vertices_ = HostBuffer(ctx, vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  indices_ = HostBuffer(ctx, ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (vbytes) std::memcpy(vertices_.data(), positions_.data(), vbytes);
  if (ibytes) std::memcpy(indices_.data(), indices_cpu_.data(), ibytes);
  // The GPU copy is all that is needed from now on.
  positions_ = {};
  indices_cpu_ = {};
}

}  // namespace gazelod::render
