// SPDX-License-Identifier: Apache-2.0
// The Vulkan 1.2 features gazelod enables where a device has them (header only, so the OpenXR
// host, which creates its device through the runtime, and render/'s own devices ask alike).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace gazelod::render {

// What to chain into VkDeviceCreateInfo::pNext: drawIndirectCount where both the instance
// (instance_api_version, VkApplicationInfo::apiVersion) and the device have Vulkan 1.2, so a cut
// a compute pass wrote is drawn with one vkCmdDrawIndexedIndirectCount. sType is set either way;
// chain it only when has_vulkan_12 says the device takes the structure.
struct Vulkan12Features {
  bool has_vulkan_12 = false;
  VkPhysicalDeviceVulkan12Features enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
};

inline Vulkan12Features vulkan12_features_to_enable(VkPhysicalDevice physical, std::uint32_t instance_api_version) {
  Vulkan12Features f;
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(physical, &props);
  f.has_vulkan_12 = instance_api_version >= VK_API_VERSION_1_2 && props.apiVersion >= VK_API_VERSION_1_2;
  if (!f.has_vulkan_12) return f;
  VkPhysicalDeviceVulkan12Features supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features2.pNext = &supported;
  vkGetPhysicalDeviceFeatures2(physical, &features2);
  f.enabled.drawIndirectCount = supported.drawIndirectCount;
  return f;
}

}  // namespace gazelod::render
