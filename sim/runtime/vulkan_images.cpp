// SPDX-License-Identifier: Apache-2.0
// VkImage creation for swapchains (see vulkan_images.hpp).
#include "sim/runtime/vulkan_images.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>

namespace gazelod::xrrt {
namespace {

constexpr VkFormat kCandidateFormats[] = {
    VK_FORMAT_R8G8B8A8_SRGB,  VK_FORMAT_B8G8R8A8_SRGB,       VK_FORMAT_R8G8B8A8_UNORM,
    VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_D32_SFLOAT,
    VK_FORMAT_D16_UNORM,      VK_FORMAT_D24_UNORM_S8_UINT,   VK_FORMAT_D32_SFLOAT_S8_UINT,
};

bool is_depth(VkFormat f) {
  return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
         f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

VkImageUsageFlags vk_usage(XrSwapchainUsageFlags u) {
  VkImageUsageFlags out = 0;
  if (u & XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT) out |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (u & XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) out |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (u & XR_SWAPCHAIN_USAGE_UNORDERED_ACCESS_BIT) out |= VK_IMAGE_USAGE_STORAGE_BIT;
  if (u & XR_SWAPCHAIN_USAGE_TRANSFER_SRC_BIT) out |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (u & XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT) out |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (u & XR_SWAPCHAIN_USAGE_SAMPLED_BIT) out |= VK_IMAGE_USAGE_SAMPLED_BIT;
  // A compositor reads what the application drew.
  return out | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
}

bool find_memory_type(VkPhysicalDevice pd, std::uint32_t type_bits, std::uint32_t* index) {
  VkPhysicalDeviceMemoryProperties props{};
  vkGetPhysicalDeviceMemoryProperties(pd, &props);
  for (std::uint32_t pass = 0; pass < 2; ++pass) {  // device-local first, then anything allowed
    for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i) {
      const bool local = props.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
      if ((type_bits & (1u << i)) && (pass == 1 || local)) {
        *index = i;
        return true;
      }
    }
  }
  return false;
}

// The layout the application finds an image in when xrWaitSwapchainImage returns
// (XR_KHR_vulkan_enable "Swapchain Image Resource State"); UNDEFINED when the image is neither a
// colour nor a depth attachment, where there is no such promise.
VkImageLayout attachment_layout(const XrSwapchainCreateInfo& info, VkImageAspectFlags* aspect) {
  *aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  if (info.usageFlags & XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT) return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  if (!(info.usageFlags & XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)) return VK_IMAGE_LAYOUT_UNDEFINED;
  *aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  const auto format = static_cast<VkFormat>(info.format);
  if (format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT)
    *aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
  return VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
}

constexpr std::uint64_t kTransitionTimeout_ns = 5'000'000'000;

// Moves one image from UNDEFINED to `layout` on the application's queue, and waits.
VkResult transition_layout(const Session& s, VkImage image, VkImageLayout layout, VkImageAspectFlags aspect) {
  VkQueue queue = VK_NULL_HANDLE;
  vkGetDeviceQueue(s.vk_device, s.vk_queue_family, s.vk_queue_index, &queue);
  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.queueFamilyIndex = s.vk_queue_family;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkResult r = vkCreateCommandPool(s.vk_device, &pool_info, nullptr, &pool);
  if (r != VK_SUCCESS) return r;
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  r = vkAllocateCommandBuffers(s.vk_device, &alloc, &cmd);
  if (r == VK_SUCCESS) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = layout;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
    b.dstAccessMask = 0;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &b);
    vkEndCommandBuffer(cmd);
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    r = vkCreateFence(s.vk_device, &fence_info, nullptr, &fence);
    if (r == VK_SUCCESS) {
      VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
      submit.commandBufferCount = 1;
      submit.pCommandBuffers = &cmd;
      r = vkQueueSubmit(queue, 1, &submit, fence);
      // Behind whatever the application queued before it, under the runtime's lock: bounded, so
      // that work which never finishes fails this call instead of hanging every other one.
      if (r == VK_SUCCESS) r = vkWaitForFences(s.vk_device, 1, &fence, VK_TRUE, kTransitionTimeout_ns);
      if (r == VK_TIMEOUT) {
        // Still pending: destroying the fence or the pool now would be invalid, so both are
        // left to the device's destruction.
        std::fprintf(stderr, "gazelod_xr_runtime: swapchain layout change still pending after 5 s\n");
        return r;
      }
      vkDestroyFence(s.vk_device, fence, nullptr);
    }
  }
  vkDestroyCommandPool(s.vk_device, pool, nullptr);
  return r;
}

}  // namespace

std::vector<std::int64_t> vulkan_swapchain_formats(const Session& s) {
  std::vector<std::int64_t> out;
  if (s.vk_physical_device == VK_NULL_HANDLE) return out;
  for (VkFormat f : kCandidateFormats) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(s.vk_physical_device, f, &props);
    const VkFormatFeatureFlags need =
        is_depth(f) ? VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
    if ((props.optimalTilingFeatures & need) == need) out.push_back(f);
  }
  return out;
}

XrResult create_vulkan_images(const Session& s, Swapchain& sc, std::uint32_t count) {
  const XrSwapchainCreateInfo& info = sc.info;
  const auto format = static_cast<VkFormat>(info.format);
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  if (info.faceCount == 6) ici.flags |= VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  if (info.usageFlags & XR_SWAPCHAIN_USAGE_MUTABLE_FORMAT_BIT) ici.flags |= VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = format;
  ici.extent = {info.width, info.height, 1};
  ici.mipLevels = info.mipCount;
  // Requests no Vulkan image can meet on any device: a cube's faces are square, and a chain has
  // at most floor(log2(largest side)) + 1 levels.
  if ((info.faceCount == 6 && info.width != info.height) ||
      info.mipCount > static_cast<std::uint32_t>(std::bit_width(std::max(info.width, info.height))))
    return XR_ERROR_VALIDATION_FAILURE;
  const std::uint64_t layers = std::uint64_t{info.arraySize} * info.faceCount;  // no 32-bit wrap
  if (layers > UINT32_MAX) return XR_ERROR_FEATURE_UNSUPPORTED;
  ici.arrayLayers = static_cast<std::uint32_t>(layers);
  ici.samples = static_cast<VkSampleCountFlagBits>(info.sampleCount);
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = vk_usage(info.usageFlags);
  ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  // Creating an image the device cannot make is undefined behaviour, not an error code (lavapipe
  // crashed now and then on sRGB storage images): ask first, and refuse the usage instead.
  VkImageFormatProperties limits{};
  if (vkGetPhysicalDeviceImageFormatProperties(s.vk_physical_device, ici.format, ici.imageType, ici.tiling, ici.usage,
                                               ici.flags, &limits) != VK_SUCCESS)
    return XR_ERROR_FEATURE_UNSUPPORTED;
  if (ici.mipLevels > limits.maxMipLevels || ici.arrayLayers > limits.maxArrayLayers ||
      ici.extent.width > limits.maxExtent.width || ici.extent.height > limits.maxExtent.height ||
      !(limits.sampleCounts & ici.samples))
    return XR_ERROR_FEATURE_UNSUPPORTED;
  for (std::uint32_t i = 0; i < count; ++i) {
    SwapchainImage img;
    VkResult r = vkCreateImage(s.vk_device, &ici, nullptr, &img.image);
    if (r != VK_SUCCESS) {
      std::fprintf(stderr, "gazelod_xr_runtime: vkCreateImage failed (VkResult %d)\n", static_cast<int>(r));
      destroy_vulkan_images(s, sc);
      return XR_ERROR_RUNTIME_FAILURE;
    }
    sc.images.push_back(img);
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(s.vk_device, img.image, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    if (!find_memory_type(s.vk_physical_device, req.memoryTypeBits, &mai.memoryTypeIndex) ||
        vkAllocateMemory(s.vk_device, &mai, nullptr, &sc.images.back().memory) != VK_SUCCESS ||
        vkBindImageMemory(s.vk_device, img.image, sc.images.back().memory, 0) != VK_SUCCESS) {
      std::fprintf(stderr, "gazelod_xr_runtime: cannot allocate swapchain image memory\n");
      destroy_vulkan_images(s, sc);
      return XR_ERROR_RUNTIME_FAILURE;
    }
  }
  return XR_SUCCESS;
}

XrResult prepare_vulkan_image(const Session& s, Swapchain& sc, std::uint32_t index) {
  SwapchainImage& img = sc.images[index];
  if (img.laid_out) return XR_SUCCESS;
  VkImageAspectFlags aspect = 0;
  const VkImageLayout layout = attachment_layout(sc.info, &aspect);
  if (layout != VK_IMAGE_LAYOUT_UNDEFINED) {
    if (VkResult r = transition_layout(s, img.image, layout, aspect); r != VK_SUCCESS) {
      std::fprintf(stderr, "gazelod_xr_runtime: swapchain layout transition failed (VkResult %d)\n",
                   static_cast<int>(r));
      return XR_ERROR_RUNTIME_FAILURE;
    }
  }
  img.laid_out = true;
  return XR_SUCCESS;
}

void destroy_vulkan_images(const Session& s, Swapchain& sc) {
  if (s.vk_device == VK_NULL_HANDLE) return;
  for (SwapchainImage& img : sc.images) {
    if (img.image != VK_NULL_HANDLE) vkDestroyImage(s.vk_device, img.image, nullptr);
    if (img.memory != VK_NULL_HANDLE) vkFreeMemory(s.vk_device, img.memory, nullptr);
  }
  sc.images.clear();
}

}  // namespace gazelod::xrrt
