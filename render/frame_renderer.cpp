// SPDX-License-Identifier: Apache-2.0
#include "render/frame_renderer.hpp"

#include "render/lod_palette.hpp"
#include "render/render_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

namespace gazelod::render {
namespace {

glm::vec3 to_target(const glm::vec3& srgb, bool target_is_srgb) {
  // An sRGB image encodes on write, so it is given linear values; a UNORM image stores
  // what it is given.
  if (!target_is_srgb) return srgb;
  return {srgb_to_linear(srgb.r), srgb_to_linear(srgb.g), srgb_to_linear(srgb.b)};
}

VkImageMemoryBarrier colour_barrier(VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags src,
                                    VkAccessFlags dst) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  return b;
}

}  // namespace

FrameRenderer::FrameRenderer(const DeviceContext& ctx, const MeshLibrary& meshes, RenderTarget target)
    : ctx_(ctx), meshes_(meshes), target_(std::move(target)) {
  switch (target_.format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
      break;
    case VK_FORMAT_R8G8B8A8_SRGB:
      srgb_ = true;
      break;
    case VK_FORMAT_B8G8R8A8_UNORM:
      bgra_ = true;
      break;
    case VK_FORMAT_B8G8R8A8_SRGB:
      srgb_ = bgra_ = true;
      break;
    default:
      throw RenderError("renderer: unsupported target format " + std::to_string(target_.format) +
                        " (need R8G8B8A8 or B8G8R8A8, UNORM or SRGB)");
  }
  if (target_.images.empty() || target_.width == 0 || target_.height == 0)
    throw RenderError("renderer: empty target (" + std::to_string(target_.images.size()) + " images, " +
                      std::to_string(target_.width) + "x" + std::to_string(target_.height) + ")");
  if (!meshes_.uploaded()) throw RenderError("renderer: the mesh library is not uploaded");
  try {
    const VkFormat depth_format = pick_depth_format(ctx_.physical);
    pipeline_ = create_pipeline(ctx_.device, target_.format, depth_format, target_.width, target_.height);
    depth_ = DeviceImage(ctx_, target_.width, target_.height, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                         VK_IMAGE_ASPECT_DEPTH_BIT);
    for (VkImage image : target_.images) {
      views_.push_back(create_image_view(ctx_.device, image, target_.format, VK_IMAGE_ASPECT_COLOR_BIT));
      const std::array<VkImageView, 2> attachments{views_.back(), depth_.view()};
      VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
      fci.renderPass = pipeline_.render_pass;
      fci.attachmentCount = static_cast<std::uint32_t>(attachments.size());
      fci.pAttachments = attachments.data();
      fci.width = target_.width;
      fci.height = target_.height;
      fci.layers = 1;
      VkFramebuffer fb = VK_NULL_HANDLE;
      vk_check(vkCreateFramebuffer(ctx_.device, &fci, nullptr, &fb), "vkCreateFramebuffer");
      framebuffers_.push_back(fb);
    }
    drawn_.assign(target_.images.size(), false);
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(ctx_.physical, &props);
    max_draw_indirect_count_ = std::max<std::uint32_t>(props.limits.maxDrawIndirectCount, 1);
    commands_ = std::make_unique<OneShotCommands>(ctx_);
  } catch (...) {
    destroy();
    throw;
  }
}

FrameRenderer::~FrameRenderer() {
  destroy();
}

void FrameRenderer::destroy() {
  commands_.reset();
  for (VkFramebuffer fb : framebuffers_) vkDestroyFramebuffer(ctx_.device, fb, nullptr);
  for (VkImageView v : views_) vkDestroyImageView(ctx_.device, v, nullptr);
  destroy_pipeline(ctx_.device, pipeline_);
  cmd_ = VK_NULL_HANDLE;
  framebuffers_.clear();
  views_.clear();
}

DrawConstants FrameRenderer::begin_frame(std::uint32_t image_index, const EyeView& view, bool after_compute) {
  if (image_index >= framebuffers_.size())
    throw RenderError("renderer: image index " + std::to_string(image_index) + " out of range (" +
                      std::to_string(framebuffers_.size()) + " images)");
  DrawConstants dc{};
  dc.view_proj = glm::mat4(projection_matrix(view.fov, view.near_m, view.far_m) * view_matrix(view.pose));
  dc.eye_position = glm::vec4(glm::vec3(view.pose.position_m), 1.0f);

  cmd_ = commands_->begin();
  if (after_compute) {  // commands a compute pass wrote (earlier in this queue) are read here
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
  }

  const glm::vec3 bg = to_target(background_colour(), srgb_);
  std::array<VkClearValue, 2> clear{};
  clear[0].color = {{bg.r, bg.g, bg.b, 1.0f}};
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rbi.renderPass = pipeline_.render_pass;
  rbi.framebuffer = framebuffers_[image_index];
  rbi.renderArea = {{0, 0}, {target_.width, target_.height}};
  rbi.clearValueCount = static_cast<std::uint32_t>(clear.size());
  rbi.pClearValues = clear.data();
  vkCmdBeginRenderPass(cmd_, &rbi, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline);
  const VkBuffer vb = meshes_.vertex_buffer();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd_, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd_, meshes_.index_buffer(), 0, VK_INDEX_TYPE_UINT32);
  return dc;
}

void FrameRenderer::end_frame(std::uint32_t image_index) {
  vkCmdEndRenderPass(cmd_);
  commands_->submit_and_wait();
  drawn_[image_index] = true;
}

void FrameRenderer::set_instance_tints(std::span<const std::uint8_t> levels) {
  if (levels.empty()) throw RenderError("renderer: set_instance_tints without any instance");
  // The colours the push constants would carry for these levels, bit for bit: the same pixels.
  instance_tints_ = HostBuffer(ctx_, levels.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  auto* out = static_cast<glm::vec3*>(instance_tints_.data());
  for (std::size_t i = 0; i < levels.size(); ++i) out[i] = to_target(lod_colour(levels[i]), srgb_);
}

void FrameRenderer::draw_indirect_count(std::uint32_t image_index, const EyeView& view, const IndirectCut& cut) {
  draw(image_index, view, {}, std::span<const IndirectCut>(&cut, 1));
}

void FrameRenderer::draw(std::uint32_t image_index, const EyeView& view, std::span<const DrawItem> items,
                         std::span<const IndirectCut> cuts) {
  for (const DrawItem& item : items)
    if (item.mesh >= meshes_.size())
      throw RenderError("renderer: mesh id " + std::to_string(item.mesh) + " out of range (" +
                        std::to_string(meshes_.size()) + " meshes)");
  if (!cuts.empty() && !ctx_.draw_indirect_count)
    throw RenderError("renderer: a GPU-built cut needs Vulkan 1.2's drawIndirectCount, not enabled on this device");
  for (const IndirectCut& cut : cuts) {
    if (cut.commands == VK_NULL_HANDLE || cut.count == VK_NULL_HANDLE)
      throw RenderError("renderer: a GPU-built cut without a command or count buffer");
    if (cut.per_instance_tint && instance_tints_.buffer() == VK_NULL_HANDLE)
      throw RenderError("renderer: a GPU-built cut tinted per instance before set_instance_tints");
  }
  DrawConstants dc = begin_frame(image_index, view, !cuts.empty());
  const ViewCuller culler(view);
  std::uint64_t triangles = 0;
  std::uint32_t draws = 0;
  bool pushed = false;
  // The draw being extended: a cluster cut is thousands of items whose ranges follow each other
  // in the index buffer under one set of constants, and lavapipe pays per draw command.
  std::uint64_t run_first = 0, run_count = 0;
  std::int32_t run_vertex_offset = 0;
  const bool indirect = multi_draw_active();
  if (indirect && indirect_.size() < items.size() * sizeof(VkDrawIndexedIndirectCommand)) {
    // The last frame's commands are done (each draw waits), so the old buffer can go.
    constexpr std::size_t kCommand = sizeof(VkDrawIndexedIndirectCommand);
    const std::size_t capacity = std::max<std::size_t>(items.size(), 2 * indirect_.size() / kCommand);
    indirect_ = HostBuffer(ctx_, capacity * kCommand, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  }
  auto* commands = indirect ? static_cast<VkDrawIndexedIndirectCommand*>(indirect_.data()) : nullptr;
  std::uint32_t draw_commands = 0, batch_first = 0;  // batch: the written commands not yet issued
  const auto flush = [&] {
    if (run_count == 0) return;
    const auto count = static_cast<std::uint32_t>(run_count), first = static_cast<std::uint32_t>(run_first);
    if (indirect) {
      commands[draws] = {count, 1, first, run_vertex_offset, 0};
    } else {
      vkCmdDrawIndexed(cmd_, count, 1, first, run_vertex_offset, 0);
      ++draw_commands;
    }
    ++draws;
    run_count = 0;
  };
  // Before constants change: the batch drawn under the current ones goes out.
  const auto flush_batch = [&] {
    flush();
    if (!indirect) return;
    while (batch_first < draws) {
      const std::uint32_t n = std::min(draws - batch_first, max_draw_indirect_count_);
      constexpr std::uint32_t kStride = sizeof(VkDrawIndexedIndirectCommand);
      vkCmdDrawIndexedIndirect(cmd_, indirect_.buffer(), VkDeviceSize{batch_first} * kStride, n, kStride);
      ++draw_commands;
      batch_first += n;
    }
  };
  for (const DrawItem& item : items) {
    const bool finite = std::isfinite(item.center_m.x) && std::isfinite(item.center_m.y) &&
                        std::isfinite(item.center_m.z) && std::isfinite(item.radius_m);
    if (!finite || !(item.radius_m > 0.0f)) continue;
    const MeshRange& mesh = meshes_.range(item.mesh);
    // The range's own sphere placed like its positions: a cluster outside the view is skipped.
    const double radius_m = item.radius_m;
    const glm::dvec3 bound_center_unit = cull_ranges_ ? glm::dvec3(mesh.bound_center_unit) : glm::dvec3(0.0);
    const double bound_radius_unit = cull_ranges_ ? mesh.bound_radius_unit : 1.0;
    if (!culler.visible(glm::dvec3(item.center_m) + radius_m * bound_center_unit, radius_m * bound_radius_unit))
      continue;
    if (item.lod_level != kMarkerLevel) triangles += mesh.triangles();
    const glm::vec4 center_radius(item.center_m, item.radius_m);
    const glm::vec4 colour(to_target(lod_colour(item.lod_level), srgb_), 1.0f);
    // Bit for bit (memcmp, not ==): -0 and +0 would otherwise merge under different constants.
    const bool same_constants = pushed && std::memcmp(&center_radius, &dc.center_radius, sizeof center_radius) == 0 &&
                                std::memcmp(&colour, &dc.colour, sizeof colour) == 0;
    if (merge_draws_ && same_constants && run_count > 0 && mesh.vertex_offset == run_vertex_offset &&
        mesh.first_index == run_first + run_count && run_count + mesh.index_count <= UINT32_MAX) {
      run_count += mesh.index_count;  // the same triangles in the same order: the same pixels
      continue;
    }
    if (!merge_draws_ || !same_constants) {
      flush_batch();
      dc.center_radius = center_radius;
      dc.colour = colour;
      vkCmdPushConstants(cmd_, pipeline_.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                         sizeof dc, &dc);
      pushed = true;
    } else {
      flush();
    }
    run_first = mesh.first_index;
    run_count = mesh.index_count;
    run_vertex_offset = mesh.vertex_offset;
    if (!merge_draws_) flush();
  }
  flush_batch();
  // The GPU-built cuts last, each under its own constants: the compute pass chose their draws,
  // so their triangles are not known here.
  for (const IndirectCut& cut : cuts) {
    if (cut.per_instance_tint) {
      vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.tinted);
      const VkBuffer tints = instance_tints_.buffer();
      const VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(cmd_, 1, 1, &tints, &offset);
    } else {
      vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline);
    }
    dc.center_radius = glm::vec4(cut.center_m, cut.radius_m);
    dc.colour = glm::vec4(to_target(lod_colour(cut.lod_level), srgb_), 1.0f);
    vkCmdPushConstants(cmd_, pipeline_.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof dc,
                       &dc);
    vkCmdDrawIndexedIndirectCount(cmd_, cut.commands, cut.commands_offset, cut.count, cut.count_offset, cut.max_draws,
                                  sizeof(VkDrawIndexedIndirectCommand));
    ++draw_commands;
  }
  end_frame(image_index);
  triangles_last_frame_ = triangles;
  draws_last_frame_ = draws;
  draw_commands_last_frame_ = draw_commands;
}

RgbaImage FrameRenderer::read_back(std::uint32_t image_index) {
  if (image_index >= framebuffers_.size() || !drawn_[image_index])
    throw RenderError("renderer: read_back of image " + std::to_string(image_index) + " that was not drawn");
  const VkDeviceSize bytes = static_cast<VkDeviceSize>(target_.width) * target_.height * 4u;
  if (readback_.buffer() == VK_NULL_HANDLE) readback_ = HostBuffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  VkImage image = target_.images[image_index];

  cmd_ = commands_->begin();
  const auto to_src =
      colour_barrier(image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                       nullptr, 0, nullptr, 1, &to_src);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {target_.width, target_.height, 1};
  vkCmdCopyImageToBuffer(cmd_, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer(), 1, &region);
  const auto back = colour_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  VkBufferMemoryBarrier host{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  host.buffer = readback_.buffer();
  host.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                       &host, 1, &back);
  commands_->submit_and_wait();

  RgbaImage out;
  out.width = target_.width;
  out.height = target_.height;
  out.pixels.resize(bytes);
  std::memcpy(out.pixels.data(), readback_.data(), bytes);
  if (bgra_)
    for (std::size_t i = 0; i + 3 < out.pixels.size(); i += 4) std::swap(out.pixels[i], out.pixels[i + 2]);
  return out;
}

}  // namespace gazelod::render
