// SPDX-License-Identifier: Apache-2.0
// All meshes a renderer can draw, in one vertex and one index buffer: a stand-in sphere per
// distinct LOD triangle count (see sphere_mesh.hpp), an arbitrary triangle mesh (add_mesh,
// e.g. baked LOD levels for the perceptual profile) or a cluster hierarchy's clusters
// (add_cluster_mesh), shared by both eyes. Built once on the CPU, then uploaded; drawing needs
// only a mesh id.
#pragma once

#include "render/device_context.hpp"
#include "render/gpu_memory.hpp"
#include "render/sphere_mesh.hpp"

#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

namespace gazelod::render {

struct MeshRange {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  std::int32_t vertex_offset = 0;
  // A sphere holding the range's triangles, in the unit frame of its positions: the unit
  // sphere for a whole mesh, each cluster's own (smaller) sphere for a cluster mesh, so that a
  // cut's clusters outside an eye's view are not submitted (FrameRenderer::draw).
  glm::vec3 bound_center_unit{0.0f};
  float bound_radius_unit = 1.0f;
  std::uint32_t triangles() const { return index_count / 3; }
};

class MeshLibrary {
 public:
  // A sphere with about `target_triangles` triangles; equal resolutions share one mesh.
  // Throws RenderError after upload().
  std::uint32_t add_sphere(std::uint32_t target_triangles);

  // Any triangle list (counter-clockwise seen from outside). Positions are in the object's
  // unit bounding-sphere frame: (p - centre) / radius, so a DrawItem's centre and radius place
  // it. The renderer has no normal attribute: the shaders use the position as the normal, so
  // shading is radial (a headlight on the bounding sphere's direction); silhouettes and depth
  // are exact. Throws RenderError after upload(), for an index count not a multiple of 3, an
  // index out of range, or a non-finite position. Every call adds a new mesh (no sharing).
  std::uint32_t add_mesh(std::span<const glm::vec3> positions_unit, std::span<const std::uint32_t> indices);

  // A cluster hierarchy's clusters (gazelod bake --clusters): one vertex block and one index
  // buffer holding every cluster of every level, cluster c being the triangle list
  // indices[first_index[c] .. + index_count[c]). Returns the mesh id of cluster 0; cluster c is
  // mesh (returned + c), so a cut is drawn with one DrawItem per drawn cluster, all with the
  // same centre and radius (the frame of positions_unit, as for add_mesh); cluster c + 1's range
  // starts where cluster c's ends when the input's do, so FrameRenderer merges their draws.
  // Each cluster's range gets the sphere around its box (MeshRange::bound_center_unit).
  // Throws RenderError after upload(), for no clusters, spans of different lengths, a range
  // outside `indices` or not of whole triangles, an index out of range or a non-finite position.
  std::uint32_t add_cluster_mesh(std::span<const glm::vec3> positions_unit, std::span<const std::uint32_t> indices,
                                 std::span<const std::uint32_t> first_index,
                                 std::span<const std::uint32_t> index_count);

  // Copies every mesh into host-visible Vulkan buffers. Call once, after the last add.
  void upload(const DeviceContext& ctx);
  bool uploaded() const { return vertices_.buffer() != VK_NULL_HANDLE; }

  std::size_t size() const { return ranges_.size(); }
  const MeshRange& range(std::uint32_t mesh) const { return ranges_.at(mesh); }
  VkBuffer vertex_buffer() const { return vertices_.buffer(); }
  VkBuffer index_buffer() const { return indices_.buffer(); }

 private:
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> by_resolution_;
  std::vector<MeshRange> ranges_;
  std::vector<glm::vec3> positions_;
  std::vector<std::uint32_t> indices_cpu_;
  HostBuffer vertices_, indices_;

  // Checks and appends one vertex block and its indices; returns the block's vertex offset
  // and first index. `what` names the caller in errors.
  std::pair<std::int32_t, std::uint32_t> append_block(const char* what, std::span<const glm::vec3> positions_unit,
                                                      std::span<const std::uint32_t> indices);
};

}  // namespace gazelod::render
