#include "plugin/render/mesh_library.hpp"

#include "plugin/render/render_error.hpp"

#include <cstring>

namespace gazelod::render {

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
