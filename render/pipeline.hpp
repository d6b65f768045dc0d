// SPDX-License-Identifier: Apache-2.0
// The renderer's graphics pipelines (one tint per draw, or one per instance): clear colour +
// depth, draw LOD meshes with the lod_mesh shaders, leave the colour image in
// COLOR_ATTACHMENT_OPTIMAL (what OpenXR expects of a released swapchain image).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>

namespace gazelod::render {

// Mirrors the push-constant block of shaders/lod_mesh.vert and lod_mesh.frag.
struct DrawConstants {
  glm::mat4 view_proj;
  glm::vec4 center_radius;
  glm::vec4 colour;
  glm::vec4 eye_position;
};
static_assert(sizeof(DrawConstants) == 112, "push constants must match the shaders (<= 128 bytes)");

// First of D32_SFLOAT, X8_D24, D16_UNORM usable as a depth attachment; throws RenderError.
VkFormat pick_depth_format(VkPhysicalDevice physical);

struct Pipeline {
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  // The same with each draw's tint from a per-instance vec3 at vertex binding 1 (picked by the
  // command's firstInstance) instead of the push constants' colour: GPU-built cuts.
  VkPipeline tinted = VK_NULL_HANDLE;
};

// Throws RenderError; destroy with destroy_pipeline.
Pipeline create_pipeline(VkDevice device, VkFormat colour_format, VkFormat depth_format, std::uint32_t width,
                         std::uint32_t height);
void destroy_pipeline(VkDevice device, Pipeline& pipeline);

}  // namespace gazelod::render
