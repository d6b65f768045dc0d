// SPDX-License-Identifier: Apache-2.0
#include "render/pipeline.hpp"

#include "render/render_error.hpp"

#include <cstdint>
#include "shaders/lod_mesh.frag.h"
#include "shaders/lod_mesh.vert.h"
#include "shaders/lod_mesh_tinted.frag.h"
#include "shaders/lod_mesh_tinted.vert.h"

#include <array>

namespace gazelod::render {
namespace {

VkRenderPass create_render_pass(VkDevice device, VkFormat colour_format, VkFormat depth_format) {
  std::array<VkAttachmentDescription, 2> att{};
  att[0].format = colour_format;
  att[0].samples = VK_SAMPLE_COUNT_1_BIT;
  att[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  att[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  att[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  // Cleared every frame, so the old contents (and layout) never matter: a fresh swapchain
  // image starts UNDEFINED, and OpenXR wants COLOR_ATTACHMENT_OPTIMAL back.
  att[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  att[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  att[1].format = depth_format;
  att[1].samples = VK_SAMPLE_COUNT_1_BIT;
  att[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  att[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  att[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;

  VkAttachmentReference colour_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour_ref;
  subpass.pDepthStencilAttachment = &depth_ref;

  // The previous frame's (or readback's) use of the same attachments finishes before this
  // frame's clear writes them.
  VkSubpassDependency dep{};
  dep.srcSubpass = VK_SUBPASS_EXTERNAL;
  dep.dstSubpass = 0;
  dep.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                     VK_PIPELINE_STAGE_TRANSFER_BIT;
  dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dep.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                     VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dep.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

  VkRenderPassCreateInfo rci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rci.attachmentCount = static_cast<std::uint32_t>(att.size());
  rci.pAttachments = att.data();
  rci.subpassCount = 1;
  rci.pSubpasses = &subpass;
  rci.dependencyCount = 1;
  rci.pDependencies = &dep;
  VkRenderPass pass = VK_NULL_HANDLE;
  vk_check(vkCreateRenderPass(device, &rci, nullptr, &pass), "vkCreateRenderPass");
  return pass;
}

VkShaderModule create_module(VkDevice device, const std::uint32_t* code, std::size_t bytes) {
  VkShaderModuleCreateInfo sci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  sci.codeSize = bytes;
  sci.pCode = code;
  VkShaderModule module = VK_NULL_HANDLE;
  vk_check(vkCreateShaderModule(device, &sci, nullptr, &module), "vkCreateShaderModule");
  return module;
}

// tinted: the PER_CLUSTER_TINT build of the shaders, with binding 1 a vec3 per instance.
VkPipeline create_graphics_pipeline(VkDevice device, VkRenderPass pass, VkPipelineLayout layout, std::uint32_t width,
                                    std::uint32_t height, bool tinted) {
  VkShaderModule vert = tinted ? create_module(device, lod_mesh_tinted_vert_spv, sizeof lod_mesh_tinted_vert_spv)
                               : create_module(device, lod_mesh_vert_spv, sizeof lod_mesh_vert_spv);
  VkShaderModule frag = VK_NULL_HANDLE;
  try {
    frag = tinted ? create_module(device, lod_mesh_tinted_frag_spv, sizeof lod_mesh_tinted_frag_spv)
                  : create_module(device, lod_mesh_frag_spv, sizeof lod_mesh_frag_spv);
  } catch (...) {
    vkDestroyShaderModule(device, vert, nullptr);
    throw;
  }
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  stages[1].pName = "main";

  const std::array<VkVertexInputBindingDescription, 2> bindings{
      {{0, sizeof(float) * 3, VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(float) * 3, VK_VERTEX_INPUT_RATE_INSTANCE}}};
  const std::array<VkVertexInputAttributeDescription, 2> attributes{
      {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32G32B32_SFLOAT, 0}}};
  VkPipelineVertexInputStateCreateInfo vin{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vin.vertexBindingDescriptionCount = tinted ? 2 : 1;
  vin.pVertexBindingDescriptions = bindings.data();
  vin.vertexAttributeDescriptionCount = tinted ? 2 : 1;
  vin.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {width, height}};
  VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  vp.viewportCount = 1;
  vp.pViewports = &viewport;
  vp.scissorCount = 1;
  vp.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_BACK_BIT;
  // Meshes are counter-clockwise seen from outside; the projection's y flip keeps that
  // counter-clockwise in Vulkan's framebuffer convention.
  rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  rs.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  ds.depthTestEnable = VK_TRUE;
  ds.depthWriteEnable = VK_TRUE;
  ds.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask =
      VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  cb.attachmentCount = 1;
  cb.pAttachments = &blend;

  VkGraphicsPipelineCreateInfo pci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  pci.stageCount = static_cast<std::uint32_t>(stages.size());
  pci.pStages = stages.data();
  pci.pVertexInputState = &vin;
  pci.pInputAssemblyState = &ia;
  pci.pViewportState = &vp;
  pci.pRasterizationState = &rs;
  pci.pMultisampleState = &ms;
  pci.pDepthStencilState = &ds;
  pci.pColorBlendState = &cb;
  pci.layout = layout;
  pci.renderPass = pass;
  pci.subpass = 0;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &pci, nullptr, &pipeline);
  vkDestroyShaderModule(device, vert, nullptr);
  vkDestroyShaderModule(device, frag, nullptr);
  vk_check(r, "vkCreateGraphicsPipelines");
  return pipeline;
}

}  // namespace

VkFormat pick_depth_format(VkPhysicalDevice physical) {
  for (VkFormat f : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(physical, f, &props);
    if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return f;
  }
  throw RenderError("the Vulkan device supports no depth attachment format");
}

Pipeline create_pipeline(VkDevice device, VkFormat colour_format, VkFormat depth_format, std::uint32_t width,
                         std::uint32_t height) {
  Pipeline p;
  try {
    p.render_pass = create_render_pass(device, colour_format, depth_format);
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(DrawConstants)};
    VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &range;
    vk_check(vkCreatePipelineLayout(device, &lci, nullptr, &p.layout), "vkCreatePipelineLayout");
    p.pipeline = create_graphics_pipeline(device, p.render_pass, p.layout, width, height, false);
    p.tinted = create_graphics_pipeline(device, p.render_pass, p.layout, width, height, true);
  } catch (...) {
    destroy_pipeline(device, p);
    throw;
  }
  return p;
}

void destroy_pipeline(VkDevice device, Pipeline& p) {
  if (p.pipeline) vkDestroyPipeline(device, p.pipeline, nullptr);
  if (p.tinted) vkDestroyPipeline(device, p.tinted, nullptr);
  if (p.layout) vkDestroyPipelineLayout(device, p.layout, nullptr);
  if (p.render_pass) vkDestroyRenderPass(device, p.render_pass, nullptr);
  p = {};
}

}  // namespace gazelod::render
