// SPDX-License-Identifier: Apache-2.0
// Device-local Vulkan buffers and the copies that fill and read them (through a host-visible
// staging buffer, in slices), for GPU-resident data such as the cluster-selection pass's records
// and draw commands (render/cluster_select_pass.hpp): on a discrete GPU a compute pass must read
// device memory, not a host-visible buffer over the bus. And the one command buffer, fence and
// pool that a record-submit-wait user needs (the copies, the pass, FrameRenderer).
#pragma once

#include "render/device_context.hpp"
#include "render/gpu_memory.hpp"

#include <vulkan/vulkan.h>

#include <memory>

namespace gazelod::render {

class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  // DEVICE_LOCAL memory (any type where the device has none). Throws RenderError.
  DeviceBuffer(const DeviceContext& ctx, VkDeviceSize size_bytes, VkBufferUsageFlags usage);

  VkBuffer buffer() const { return owned_ ? owned_->bound.buffer : VK_NULL_HANDLE; }
  VkDeviceSize size() const { return owned_ ? owned_->size : 0; }

 private:
  struct Owned {  // move-only through the pointer; destroyed with the device it was made on
    VkDevice device = VK_NULL_HANDLE;
    BoundBuffer bound;
    VkDeviceSize size = 0;
    ~Owned();
  };
  std::unique_ptr<Owned> owned_;
};

// One command buffer, recorded, submitted and waited for.
class OneShotCommands {
 public:
  explicit OneShotCommands(const DeviceContext& ctx);  // throws RenderError
  ~OneShotCommands();
  OneShotCommands(const OneShotCommands&) = delete;
  OneShotCommands& operator=(const OneShotCommands&) = delete;

  VkCommandBuffer begin();  // resets and begins the command buffer (one-time submit)
  void submit_and_wait();   // ends, submits, waits

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

// Host <-> device copies through `staging` (host-visible, TRANSFER_SRC and TRANSFER_DST), one
// slice of its size per submission; each returns when its data has arrived.
void copy_to_device(OneShotCommands& commands, HostBuffer& staging, VkBuffer dst, VkDeviceSize dst_offset,
                    const void* src, VkDeviceSize bytes);
void copy_from_device(OneShotCommands& commands, HostBuffer& staging, VkBuffer src, VkDeviceSize src_offset, void* dst,
                      VkDeviceSize bytes);

}  // namespace gazelod::render
