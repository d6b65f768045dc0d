// SPDX-License-Identifier: Apache-2.0
#include "render/gpu_memory.hpp"

#include "render/render_error.hpp"

#include <utility>

namespace gazelod::render {

std::uint32_t find_memory_type(VkPhysicalDevice physical, std::uint32_t type_bits, VkMemoryPropertyFlags flags) {
  VkPhysicalDeviceMemoryProperties props{};
  vkGetPhysicalDeviceMemoryProperties(physical, &props);
  for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
  throw RenderError("no Vulkan memory type with property flags " + std::to_string(flags));
}

BoundBuffer create_bound_buffer(const DeviceContext& ctx, VkDeviceSize size_bytes, VkBufferUsageFlags usage,
                                VkMemoryPropertyFlags flags, bool any_type_fallback) {
  BoundBuffer b;
  try {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size_bytes > 0 ? size_bytes : 4;  // Vulkan forbids empty buffers
    bci.usage = usage;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    vk_check(vkCreateBuffer(ctx.device, &bci, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    try {
      mai.memoryTypeIndex = find_memory_type(ctx.physical, req.memoryTypeBits, flags);
    } catch (const RenderError&) {
      if (!any_type_fallback) throw;
      mai.memoryTypeIndex = find_memory_type(ctx.physical, req.memoryTypeBits, 0);
    }
    vk_check(vkAllocateMemory(ctx.device, &mai, nullptr, &b.memory), "vkAllocateMemory (buffer)");
    vk_check(vkBindBufferMemory(ctx.device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  } catch (...) {
    if (b.buffer) vkDestroyBuffer(ctx.device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(ctx.device, b.memory, nullptr);
    throw;
  }
  return b;
}

HostBuffer::HostBuffer(const DeviceContext& ctx, VkDeviceSize size_bytes, VkBufferUsageFlags usage)
    : device_(ctx.device), size_(size_bytes) {
  const BoundBuffer b = create_bound_buffer(ctx, size_bytes, usage,
                                            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  buffer_ = b.buffer;
  memory_ = b.memory;
  try {
    vk_check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
  } catch (...) {
    reset();
    throw;
  }
}

HostBuffer::~HostBuffer() {
  reset();
}

HostBuffer::HostBuffer(HostBuffer&& o) noexcept
    : device_(std::exchange(o.device_, VK_NULL_HANDLE)),
      buffer_(std::exchange(o.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(o.memory_, VK_NULL_HANDLE)),
      mapped_(std::exchange(o.mapped_, nullptr)),
      size_(std::exchange(o.size_, 0)) {}

HostBuffer& HostBuffer::operator=(HostBuffer&& o) noexcept {
  if (this != &o) {
    reset();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    mapped_ = std::exchange(o.mapped_, nullptr);
    size_ = std::exchange(o.size_, 0);
  }
  return *this;
}

void HostBuffer::reset() {
  if (device_ == VK_NULL_HANDLE) return;
  if (mapped_) vkUnmapMemory(device_, memory_);
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  mapped_ = nullptr;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
}

VkImageView create_image_view(VkDevice device, VkImage image, VkFormat format, VkImageAspectFlags aspect) {
  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = image;
  vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
  vci.format = format;
  vci.subresourceRange = {aspect, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  vk_check(vkCreateImageView(device, &vci, nullptr, &view), "vkCreateImageView");
  return view;
}

DeviceImage::DeviceImage(const DeviceContext& ctx, std::uint32_t width, std::uint32_t height, VkFormat format,
                         VkImageUsageFlags usage, VkImageAspectFlags aspect)
    : device_(ctx.device) {
  try {
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = format;
    ici.extent = {width, height, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = usage;
    ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    vk_check(vkCreateImage(device_, &ici, nullptr, &image_), "vkCreateImage");
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(device_, image_, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = find_memory_type(ctx.physical, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    vk_check(vkAllocateMemory(device_, &mai, nullptr, &memory_), "vkAllocateMemory (image)");
    vk_check(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory");
    view_ = create_image_view(device_, image_, format, aspect);
  } catch (...) {
    reset();
    throw;
  }
}

DeviceImage::~DeviceImage() {
  reset();
}

DeviceImage::DeviceImage(DeviceImage&& o) noexcept
    : device_(std::exchange(o.device_, VK_NULL_HANDLE)),
      image_(std::exchange(o.image_, VK_NULL_HANDLE)),
      memory_(std::exchange(o.memory_, VK_NULL_HANDLE)),
      view_(std::exchange(o.view_, VK_NULL_HANDLE)) {}

DeviceImage& DeviceImage::operator=(DeviceImage&& o) noexcept {
  if (this != &o) {
    reset();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    image_ = std::exchange(o.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
  }
  return *this;
}

void DeviceImage::reset() {
  if (device_ == VK_NULL_HANDLE) return;
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
}

}  // namespace gazelod::render
