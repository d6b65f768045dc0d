// SPDX-License-Identifier: Apache-2.0
// `gazelod run --cluster-select gpu`: the cluster meshes' cut chosen on the GPU by
// shaders/cluster_select.comp (render/cluster_select_pass.hpp) from the viewer the plugin
// selected with this frame (FrameDiagnostics::viewer), culled to each eye's frustum, and drawn
// with one vkCmdDrawIndexedIndirectCount (render::IndirectCut). What an engine does with the
// installed shader, run where users run it.
//
// The plugin's own cut (FrameDecisions::cluster_drawn, with the cluster switch policy off: the
// shader keeps no history) is the check: once per frame the GPU's decisions are read back and
// compared, cluster by cluster, and the differences are reported (ClusterGpuSummary). The run
// keeps counting and auditing the plugin's cut, so a difference is said, never hidden.
#pragma once

#include "apps/gazelod/clusters/audit.hpp"
#include "apps/gazelod/clusters/scene.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/select.hpp"
#include "render/cluster_select_pass.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace gazelod::cli {

class GpuClusterCut {
 public:
  // `scene`'s meshes at their registration poses (the run refuses --cluster-select gpu for
  // meshes that move); first_mesh[k]: the MeshLibrary id of mesh k's cluster 0 (uploaded).
  // Throws render::RenderError (Vulkan) or std::invalid_argument (a hierarchy the pass refuses).
  GpuClusterCut(const render::DeviceContext& ctx, const ClusterScene& scene, const render::MeshLibrary& meshes,
                std::span<const std::uint32_t> first_mesh);
  ~GpuClusterCut();
  GpuClusterCut(const GpuClusterCut&) = delete;
  GpuClusterCut& operator=(const GpuClusterCut&) = delete;

  // One eye's selection, run and waited for, each mesh at its frame-budget detail scale
  // (FrameDecisions::cluster_detail_scale; empty: none): true, or false when the plugin refused
  // this frame's viewer (it then draws every cluster at full detail: draw its cut on the CPU).
  bool select(const lod::Viewer& viewer, const render::EyeView& eye_view, std::span<const float> detail_scale);
  // The last select()'s commands, placed and tinted as given.
  render::IndirectCut cut(const glm::vec3& center_m, float radius_m, std::uint32_t tint) const;
  // After the frame's first select(): its decisions against the plugin's cut (the scene's
  // layout, FrameDecisions::cluster_drawn), counted into the summary.
  void compare(std::span<const std::uint8_t> cpu_drawn);

  const ClusterGpuSummary& summary() const { return summary_; }

 private:
  lod::ClusterStore store_;
  std::unique_ptr<render::ClusterSelectPass> pass_;
  std::vector<std::uint8_t> gpu_drawn_;
  std::vector<double> scale_;  // this frame's detail scales, per mesh
  ClusterGpuSummary summary_;
};

}  // namespace gazelod::cli
