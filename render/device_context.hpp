// SPDX-License-Identifier: Apache-2.0
// The Vulkan objects the renderer draws with: borrowed from the OpenXR runtime
// (XR_KHR_vulkan_enable2 gives instance, physical device, device and queue) or owned by an
// OffscreenDevice, which makes its own instance and device on Mesa's lavapipe for tests,
// benchmarks and `gazelod bake`.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace gazelod::render {

// Plain handles; whoever created them destroys them.
struct DeviceContext {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  VkQueue queue = VK_NULL_HANDLE;
  // VkPhysicalDeviceFeatures::multiDrawIndirect was enabled on `device` (OffscreenDevice and
  // the OpenXR host, apps/xr_host, enable it where supported).
  bool multi_draw_indirect = false;
  // Vulkan 1.2's drawIndirectCount was enabled on `device` (vkCmdDrawIndexedIndirectCount:
  // FrameRenderer::draw_indirect_count; OffscreenDevice enables it where supported).
  bool draw_indirect_count = false;
};

class OffscreenDevice {
 public:
  // Prefers a CPU device (lavapipe), else the first with a graphics queue; with prefer_gpu, a
  // discrete GPU, then an integrated one, then any other (benchmarks meant for real hardware).
  // Enables VK_LAYER_KHRONOS_validation when asked and installed (messages:
  // validation_messages()). Throws NoVulkanDevice when there is no loader, no ICD or no
  // graphics-capable device.
  explicit OffscreenDevice(bool want_validation = true, bool prefer_gpu = false);
  ~OffscreenDevice();
  OffscreenDevice(const OffscreenDevice&) = delete;
  OffscreenDevice& operator=(const OffscreenDevice&) = delete;

  const DeviceContext& context() const { return ctx_; }
  const std::string& device_name() const { return device_name_; }
  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }
  // Warnings and errors the validation layer reported so far (empty without the layer).
  std::vector<std::string> validation_messages() const;

 private:
  struct Messages {
    mutable std::mutex mutex;
    std::vector<std::string> list;
  };
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  void destroy();

  DeviceContext ctx_;
  std::string device_name_;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::unique_ptr<Messages> messages_ = std::make_unique<Messages>();
};

}  // namespace gazelod::render
