// SPDX-License-Identifier: Apache-2.0
// Owning wrappers for the few Vulkan allocations the renderer makes: a persistently mapped
// host-visible buffer (meshes, readback) and a device image with its view (depth, offscreen
// colour). Move-only; destroyed with the device they were made on.
#pragma once

#include "render/device_context.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace gazelod::render {

// Index of a memory type allowed by `type_bits` with all of `flags`; throws RenderError.
std::uint32_t find_memory_type(VkPhysicalDevice physical, std::uint32_t type_bits, VkMemoryPropertyFlags flags);

// A buffer of size_bytes (at least 4: Vulkan forbids empty buffers) bound to its own memory of a
// type with all of `flags` (with `any_type_fallback`, of any type where none has them). Throws
// RenderError, leaving nothing behind. HostBuffer's and DeviceBuffer's (device_buffer.hpp).
struct BoundBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
};
BoundBuffer create_bound_buffer(const DeviceContext& ctx, VkDeviceSize size_bytes, VkBufferUsageFlags usage,
                                VkMemoryPropertyFlags flags, bool any_type_fallback = false);

class HostBuffer {
 public:
  HostBuffer() = default;
  HostBuffer(const DeviceContext& ctx, VkDeviceSize size_bytes, VkBufferUsageFlags usage);
  ~HostBuffer();
  HostBuffer(HostBuffer&& other) noexcept;
  HostBuffer& operator=(HostBuffer&& other) noexcept;
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;

  VkBuffer buffer() const { return buffer_; }
  void* data() const { return mapped_; }
  VkDeviceSize size() const { return size_; }

 private:
  void reset();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
  VkDeviceSize size_ = 0;
};

class DeviceImage {
 public:
  DeviceImage() = default;
  DeviceImage(const DeviceContext& ctx, std::uint32_t width, std::uint32_t height, VkFormat format,
              VkImageUsageFlags usage, VkImageAspectFlags aspect);
  ~DeviceImage();
  DeviceImage(DeviceImage&& other) noexcept;
  DeviceImage& operator=(DeviceImage&& other) noexcept;
  DeviceImage(const DeviceImage&) = delete;
  DeviceImage& operator=(const DeviceImage&) = delete;

  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }

 private:
  void reset();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

// A 2D colour view of `image` (swapchain or owned); the caller destroys it.
VkImageView create_image_view(VkDevice device, VkImage image, VkFormat format, VkImageAspectFlags aspect);

}  // namespace gazelod::render
