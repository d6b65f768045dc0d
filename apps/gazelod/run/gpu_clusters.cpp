// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/gpu_clusters.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gazelod::cli {

GpuClusterCut::GpuClusterCut(const render::DeviceContext& ctx, const ClusterScene& scene,
                             const render::MeshLibrary& meshes, std::span<const std::uint32_t> first_mesh) {
  std::vector<render::ClusterDrawRange> ranges;
  ranges.reserve(scene.cluster_count());
  store_.reserve(scene.meshes.size(), scene.cluster_count());
  for (std::size_t k = 0; k < scene.meshes.size(); ++k) {
    const ClusterMesh& m = scene.meshes[k];
    const lod::ClusterHierarchy& h = m.primitive->hierarchy;
    try {
      store_.add_mesh(h, m.pose, glm::dvec3(0.0), m.primitive->indices.size());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("GPU cluster selection: " + m.label + ": " + e.what());
    }
    for (std::size_t c = 0; c < h.size(); ++c) {
      const render::MeshRange& r = meshes.range(first_mesh[k] + static_cast<std::uint32_t>(c));
      ranges.push_back({r.first_index, r.index_count, r.vertex_offset});
    }
  }
  pass_ = std::make_unique<render::ClusterSelectPass>(ctx, store_.view(), ranges);
  gpu_drawn_.resize(store_.size());
  summary_.used = true;
  summary_.dispatches_per_select = pass_->dispatch_count();
}

GpuClusterCut::~GpuClusterCut() = default;

bool GpuClusterCut::select(const lod::Viewer& viewer, const render::EyeView& eye_view,
                           std::span<const float> detail_scale) {
  scale_.assign(detail_scale.begin(), detail_scale.end());
  if (!lod::validate_viewer(viewer).empty() || !lod::check_detail_scales(scale_, store_.mesh_count()).empty()) {
    ++summary_.selections_refused;
    return false;
  }
  pass_->run(viewer, &eye_view, scale_);
  ++summary_.selections;
  summary_.commands += pass_->read_draw_count();
  const double ms = pass_->read_dispatch_ms();
  if (ms >= 0.0) {
    summary_.dispatch_ms_sum += ms;
    summary_.dispatch_ms_max = std::max(summary_.dispatch_ms_max, ms);
    ++summary_.dispatches_timed;
  }
  return true;
}

render::IndirectCut GpuClusterCut::cut(const glm::vec3& center_m, float radius_m, std::uint32_t tint) const {
  render::IndirectCut c;
  c.center_m = center_m;
  c.radius_m = radius_m;
  c.lod_level = tint;
  c.commands = pass_->commands_buffer();
  c.count = pass_->count_buffer();
  c.max_draws = pass_->command_capacity();
  return c;
}

void GpuClusterCut::compare(std::span<const std::uint8_t> cpu_drawn) {
  pass_->read_drawn(gpu_drawn_);
  ++summary_.frames_compared;
  const std::size_t n = std::min(cpu_drawn.size(), gpu_drawn_.size());
  // A layout the run already checked (same_cluster_layout): a size mismatch is every cluster.
  summary_.decisions_compared += std::max(cpu_drawn.size(), gpu_drawn_.size());
  summary_.differences += std::max(cpu_drawn.size(), gpu_drawn_.size()) - n;
  for (std::size_t i = 0; i < n; ++i) {
    summary_.differences += (cpu_drawn[i] != 0) != (gpu_drawn_[i] != 0) ? 1 : 0;
  }
}

}  // namespace gazelod::cli
