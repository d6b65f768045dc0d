// SPDX-License-Identifier: Apache-2.0
// Draws one eye's frame into one of a set of target images (an OpenXR swapchain's VkImages,
// or an OffscreenTarget): each object as its LOD level's mesh, tinted by level, with depth.
// Each call records, submits and waits, so a swapchain image can be released right after.
#pragma once

#include "render/camera.hpp"
#include "render/device_buffer.hpp"
#include "render/device_context.hpp"
#include "render/gpu_memory.hpp"
#include "render/mesh_library.hpp"
#include "render/pipeline.hpp"
#include "render/rgba_image.hpp"

#include <glm/vec3.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace gazelod::render {

// Images in layout UNDEFINED or COLOR_ATTACHMENT_OPTIMAL, usage COLOR_ATTACHMENT (plus
// TRANSFER_SRC for read_back). Formats: R8G8B8A8 or B8G8R8A8, UNORM or SRGB.
struct RenderTarget {
  std::vector<VkImage> images;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

struct DrawItem {
  glm::vec3 center_m{0.0f};
  float radius_m = 0.0f;
  std::uint32_t mesh = 0;       // MeshLibrary id
  std::uint32_t lod_level = 0;  // picks the tint (lod_palette.hpp); kMarkerLevel for markers
};

// A cut whose draws the GPU wrote (ClusterSelectPass, render/cluster_select_pass.hpp):
// VkDrawIndexedIndirectCommands into one buffer, their number into another. Drawn under one set
// of constants: one placement of the cluster mesh's unit frame and one tint for every cluster.
struct IndirectCut {
  glm::vec3 center_m{0.0f};
  float radius_m = 0.0f;
  std::uint32_t lod_level = 0;  // the tint
  VkBuffer commands = VK_NULL_HANDLE;
  VkDeviceSize commands_offset = 0;
  VkBuffer count = VK_NULL_HANDLE;  // a uint32_t
  VkDeviceSize count_offset = 0;
  std::uint32_t max_draws = 0;  // commands the buffer holds (ClusterSelectPass::command_capacity)
  // Each command tinted by the level set_instance_tints gave its firstInstance (the cluster's
  // id, as ClusterSelectPass writes it) instead of lod_level.
  bool per_instance_tint = false;
};

class FrameRenderer {
 public:
  // `meshes` must be uploaded and outlive the renderer. Throws RenderError.
  FrameRenderer(const DeviceContext& ctx, const MeshLibrary& meshes, RenderTarget target);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Clears and draws `items` (skipping those with a non-finite centre, a radius <= 0, or whose
  // mesh range's sphere, MeshRange::bound_center_unit placed by the item, is outside the view)
  // into images[image_index], leaving it in COLOR_ATTACHMENT_OPTIMAL; then each of `cuts`, a
  // GPU-built cut, with one vkCmdDrawIndexedIndirectCount (after a barrier from compute shader
  // writes to indirect reads; needs DeviceContext::draw_indirect_count). The GPU chose the cuts'
  // draws: triangles_last_frame() and draws_last_frame() count the items only, and each cut is
  // one of draw_commands_last_frame(). Throws RenderError for a bad index, mesh id or cut.
  void draw(std::uint32_t image_index, const EyeView& view, std::span<const DrawItem> items,
            std::span<const IndirectCut> cuts = {});

  // The tints of per_instance_tint cuts: instance i drawn in level levels[i]'s colour (what
  // DrawItem::lod_level gives), for firstInstance values below levels.size(). Throws RenderError.
  void set_instance_tints(std::span<const std::uint8_t> levels);

  // draw() with one GPU-built cut and no items.
  void draw_indirect_count(std::uint32_t image_index, const EyeView& view, const IndirectCut& cut);

  // Copies a drawn image to RGBA8 (swizzling BGRA); it stays in COLOR_ATTACHMENT_OPTIMAL.
  RgbaImage read_back(std::uint32_t image_index);

  // On (the default), consecutive drawn items with the same centre, radius and tint whose index
  // ranges follow each other in the mesh library (the clusters of a cut, cluster by cluster)
  // become one indexed draw: the same triangles in the same order, so the same image. Off: one
  // draw per item, the reference the tests and benchmarks compare against.
  void set_merge_draws(bool on) { merge_draws_ = on; }
  // On (the default), with merging on and a device with multiDrawIndirect
  // (DeviceContext::multi_draw_indirect): the merged draws under one set of constants go out as
  // one vkCmdDrawIndexedIndirect, in item order, so the image is unchanged. Off, or without the
  // feature: a loop of vkCmdDrawIndexed.
  void set_multi_draw(bool on) { multi_draw_ = on; }
  // On (the default), an item is culled by its mesh range's own sphere (a cluster's); off, by
  // the item's sphere alone, as a whole mesh is: the reference the tests and benchmarks compare
  // against (the same image, more triangles submitted).
  void set_cull_ranges(bool on) { cull_ranges_ = on; }
  bool multi_draw_active() const { return merge_draws_ && multi_draw_ && ctx_.multi_draw_indirect; }
  // Indexed draws (merged ranges) and draw commands (an indirect command counts once) recorded
  // by the last draw, markers included.
  std::uint32_t draws_last_frame() const { return draws_last_frame_; }
  std::uint32_t draw_commands_last_frame() const { return draw_commands_last_frame_; }

  // Scene triangles submitted in the last draw (markers and culled objects not counted).
  std::uint64_t triangles_last_frame() const { return triangles_last_frame_; }
  const RenderTarget& target() const { return target_; }

 private:
  // The frame's command buffer up to the bound pipeline and buffers inside the cleared render
  // pass (first a compute-to-indirect barrier when asked), and the constants every draw shares;
  // then its end, submitted and waited for.
  DrawConstants begin_frame(std::uint32_t image_index, const EyeView& view, bool after_compute);
  void end_frame(std::uint32_t image_index);
  void destroy();

  DeviceContext ctx_;
  const MeshLibrary& meshes_;
  RenderTarget target_;
  bool srgb_ = false;
  bool bgra_ = false;
  Pipeline pipeline_;
  DeviceImage depth_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<bool> drawn_;
  std::unique_ptr<OneShotCommands> commands_;  // each frame and read-back: record, submit, wait
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;       // the one being recorded
  HostBuffer readback_;
  std::uint64_t triangles_last_frame_ = 0;
  std::uint32_t draws_last_frame_ = 0, draw_commands_last_frame_ = 0;
  bool merge_draws_ = true, multi_draw_ = true, cull_ranges_ = true;
  HostBuffer indirect_;        // VkDrawIndexedIndirectCommand per merged draw, grown to the item count
  HostBuffer instance_tints_;  // vec3 per instance (set_instance_tints), in the target's colour space
  std::uint32_t max_draw_indirect_count_ = 1;
};

}  // namespace gazelod::render
