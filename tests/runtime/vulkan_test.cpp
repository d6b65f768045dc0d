// SPDX-License-Identifier: Apache-2.0
// XR_KHR_vulkan_enable2 on lavapipe: Vulkan instance and device created through the runtime,
// a session with a Vulkan binding, swapchains of real VkImages and the acquire / wait /
// release and xrEndFrame layer rules.
#include "sim/runtime/xr_headers.hpp"
#include "tests/runtime/xr_client.hpp"
#include "tests/skip_or_fail.hpp"

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace gazelod::xrrt_test {
namespace {

struct VulkanRig {
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  VkInstance vk_instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  XrSession session = XR_NULL_HANDLE;
  // With `validate`, Khronos's validation layer checks every Vulkan call on the device, the
  // runtime's own included (they pass through the same dispatch); its errors are kept here.
  bool validate = false;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  std::vector<std::string> validation_errors;

  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
      static_cast<VulkanRig*>(self)->validation_errors.emplace_back(data->pMessage ? data->pMessage : "");
    return VK_FALSE;
  }

  static bool has_validation_layer() {
    std::uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    for (const VkLayerProperties& l : layers)
      if (std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0) return true;
    return false;
  }

  void create_devices() {
    instance = create_instance({XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME});
    ASSERT_NE(instance, XR_NULL_HANDLE);
    system = get_system(instance);
    // No session before the graphics requirements were queried.
    VkInstance fake = reinterpret_cast<VkInstance>(uintptr_t(1));
    XrGraphicsBindingVulkan2KHR early{XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR};
    early.instance = fake;
    early.physicalDevice = reinterpret_cast<VkPhysicalDevice>(uintptr_t(1));
    early.device = reinterpret_cast<VkDevice>(uintptr_t(1));
    XrSessionCreateInfo si{XR_TYPE_SESSION_CREATE_INFO, &early};
    si.systemId = system;
    XrSession s = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateSession(instance, &si, &s), XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING);

    XrGraphicsRequirementsVulkan2KHR req{XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR};
    XRRT_ASSERT_XR(proc<PFN_xrGetVulkanGraphicsRequirements2KHR>(instance, "xrGetVulkanGraphicsRequirements2KHR")(
        instance, system, &req));
    EXPECT_LE(req.minApiVersionSupported, XR_MAKE_VERSION(1, 0, 0));

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_0;
    VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    if (validate) {
      ici.enabledLayerCount = 1;
      ici.ppEnabledLayerNames = &layer;
      ici.enabledExtensionCount = 1;
      ici.ppEnabledExtensionNames = &extension;
    }
    XrVulkanInstanceCreateInfoKHR xci{XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR};
    xci.systemId = system;
    xci.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
    xci.vulkanCreateInfo = &ici;
    VkResult vr = VK_ERROR_UNKNOWN;
    XRRT_ASSERT_XR(
        proc<PFN_xrCreateVulkanInstanceKHR>(instance, "xrCreateVulkanInstanceKHR")(instance, &xci, &vk_instance, &vr));
    ASSERT_EQ(vr, VK_SUCCESS);
    if (validate) {
      VkDebugUtilsMessengerCreateInfoEXT mci{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
      mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
      mci.pfnUserCallback = &on_message;
      mci.pUserData = this;
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(vk_instance, "vkCreateDebugUtilsMessengerEXT"));
      ASSERT_NE(create, nullptr);
      ASSERT_EQ(create(vk_instance, &mci, nullptr, &messenger), VK_SUCCESS);
    }
    XrVulkanGraphicsDeviceGetInfoKHR gi{XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR};
    gi.systemId = system;
    gi.vulkanInstance = vk_instance;
    XRRT_ASSERT_XR(
        proc<PFN_xrGetVulkanGraphicsDevice2KHR>(instance, "xrGetVulkanGraphicsDevice2KHR")(instance, &gi, &physical));
    std::uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> qs(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nq, qs.data());
    for (family = 0; family < nq && !(qs[family].queueFlags & VK_QUEUE_GRAPHICS_BIT);) ++family;
    ASSERT_LT(family, nq);
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    XrVulkanDeviceCreateInfoKHR xdi{XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR};
    xdi.systemId = system;
    xdi.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
    xdi.vulkanPhysicalDevice = physical;
    xdi.vulkanCreateInfo = &dci;
    XRRT_ASSERT_XR(
        proc<PFN_xrCreateVulkanDeviceKHR>(instance, "xrCreateVulkanDeviceKHR")(instance, &xdi, &device, &vr));
    ASSERT_EQ(vr, VK_SUCCESS);

    XrGraphicsBindingVulkan2KHR binding{XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR};
    binding.instance = vk_instance;
    binding.physicalDevice = physical;
    binding.device = device;
    binding.queueFamilyIndex = family;
    si.next = &binding;
    XRRT_ASSERT_XR(xrCreateSession(instance, &si, &session));
    drain_states(instance);
    XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
    bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    XRRT_ASSERT_XR(xrBeginSession(session, &bi));
  }

  void destroy() {
    if (session) xrDestroySession(session);
    if (instance) xrDestroyInstance(instance);
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) {
      auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(vk_instance, "vkDestroyDebugUtilsMessengerEXT"));
      destroy_messenger(vk_instance, messenger, nullptr);
    }
    if (vk_instance) vkDestroyInstance(vk_instance, nullptr);
  }
};

TEST(RuntimeVulkan, SwapchainsOfRealImagesOnLavapipe) {
  setenv("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json", 1);
  use_runtime(5.0);
  VulkanRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create_devices());
  std::uint32_t n = 0;
  ASSERT_EQ(xrEnumerateSwapchainFormats(rig.session, 0, &n, nullptr), XR_SUCCESS);
  ASSERT_GT(n, 0u);
  std::vector<int64_t> formats(n);
  ASSERT_EQ(xrEnumerateSwapchainFormats(rig.session, n, &n, formats.data()), XR_SUCCESS);
  XrSwapchainCreateInfo sci{XR_TYPE_SWAPCHAIN_CREATE_INFO};
  sci.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
  sci.format = 12345;  // not a format the runtime offers
  sci.sampleCount = 1;
  sci.width = 64;
  sci.height = 48;
  sci.faceCount = 1;
  sci.arraySize = 1;
  sci.mipCount = 1;
  XrSwapchain sc = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateSwapchain(rig.session, &sci, &sc), XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
  sci.format = formats[0];
  ASSERT_EQ(xrCreateSwapchain(rig.session, &sci, &sc), XR_SUCCESS);
  ASSERT_EQ(xrEnumerateSwapchainImages(sc, 0, &n, nullptr), XR_SUCCESS);
  ASSERT_GE(n, 2u);
  std::vector<XrSwapchainImageVulkan2KHR> images(n, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
  ASSERT_EQ(xrEnumerateSwapchainImages(sc, n, &n, reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
            XR_SUCCESS);
  for (const auto& img : images) EXPECT_NE(img.image, VK_NULL_HANDLE);
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(rig.device, images[0].image, &req);  // a real image on our device
  EXPECT_GE(req.size, 64u * 48u * 4u);

  XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
  wait.timeout = XR_INFINITE_DURATION;
  EXPECT_EQ(xrWaitSwapchainImage(sc, &wait), XR_ERROR_CALL_ORDER_INVALID);
  EXPECT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_ERROR_CALL_ORDER_INVALID);

  XrFrameState fs{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(rig.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(rig.session, nullptr), XR_SUCCESS);
  XrReferenceSpaceCreateInfo rs{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  rs.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  rs.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace local = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateReferenceSpace(rig.session, &rs, &local), XR_SUCCESS);
  XrCompositionLayerProjectionView views[2] = {{XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW},
                                               {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW}};
  for (auto& v : views) {
    v.pose.orientation.w = 1.0f;
    v.subImage.swapchain = sc;
    v.subImage.imageRect = {{0, 0}, {64, 48}};
  }
  XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  layer.space = local;
  layer.viewCount = 2;
  layer.views = views;
  const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<XrCompositionLayerBaseHeader*>(&layer)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = fs.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.layerCount = 1;
  end.layers = layers;
  EXPECT_EQ(xrEndFrame(rig.session, &end), XR_ERROR_LAYER_INVALID);  // no image released yet

  std::uint32_t index = 99;
  ASSERT_EQ(xrAcquireSwapchainImage(sc, nullptr, &index), XR_SUCCESS);
  EXPECT_LT(index, n);
  EXPECT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_ERROR_CALL_ORDER_INVALID);  // not waited
  ASSERT_EQ(xrWaitSwapchainImage(sc, &wait), XR_SUCCESS);
  EXPECT_EQ(xrWaitSwapchainImage(sc, &wait), XR_ERROR_CALL_ORDER_INVALID);
  ASSERT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_SUCCESS);
  views[1].subImage.imageRect = {{8, 0}, {64, 48}};
  EXPECT_EQ(xrEndFrame(rig.session, &end), XR_ERROR_SWAPCHAIN_RECT_INVALID);
  views[1].subImage.imageRect = {{0, 0}, {64, 48}};
  EXPECT_EQ(xrEndFrame(rig.session, &end), XR_SUCCESS);
  // Every image can be held at once, one more cannot.
  for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(xrAcquireSwapchainImage(sc, nullptr, &index), XR_SUCCESS);
  EXPECT_EQ(xrAcquireSwapchainImage(sc, nullptr, &index), XR_ERROR_CALL_ORDER_INVALID);
  EXPECT_EQ(xrDestroySwapchain(sc), XR_SUCCESS);
  EXPECT_EQ(xrDestroySwapchain(sc), XR_ERROR_HANDLE_INVALID);
  rig.destroy();
}

// Records and runs, on the application's queue, a barrier that says `image` is in `layout`: the
// validation layer checks that claim against the layout it has tracked for the image.
void claim_layout(const VulkanRig& rig, VkImage image, VkImageLayout layout, VkImageAspectFlags aspect) {
  VkQueue queue = VK_NULL_HANDLE;
  vkGetDeviceQueue(rig.device, rig.family, 0, &queue);
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.queueFamilyIndex = rig.family;
  VkCommandPool pool = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateCommandPool(rig.device, &pci, nullptr, &pool), VK_SUCCESS);
  VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cai.commandPool = pool;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  ASSERT_EQ(vkAllocateCommandBuffers(rig.device, &cai, &cmd), VK_SUCCESS);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  vkBeginCommandBuffer(cmd, &begin);
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.oldLayout = b.newLayout = layout;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &b);
  vkEndCommandBuffer(cmd);
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  EXPECT_EQ(vkQueueSubmit(queue, 1, &submit, VK_NULL_HANDLE), VK_SUCCESS);
  EXPECT_EQ(vkQueueWaitIdle(queue), VK_SUCCESS);
  vkDestroyCommandPool(rig.device, pool, nullptr);
}

// An image the device cannot make (storage use of an sRGB format on lavapipe, too many array
// layers) is refused with XR_ERROR_FEATURE_UNSUPPORTED, never created: creating it is undefined
// behaviour in Vulkan, and the conformance suite crashed on it now and then. The layout change
// each image gets at its first acquire passes the validation layer too.
TEST(RuntimeVulkan, ImagesTheDeviceCannotMakeAreRefusedNotCreated) {
  setenv("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json", 1);
  if (!VulkanRig::has_validation_layer()) {
    GAZELOD_SKIP_OR_FAIL("no VK_LAYER_KHRONOS_validation (Debian's vulkan-validationlayers)");
  }
  use_runtime(5.0);
  VulkanRig rig;
  rig.validate = true;
  ASSERT_NO_FATAL_FAILURE(rig.create_devices());
  std::uint32_t n = 0;
  ASSERT_EQ(xrEnumerateSwapchainFormats(rig.session, 0, &n, nullptr), XR_SUCCESS);
  std::vector<int64_t> formats(n);
  ASSERT_EQ(xrEnumerateSwapchainFormats(rig.session, n, &n, formats.data()), XR_SUCCESS);
  int refused = 0, created = 0;
  for (int64_t format : formats) {
    const auto vk_format = static_cast<VkFormat>(format);
    const bool depth = vk_format == VK_FORMAT_D32_SFLOAT || vk_format == VK_FORMAT_D16_UNORM ||
                       vk_format == VK_FORMAT_D24_UNORM_S8_UINT || vk_format == VK_FORMAT_D32_SFLOAT_S8_UINT;
    XrSwapchainCreateInfo sci{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    sci.usageFlags =
        (depth ? XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT) |
        XR_SWAPCHAIN_USAGE_UNORDERED_ACCESS_BIT;
    sci.format = format;
    sci.sampleCount = 1;
    sci.width = 32;
    sci.height = 32;
    sci.faceCount = 1;
    sci.arraySize = 2;
    sci.mipCount = 1;
    // What the device says of the image the runtime would create (it adds transfer-source use).
    const VkImageUsageFlags usage =
        (depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) |
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VkImageFormatProperties props{};
    const bool can = vkGetPhysicalDeviceImageFormatProperties(rig.physical, vk_format, VK_IMAGE_TYPE_2D,
                                                              VK_IMAGE_TILING_OPTIMAL, usage, 0, &props) == VK_SUCCESS;
    XrSwapchain sc = XR_NULL_HANDLE;
    const XrResult r = xrCreateSwapchain(rig.session, &sci, &sc);
    EXPECT_EQ(r, can ? XR_SUCCESS : XR_ERROR_FEATURE_UNSUPPORTED) << "format " << format;
    if (r != XR_SUCCESS) {
      ++refused;
      continue;
    }
    ++created;
    std::uint32_t count = 0, index = 0;
    ASSERT_EQ(xrEnumerateSwapchainImages(sc, 0, &count, nullptr), XR_SUCCESS);
    std::vector<XrSwapchainImageVulkan2KHR> images(count, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
    ASSERT_EQ(
        xrEnumerateSwapchainImages(sc, count, &count, reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
        XR_SUCCESS);
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    for (std::uint32_t i = 0; i < count; ++i) {
      ASSERT_EQ(xrAcquireSwapchainImage(sc, nullptr, &index), XR_SUCCESS);
      ASSERT_EQ(xrWaitSwapchainImage(sc, &wait), XR_SUCCESS);
      // The specification's promise once the wait returns: the attachment layout.
      const VkImageAspectFlags aspect =
          !depth ? VK_IMAGE_ASPECT_COLOR_BIT
                 : VK_IMAGE_ASPECT_DEPTH_BIT |
                       (vk_format == VK_FORMAT_D24_UNORM_S8_UINT || vk_format == VK_FORMAT_D32_SFLOAT_S8_UINT
                            ? VK_IMAGE_ASPECT_STENCIL_BIT
                            : 0);
      ASSERT_NO_FATAL_FAILURE(claim_layout(
          rig, images[index].image,
          depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, aspect));
      ASSERT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_SUCCESS);
    }
    // Past the device's array-layer limit, or so many that arraySize x 6 faces wraps in 32 bits:
    // refused as well. A cube with unequal sides and more mip levels than 32 x 32 has (6) are no
    // image at all.
    XrSwapchain refused_sc = XR_NULL_HANDLE;
    XrSwapchainCreateInfo bad = sci;
    bad.arraySize = props.maxArrayLayers + 1;
    EXPECT_EQ(xrCreateSwapchain(rig.session, &bad, &refused_sc), XR_ERROR_FEATURE_UNSUPPORTED);
    bad = sci;
    bad.faceCount = 6;
    bad.arraySize = 0x2AAAAAABu;  // x 6 = 2^32 + 2
    EXPECT_EQ(xrCreateSwapchain(rig.session, &bad, &refused_sc), XR_ERROR_FEATURE_UNSUPPORTED);
    bad = sci;
    bad.faceCount = 6;
    bad.height = 16;
    EXPECT_EQ(xrCreateSwapchain(rig.session, &bad, &refused_sc), XR_ERROR_VALIDATION_FAILURE);
    bad = sci;
    bad.mipCount = 7;
    EXPECT_EQ(xrCreateSwapchain(rig.session, &bad, &refused_sc), XR_ERROR_VALIDATION_FAILURE);
    bad.mipCount = 6;  // the full chain of 32 x 32
    ASSERT_EQ(xrCreateSwapchain(rig.session, &bad, &refused_sc), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(refused_sc), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(sc), XR_SUCCESS);
  }
  // Both branches ran: lavapipe has formats with storage use (UNORM) and without (sRGB).
  EXPECT_GT(refused, 0);
  EXPECT_GT(created, 0);
  rig.destroy();  // the layer reports what was left alive when the device goes
  for (const std::string& e : rig.validation_errors) ADD_FAILURE() << "Vulkan validation: " << e;
}

// xrRequestExitSession before the first xrWaitFrame: STOPPING follows only SYNCHRONIZED
// (section 9.3), so the session passes through it; then IDLE and EXITING after xrEndSession.
TEST(RuntimeVulkan, EarlyExitRequestPassesThroughSynchronized) {
  setenv("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json", 1);
  use_runtime(5.0);
  VulkanRig rig;
  ASSERT_NO_FATAL_FAILURE(rig.create_devices());  // begun, READY, no frame yet
  ASSERT_EQ(xrRequestExitSession(rig.session), XR_SUCCESS);
  EXPECT_EQ(drain_states(rig.instance),
            (std::vector<XrSessionState>{XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_STOPPING}));
  ASSERT_EQ(xrEndSession(rig.session), XR_SUCCESS);
  EXPECT_EQ(drain_states(rig.instance), (std::vector<XrSessionState>{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
  rig.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
