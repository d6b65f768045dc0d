// SPDX-License-Identifier: Apache-2.0
#include "render/device_context.hpp"
#include "render/vulkan12_features.hpp"
#include "render/render_error.hpp"

#include <algorithm>
#include <cstring>

namespace gazelod::render {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  std::uint32_t n = 0;
  if (vkEnumerateInstanceLayerProperties(&n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(n);
  if (vkEnumerateInstanceLayerProperties(&n, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.end(),
                     [name](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_instance_extension(const char* name) {
  std::uint32_t n = 0;
  if (vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> exts(n);
  if (vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data()) != VK_SUCCESS) return false;
  return std::any_of(exts.begin(), exts.end(),
                     [name](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// Graphics queue family of `physical`, or -1.
int graphics_family(VkPhysicalDevice physical) {
  std::uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &n, families.data());
  for (std::uint32_t i = 0; i < n; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return static_cast<int>(i);
  return -1;
}

}  // namespace

OffscreenDevice::OffscreenDevice(bool want_validation, bool prefer_gpu) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "gazelod offscreen renderer";
  // 1.2 where the loader has it: vkCmdDrawIndexedIndirectCount is core there.
  std::uint32_t loader_version = VK_API_VERSION_1_0;  // a 1.0 loader lacks the query
  const auto version_of = reinterpret_cast<PFN_vkEnumerateInstanceVersion>(
      vkGetInstanceProcAddr(VK_NULL_HANDLE, "vkEnumerateInstanceVersion"));
  if (!version_of || version_of(&loader_version) != VK_SUCCESS) loader_version = VK_API_VERSION_1_0;
  app.apiVersion = loader_version >= VK_API_VERSION_1_2 ? VK_API_VERSION_1_2 : VK_API_VERSION_1_1;
  const bool validate =
      want_validation && has_layer(kValidationLayer) && has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  if (validate) {
    ici.enabledLayerCount = 1;
    ici.ppEnabledLayerNames = layers;
    ici.enabledExtensionCount = 1;
    ici.ppEnabledExtensionNames = extensions;
  }
  VkResult r = vkCreateInstance(&ici, nullptr, &ctx_.instance);
  if (r != VK_SUCCESS)
    throw NoVulkanDevice("no Vulkan: vkCreateInstance failed (VkResult " + std::to_string(r) +
                         "); install mesa-vulkan-drivers for lavapipe");
  try {
    if (validate) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(ctx_.instance, "vkCreateDebugUtilsMessengerEXT"));
      VkDebugUtilsMessengerCreateInfoEXT mci{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
      mci.messageSeverity =
          VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                        VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
      mci.pfnUserCallback = &OffscreenDevice::on_message;
      mci.pUserData = messages_.get();
      if (create) vk_check(create(ctx_.instance, &mci, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }

    std::uint32_t n = 0;
    vk_check(vkEnumeratePhysicalDevices(ctx_.instance, &n, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(n);
    vk_check(vkEnumeratePhysicalDevices(ctx_.instance, &n, devices.data()), "vkEnumeratePhysicalDevices");
    // Lavapipe (a CPU device) first: results are then the same on every machine (unless
    // prefer_gpu: real hardware for GPU benchmarks).
    int best_rank = -1;
    for (VkPhysicalDevice d : devices) {
      const int family = graphics_family(d);
      if (family < 0) continue;
      VkPhysicalDeviceProperties p{};
      vkGetPhysicalDeviceProperties(d, &p);
      if (p.apiVersion < VK_API_VERSION_1_1) continue;
      const int rank = !prefer_gpu ? (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1 : 0)
                       : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU   ? 3
                       : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 2
                       : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU            ? 0
                                                                                : 1;
      if (rank > best_rank) {
        best_rank = rank;
        ctx_.physical = d;
        ctx_.queue_family = static_cast<std::uint32_t>(family);
        device_name_ = p.deviceName;
      }
    }
    if (ctx_.physical == VK_NULL_HANDLE)
      throw NoVulkanDevice("no Vulkan device with a graphics queue (" + std::to_string(n) +
                           " device(s) found); install mesa-vulkan-drivers for lavapipe");

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = ctx_.queue_family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    // Lets FrameRenderer draw a cluster cut's runs of one tint with one indirect command.
    VkPhysicalDeviceFeatures supported{}, enabled{};
    vkGetPhysicalDeviceFeatures(ctx_.physical, &supported);
    enabled.multiDrawIndirect = supported.multiDrawIndirect;
    // And the GPU-driven cut's one draw (ClusterSelectPass's commands and count).
    Vulkan12Features features12 = vulkan12_features_to_enable(ctx_.physical, app.apiVersion);
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = features12.has_vulkan_12 ? &features12.enabled : nullptr;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.pEnabledFeatures = &enabled;
    r = vkCreateDevice(ctx_.physical, &dci, nullptr, &ctx_.device);
    if (r != VK_SUCCESS)
      throw NoVulkanDevice("vkCreateDevice on " + device_name_ + " failed (VkResult " + std::to_string(r) + ")");
    vkGetDeviceQueue(ctx_.device, ctx_.queue_family, 0, &ctx_.queue);
    ctx_.multi_draw_indirect = enabled.multiDrawIndirect == VK_TRUE;
    ctx_.draw_indirect_count = features12.enabled.drawIndirectCount == VK_TRUE;
  } catch (...) {
    destroy();
    throw;
  }
}

OffscreenDevice::~OffscreenDevice() {
  destroy();
}

void OffscreenDevice::destroy() {
  if (ctx_.device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(ctx_.device);
    vkDestroyDevice(ctx_.device, nullptr);
    ctx_.device = VK_NULL_HANDLE;
  }
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(ctx_.instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy_messenger) destroy_messenger(ctx_.instance, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (ctx_.instance != VK_NULL_HANDLE) {
    vkDestroyInstance(ctx_.instance, nullptr);
    ctx_.instance = VK_NULL_HANDLE;
  }
}

std::vector<std::string> OffscreenDevice::validation_messages() const {
  std::lock_guard lock(messages_->mutex);
  return messages_->list;
}

VKAPI_ATTR VkBool32 VKAPI_CALL OffscreenDevice::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                           VkDebugUtilsMessageTypeFlagsEXT,
                                                           const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                           void* user) {
  auto* messages = static_cast<Messages*>(user);
  std::lock_guard lock(messages->mutex);
  messages->list.emplace_back(data && data->pMessage ? data->pMessage : "(no message)");
  return VK_FALSE;
}

}  // namespace gazelod::render
