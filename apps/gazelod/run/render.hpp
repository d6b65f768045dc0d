// SPDX-License-Identifier: Apache-2.0
// `gazelod run`'s drawing: each eye's swapchain image gets every object at the LOD the plugin
// chose, tinted by level (a --scene object with its levels' own triangles; a scenario's
// generated object, which has no geometry, as a stand-in sphere of the level's triangle
// count), and every cluster mesh (--scene with cluster
// hierarchies) as its drawn cut with the clusters' real triangles, one DrawItem per drawn
// cluster in cluster order, tinted by the cluster's depth (render/; the renderer merges runs of
// clusters that follow each other in the index buffer at one depth into one draw). Thin
// adapter from XrApp's Vulkan objects and swapchains and the plugin's decisions to
// render::FrameRenderer.
#pragma once

#include "apps/gazelod/clusters/scene.hpp"
#include "apps/gazelod/run/gpu_clusters.hpp"
#include "apps/xr_host/xr_app.hpp"
#include "plugin/lod_plugin.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

namespace gazelod::cli {

class RunRenderer {
 public:
  // One mesh per (object, level) and one per cluster of each of `clusters`' meshes (its
  // positions posed in LOCAL space; null: none); one renderer per swapchain. baked[i] (when
  // `baked` has an entry i that is not null and holds one BakedLevelMesh per level of chain i)
  // gives object i's levels their own triangles, posed by its world transform in the frame of
  // its bounding sphere (the scenario object's position and radius); otherwise a stand-in
  // sphere of the level's triangle count. Throws render::RenderError (unsupported swapchain
  // format, Vulkan failure, a level mesh the renderer refuses).
  // gpu_select (with `clusters`): the cluster meshes' cut is selected on the GPU and drawn
  // with one indirect-count draw per eye (run/gpu_clusters.hpp), every mesh at its registration
  // pose in one shared frame, each cluster tinted by its depth per instance; throws
  // RenderError where the device has no drawIndirectCount.
  RunRenderer(xr_host::XrApp& app, const std::vector<std::vector<lod::LodLevel>>& chains,
              const ClusterScene* clusters = nullptr, std::span<const bake::BakedObject* const> baked = {},
              bool gpu_select = false);
  ~RunRenderer();
  RunRenderer(const RunRenderer&) = delete;
  RunRenderer& operator=(const RunRenderer&) = delete;

  // Draws into swapchains()[eye].images[image_index] (acquired and waited on by the caller)
  // and waits for the GPU, so the image can be released right after. positions_m/radii_m are
  // bounding spheres in LOCAL space; decisions.lod[i] is object i's level (clamped to its chain);
  // decisions.cluster_drawn the cluster meshes' cuts (in the ClusterScene's layout), each mesh
  // moved by cluster_shift_m[k] (LOCAL; missing entries: not moved).
  void render_eye(std::size_t eye, std::uint32_t image_index, const XrView& view,
                  std::span<const glm::dvec3> positions_m, std::span<const double> radii_m,
                  const FrameDecisions& decisions, const FrameDiagnostics& diagnostics,
                  std::span<const glm::dvec3> cluster_shift_m = {});

  // The image last drawn by render_eye as a PNG; call before releasing it. Throws
  // render::RenderError naming the file.
  // With a colour key under the frame for levels 0 .. levels - 1 (render/lod_key.hpp).
  void save_png(std::size_t eye, std::uint32_t image_index, const std::filesystem::path& file, std::uint32_t levels);

  // The debug view's foveal circle (render/foveal_marker.hpp) around the gaze, in white;
  // on by default.
  void set_foveal_circle(bool on) { foveal_circle_ = on; }

  // Scene triangles submitted for the last render_eye of `eye` (a GPU-selected cut's not
  // counted: the host does not see it).
  std::uint64_t triangles_drawn(std::size_t eye) const;
  // The GPU selection's figures (used = false without gpu_select).
  ClusterGpuSummary gpu_summary() const { return gpu_ ? gpu_->summary() : ClusterGpuSummary{}; }

 private:
  render::FrameRenderer& renderer(std::size_t eye) const;

  render::MeshLibrary meshes_;
  std::vector<std::vector<std::uint32_t>> mesh_ids_;  // [object][level] -> MeshLibrary id
  struct ClusterDraw {                                // one cluster mesh
    glm::vec3 center_m{0.0f};                         // its positions' frame in LOCAL space
    float radius_m = 1.0f;
    std::uint32_t first_mesh = 0;     // MeshLibrary id of its cluster 0
    std::uint32_t first_cluster = 0;  // into FrameDecisions::cluster_drawn
    std::vector<std::uint8_t> depth;  // per cluster: the tint
  };
  std::vector<ClusterDraw> clusters_;
  std::vector<std::unique_ptr<render::FrameRenderer>> eyes_;
  std::vector<render::DrawItem> items_;  // reused each frame: no allocation
  std::unique_ptr<GpuClusterCut> gpu_;   // --cluster-select gpu
  glm::vec3 gpu_center_m_{0.0f};         // the cluster meshes' shared frame there
  float gpu_radius_m_ = 1.0f;
  std::uint32_t marker_mesh_ = 0;
  bool foveal_circle_ = true;
};

}  // namespace gazelod::cli
