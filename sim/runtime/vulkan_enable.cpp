// SPDX-License-Identifier: Apache-2.0
// XR_KHR_vulkan_enable and XR_KHR_vulkan_enable2: graphics requirements, the physical device
// to use (the first the Vulkan loader lists: lavapipe when VK_ICD_FILENAMES forces it), and
// instance / device creation on the application's behalf (enable2).
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/system_info.hpp"

#include <vector>

namespace gazelod::xrrt {
namespace {

XrResult pick_physical_device(Instance& inst, VkInstance vk_instance, VkPhysicalDevice* out) {
  std::uint32_t n = 0;
  if (vkEnumeratePhysicalDevices(vk_instance, &n, nullptr) != VK_SUCCESS || n == 0) return XR_ERROR_RUNTIME_FAILURE;
  std::vector<VkPhysicalDevice> devices(n);
  if (vkEnumeratePhysicalDevices(vk_instance, &n, devices.data()) < 0 || n == 0) return XR_ERROR_RUNTIME_FAILURE;
  inst.vk_instance = vk_instance;
  inst.vk_physical_device = devices[0];
  *out = devices[0];
  return XR_SUCCESS;
}

}  // namespace

XrResult GetVulkanInstanceExtensionsKHR(XrInstance instance, XrSystemId systemId, uint32_t capacity, uint32_t* count,
                                        char* buffer) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (XrResult r = check_system(find_instance(instance), systemId); r != XR_SUCCESS) return r;
    return two_call_string(capacity, count, buffer, "");  // nothing beyond core Vulkan
  });
}

XrResult GetVulkanDeviceExtensionsKHR(XrInstance instance, XrSystemId systemId, uint32_t capacity, uint32_t* count,
                                      char* buffer) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (XrResult r = check_system(find_instance(instance), systemId); r != XR_SUCCESS) return r;
    return two_call_string(capacity, count, buffer, "");
  });
}

XrResult GetVulkanGraphicsRequirementsKHR(XrInstance instance, XrSystemId systemId,
                                          XrGraphicsRequirementsVulkanKHR* requirements) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    if (requirements == nullptr || requirements->type != XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN_KHR)
      return XR_ERROR_VALIDATION_FAILURE;
    requirements->minApiVersionSupported = XR_MAKE_VERSION(1, 0, 0);
    requirements->maxApiVersionSupported = XR_MAKE_VERSION(1, 3, 0);
    inst->graphics_requirements_queried = true;
    return XR_SUCCESS;
  });
}

XrResult GetVulkanGraphicsDeviceKHR(XrInstance instance, XrSystemId systemId, VkInstance vkInstance,
                                    VkPhysicalDevice* vkPhysicalDevice) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (XrResult r = check_system(inst, systemId); r != XR_SUCCESS) return r;
    if (vkInstance == VK_NULL_HANDLE || vkPhysicalDevice == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    return pick_physical_device(*inst, vkInstance, vkPhysicalDevice);
  });
}

XrResult GetVulkanGraphicsDevice2KHR(XrInstance instance, const XrVulkanGraphicsDeviceGetInfoKHR* getInfo,
                                     VkPhysicalDevice* vulkanPhysicalDevice) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Instance* inst = find_instance(instance);
    if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (getInfo == nullptr || getInfo->type != XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR ||
        getInfo->vulkanInstance == VK_NULL_HANDLE || vulkanPhysicalDevice == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    if (XrResult r = check_system(inst, getInfo->systemId); r != XR_SUCCESS) return r;
    return pick_physical_device(*inst, getInfo->vulkanInstance, vulkanPhysicalDevice);
  });
}

XrResult CreateVulkanInstanceKHR(XrInstance instance, const XrVulkanInstanceCreateInfoKHR* info,
                                 VkInstance* vulkanInstance, VkResult* vulkanResult) {
  return guarded([&] {
    PFN_vkCreateInstance create = nullptr;
    {
      std::lock_guard lock(runtime_mutex());
      Instance* inst = find_instance(instance);
      if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (info == nullptr || info->type != XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR || info->createFlags != 0 ||
          info->pfnGetInstanceProcAddr == nullptr || info->vulkanCreateInfo == nullptr || vulkanInstance == nullptr ||
          vulkanResult == nullptr)
        return XR_ERROR_VALIDATION_FAILURE;
      if (XrResult r = check_system(inst, info->systemId); r != XR_SUCCESS) return r;
      create = reinterpret_cast<PFN_vkCreateInstance>(info->pfnGetInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    }
    if (create == nullptr) return XR_ERROR_RUNTIME_FAILURE;
    // The runtime needs no Vulkan extension, so the application's create info goes as is.
    *vulkanResult = create(info->vulkanCreateInfo, info->vulkanAllocator, vulkanInstance);
    return XR_SUCCESS;
  });
}

XrResult CreateVulkanDeviceKHR(XrInstance instance, const XrVulkanDeviceCreateInfoKHR* info, VkDevice* vulkanDevice,
                               VkResult* vulkanResult) {
  return guarded([&] {
    PFN_vkCreateDevice create = nullptr;
    {
      std::lock_guard lock(runtime_mutex());
      Instance* inst = find_instance(instance);
      if (inst == nullptr) return XR_ERROR_HANDLE_INVALID;
      if (info == nullptr || info->type != XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR || info->createFlags != 0 ||
          info->pfnGetInstanceProcAddr == nullptr || info->vulkanCreateInfo == nullptr ||
          info->vulkanPhysicalDevice == VK_NULL_HANDLE || vulkanDevice == nullptr || vulkanResult == nullptr)
        return XR_ERROR_VALIDATION_FAILURE;
      if (XrResult r = check_system(inst, info->systemId); r != XR_SUCCESS) return r;
      // The device must be on the physical device xrGetVulkanGraphicsDevice2KHR returned.
      if (inst->vk_instance == VK_NULL_HANDLE) return XR_ERROR_CALL_ORDER_INVALID;
      if (info->vulkanPhysicalDevice != inst->vk_physical_device) return XR_ERROR_VALIDATION_FAILURE;
      create = reinterpret_cast<PFN_vkCreateDevice>(info->pfnGetInstanceProcAddr(inst->vk_instance, "vkCreateDevice"));
    }
    if (create == nullptr) return XR_ERROR_RUNTIME_FAILURE;
    *vulkanResult = create(info->vulkanPhysicalDevice, info->vulkanCreateInfo, info->vulkanAllocator, vulkanDevice);
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
