// SPDX-License-Identifier: Apache-2.0
// Errors of the Vulkan renderer: every failing Vulkan call is reported by name and VkResult,
// and "there is no usable Vulkan device" is its own type so callers (tests) can tell it apart.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace gazelod::render {

struct RenderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// No Vulkan loader/ICD, or no device with a graphics queue.
struct NoVulkanDevice : RenderError {
  using RenderError::RenderError;
};

// Throws RenderError("<call> failed (VkResult N)") unless `result` is VK_SUCCESS.
inline void vk_check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw RenderError(std::string(call) + " failed (VkResult " + std::to_string(result) + ")");
}

}  // namespace gazelod::render
