// SPDX-License-Identifier: Apache-2.0
// Device-local buffers, one-shot command buffers and staged copies (device_buffer.hpp).
#include "render/device_buffer.hpp"

#include "render/render_error.hpp"

#include <algorithm>
#include <cstring>

namespace gazelod::render {

DeviceBuffer::DeviceBuffer(const DeviceContext& ctx, VkDeviceSize size_bytes, VkBufferUsageFlags usage)
    : owned_(std::make_unique<Owned>()) {
  owned_->bound = create_bound_buffer(ctx, size_bytes, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, true);
  owned_->device = ctx.device;  // set once the buffer exists: ~Owned frees what it names
  owned_->size = size_bytes;
}

DeviceBuffer::Owned::~Owned() {
  if (device == VK_NULL_HANDLE) return;
  vkDestroyBuffer(device, bound.buffer, nullptr);
  vkFreeMemory(device, bound.memory, nullptr);
}

OneShotCommands::OneShotCommands(const DeviceContext& ctx) : device_(ctx.device), queue_(ctx.queue) {
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = ctx.queue_family;
  vk_check(vkCreateCommandPool(device_, &pci, nullptr, &pool_), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cai.commandPool = pool_;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkResult r = vkAllocateCommandBuffers(device_, &cai, &cmd_);
  if (r == VK_SUCCESS) r = vkCreateFence(device_, &fci, nullptr, &fence_);
  if (r != VK_SUCCESS) {
    vkDestroyCommandPool(device_, pool_, nullptr);  // frees cmd_
    vk_check(r, cmd_ ? "vkCreateFence" : "vkAllocateCommandBuffers");
  }
}

OneShotCommands::~OneShotCommands() {
  vkDestroyFence(device_, fence_, nullptr);
  vkDestroyCommandPool(device_, pool_, nullptr);  // frees cmd_
}

VkCommandBuffer OneShotCommands::begin() {
  vk_check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk_check(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");
  return cmd_;
}

void OneShotCommands::submit_and_wait() {
  vk_check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
  VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd_;
  vk_check(vkQueueSubmit(queue_, 1, &si, fence_), "vkQueueSubmit");
  vk_check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  vk_check(vkResetFences(device_, 1, &fence_), "vkResetFences");
}

namespace {

// Everything earlier in the queue (a pass writing `buffer`) before the copy, and the copy's
// writes before the host or later commands read.
void copy_slice(OneShotCommands& commands, VkBuffer src, VkDeviceSize src_offset, VkBuffer dst, VkDeviceSize dst_offset,
                VkDeviceSize bytes) {
  VkCommandBuffer cmd = commands.begin();
  VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0,
                       nullptr, 0, nullptr);
  const VkBufferCopy region{src_offset, dst_offset, bytes};
  vkCmdCopyBuffer(cmd, src, dst, 1, &region);
  VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_HOST_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &after, 0, nullptr, 0,
                       nullptr);
  commands.submit_and_wait();
}

}  // namespace

void copy_to_device(OneShotCommands& commands, HostBuffer& staging, VkBuffer dst, VkDeviceSize dst_offset,
                    const void* src, VkDeviceSize bytes) {
  const auto* from = static_cast<const unsigned char*>(src);
  for (VkDeviceSize done = 0; done < bytes;) {
    const VkDeviceSize n = std::min(bytes - done, staging.size());
    std::memcpy(staging.data(), from + done, n);
    copy_slice(commands, staging.buffer(), 0, dst, dst_offset + done, n);
    done += n;
  }
}

void copy_from_device(OneShotCommands& commands, HostBuffer& staging, VkBuffer src, VkDeviceSize src_offset, void* dst,
                      VkDeviceSize bytes) {
  auto* to = static_cast<unsigned char*>(dst);
  for (VkDeviceSize done = 0; done < bytes;) {
    const VkDeviceSize n = std::min(bytes - done, staging.size());
    copy_slice(commands, src, src_offset + done, staging.buffer(), 0, n);
    std::memcpy(to + done, staging.data(), n);
    done += n;
  }
}

}  // namespace gazelod::render
