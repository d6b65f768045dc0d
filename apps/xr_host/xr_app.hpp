// SPDX-License-Identifier: Apache-2.0
// The OpenXR side of `gazelod run`, in hello_xr's shape: create the instance (Vulkan through
// XR_KHR_vulkan_enable2, eye gaze when offered), the session, spaces and one swapchain per
// view; then per frame poll events, wait, begin, locate views, acquire/release images, end.
#pragma once

#define XR_USE_GRAPHICS_API_VULKAN
#define XR_USE_TIMESPEC
#include <time.h>
#include <vulkan/vulkan.h>
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "plugin/xr_check.hpp"

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gazelod::xr_host {

// Every failed OpenXR or Vulkan set-up call: its name and result.
using XrAppError = XrCallError;

struct XrSwapchainView {
  XrSwapchain handle = XR_NULL_HANDLE;
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::int64_t format = 0;  // VkFormat
  std::vector<VkImage> images;
};

class XrApp {
 public:
  // Throws XrAppError naming the failing call: no runtime, no Vulkan device, ...
  explicit XrApp(bool want_eye_gaze);
  ~XrApp();
  XrApp(const XrApp&) = delete;
  XrApp& operator=(const XrApp&) = delete;

  XrInstance instance() const { return instance_; }
  XrSystemId system() const { return system_; }
  XrSession session() const { return session_; }
  XrSpace local_space() const { return local_space_; }
  bool eye_gaze_enabled() const { return eye_gaze_enabled_; }
  // The runtime's clock now (XR_KHR_convert_timespec_time from CLOCK_MONOTONIC), the clock
  // devices outside OpenXR (a HID eye tracker) stamp their samples on; 0 when not offered.
  XrTime now() const;
  const std::string& runtime_name() const { return runtime_name_; }
  // Scenario time 0 as an XrTime, when the runtime is gazelod's simulator
  // (XR_GAZELOD_simulator_state); 0 otherwise.
  XrTime scenario_time_base() const;
  const std::string& system_name() const { return system_name_; }

  VkInstance vk_instance() const { return vk_instance_; }
  VkPhysicalDevice vk_physical_device() const { return vk_physical_; }
  VkDevice vk_device() const { return vk_device_; }
  // VkPhysicalDeviceFeatures::multiDrawIndirect was enabled on vk_device().
  bool vk_multi_draw_indirect() const { return multi_draw_indirect_; }
  bool vk_draw_indirect_count() const { return draw_indirect_count_; }  // Vulkan 1.2's, enabled
  std::uint32_t vk_queue_family() const { return queue_family_; }
  VkQueue vk_queue() const { return queue_; }
  const std::string& vk_device_name() const { return vk_device_name_; }

  const std::vector<XrSwapchainView>& swapchains() const { return swapchains_; }

  // Drains the event queue; begins/ends the session as its state asks. Calls `on_state` for
  // each state change. Returns false once the application should stop (EXITING,
  // LOSS_PENDING, instance loss).
  bool poll_events(const std::function<void(XrSessionState, XrTime)>& on_state);
  bool session_running() const { return session_running_; }

  XrFrameState wait_frame();
  void begin_frame();
  // Views at `time` in the LOCAL space; false when the runtime reports no valid pose.
  bool locate_views(XrTime time, std::vector<XrView>& views);
  std::uint32_t acquire(std::size_t view);
  void release(std::size_t view);
  // Submits one projection layer when `views` is non-empty, otherwise no layers.
  void end_frame(XrTime display_time, const std::vector<XrView>& views);

 private:
  void create_instance(bool want_eye_gaze);
  void create_vulkan();
  void create_session();
  void create_swapchains();

  XrInstance instance_ = XR_NULL_HANDLE;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace local_space_ = XR_NULL_HANDLE;
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  bool session_running_ = false;
  bool eye_gaze_enabled_ = false;
  bool timespec_enabled_ = false;
  mutable void (*to_xr_time_)() = nullptr;
  bool simulator_state_enabled_ = false;
  std::string runtime_name_, system_name_, vk_device_name_;
  VkInstance vk_instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice vk_physical_ = VK_NULL_HANDLE;
  bool multi_draw_indirect_ = false;
  bool draw_indirect_count_ = false;
  VkDevice vk_device_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::vector<XrViewConfigurationView> config_views_;
  std::vector<XrSwapchainView> swapchains_;
  std::vector<XrCompositionLayerProjectionView> projection_views_;
};

}  // namespace gazelod::xr_host
