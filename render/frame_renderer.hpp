// Draws one eye's frame into one of a set of target images (an OpenXR swapchain's VkImages,
// or an OffscreenTarget): each object as its LOD level's mesh, tinted by level, with depth.
// Each call records, submits and waits, so a swapchain image can be released right after.
#pragma once

#include "render/camera.hpp"
#include "render/device_context.hpp"
#include "render/gpu_memory.hpp"
#include "render/mesh_library.hpp"
#include "render/pipeline.hpp"
#include "render/rgba_image.hpp"

#include <glm/vec3.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>
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

class FrameRenderer {
 public:
  // `meshes` must be uploaded and outlive the renderer. Throws RenderError.
  FrameRenderer(const DeviceContext& ctx, const MeshLibrary& meshes, RenderTarget target);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Clears and draws `items` (skipping those with a non-finite centre, a radius <= 0, or
  // entirely outside the view)
  // into images[image_index], leaving it in COLOR_ATTACHMENT_OPTIMAL. Throws RenderError for a
  // bad index or mesh id.
  void draw(std::uint32_t image_index, const EyeView& view, std::span<const DrawItem> items);

  // Copies a drawn image to RGBA8 (swizzling BGRA); it stays in COLOR_ATTACHMENT_OPTIMAL.
  RgbaImage read_back(std::uint32_t image_index);

  // Scene triangles submitted in the last draw (markers and culled objects not counted).
  std::uint64_t triangles_last_frame() const { return triangles_last_frame_; }
  const RenderTarget& target() const { return target_; }

 private:
  void submit_and_wait();
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
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  HostBuffer readback_;
  std::uint64_t triangles_last_frame_ = 0;
};

}  // namespace gazelod::render
