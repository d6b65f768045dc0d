// SPDX-License-Identifier: Apache-2.0
#include "apps/xr_host/xr_app.hpp"

#include "plugin/xr_check.hpp"
#include "render/vulkan12_features.hpp"
#include "sim/runtime/simulator_state_ext.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

namespace gazelod::xr_host {
namespace {

void check(XrInstance, XrResult r, const char* call) {
  xr_check(r, call);
}

template <typename Fn>
Fn proc(XrInstance instance, const char* name) {
  PFN_xrVoidFunction f = nullptr;
  check(instance, xrGetInstanceProcAddr(instance, name, &f), name);
  return reinterpret_cast<Fn>(f);
}

}  // namespace

XrApp::XrApp(bool want_eye_gaze) {
  create_instance(want_eye_gaze);
  create_vulkan();
  create_session();
  create_swapchains();
}

XrApp::~XrApp() {
  for (auto& s : swapchains_)
    if (s.handle != XR_NULL_HANDLE) xrDestroySwapchain(s.handle);
  if (local_space_ != XR_NULL_HANDLE) xrDestroySpace(local_space_);
  if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
  // The device and instance were created through the runtime, but are the application's
  // to destroy (XR_KHR_vulkan_enable2).
  if (vk_device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(vk_device_);
    vkDestroyDevice(vk_device_, nullptr);
  }
  if (vk_instance_ != VK_NULL_HANDLE) vkDestroyInstance(vk_instance_, nullptr);
  if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
}

void XrApp::create_instance(bool want_eye_gaze) {
  std::uint32_t count = 0;
  const XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
  if (XR_FAILED(r))
    throw XrAppError("no OpenXR runtime: xrEnumerateInstanceExtensionProperties failed (" + xr_result_name(r) +
                     "); is XR_RUNTIME_JSON or an active runtime set?");
  std::vector<XrExtensionProperties> props(count, {XR_TYPE_EXTENSION_PROPERTIES});
  check(XR_NULL_HANDLE, xrEnumerateInstanceExtensionProperties(nullptr, count, &count, props.data()),
        "xrEnumerateInstanceExtensionProperties");
  auto has = [&](const char* name) {
    return std::any_of(props.begin(), props.end(),
                       [&](const XrExtensionProperties& p) { return std::strcmp(p.extensionName, name) == 0; });
  };
  if (!has(XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME))
    throw XrAppError("the OpenXR runtime does not offer XR_KHR_vulkan_enable2");
  std::vector<const char*> exts{XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME};
  eye_gaze_enabled_ = want_eye_gaze && has(XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
  if (eye_gaze_enabled_) exts.push_back(XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
  timespec_enabled_ = has(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
  if (timespec_enabled_) exts.push_back(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
  simulator_state_enabled_ = has(XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME);
  if (simulator_state_enabled_) exts.push_back(XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME);

  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strncpy(info.applicationInfo.applicationName, "gazelod run", XR_MAX_APPLICATION_NAME_SIZE - 1);
  std::strncpy(info.applicationInfo.engineName, "gazelod", XR_MAX_ENGINE_NAME_SIZE - 1);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = static_cast<std::uint32_t>(exts.size());
  info.enabledExtensionNames = exts.data();
  check(XR_NULL_HANDLE, xrCreateInstance(&info, &instance_), "xrCreateInstance");

  XrInstanceProperties ip{XR_TYPE_INSTANCE_PROPERTIES};
  check(instance_, xrGetInstanceProperties(instance_, &ip), "xrGetInstanceProperties");
  runtime_name_ = ip.runtimeName;

  XrSystemGetInfo sys{XR_TYPE_SYSTEM_GET_INFO};
  sys.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  check(instance_, xrGetSystem(instance_, &sys, &system_), "xrGetSystem");
  XrSystemProperties sp{XR_TYPE_SYSTEM_PROPERTIES};
  check(instance_, xrGetSystemProperties(instance_, system_, &sp), "xrGetSystemProperties");
  system_name_ = sp.systemName;
}

void XrApp::create_vulkan() {
  auto get_requirements =
      proc<PFN_xrGetVulkanGraphicsRequirements2KHR>(instance_, "xrGetVulkanGraphicsRequirements2KHR");
  auto create_instance = proc<PFN_xrCreateVulkanInstanceKHR>(instance_, "xrCreateVulkanInstanceKHR");
  auto get_device = proc<PFN_xrGetVulkanGraphicsDevice2KHR>(instance_, "xrGetVulkanGraphicsDevice2KHR");
  auto create_device = proc<PFN_xrCreateVulkanDeviceKHR>(instance_, "xrCreateVulkanDeviceKHR");

  XrGraphicsRequirementsVulkan2KHR req{XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR};
  check(instance_, get_requirements(instance_, system_, &req), "xrGetVulkanGraphicsRequirements2KHR");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "gazelod run";
  // 1.2 where the loader has it: drawIndirectCount draws a GPU-selected cut (render/).
  std::uint32_t loader_version = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS) loader_version = VK_API_VERSION_1_0;
  const bool runtime_allows_12 = req.maxApiVersionSupported >= XR_MAKE_VERSION(1, 2, 0);
  app.apiVersion = loader_version >= VK_API_VERSION_1_2 && runtime_allows_12 ? VK_API_VERSION_1_2 : VK_API_VERSION_1_1;
  VkInstanceCreateInfo vci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  vci.pApplicationInfo = &app;
  XrVulkanInstanceCreateInfoKHR xci{XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR};
  xci.systemId = system_;
  xci.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
  xci.vulkanCreateInfo = &vci;
  VkResult vr = VK_SUCCESS;
  check(instance_, create_instance(instance_, &xci, &vk_instance_, &vr), "xrCreateVulkanInstanceKHR");
  if (vr != VK_SUCCESS)
    throw XrAppError("no Vulkan: vkCreateInstance failed (VkResult " + std::to_string(vr) +
                     "); install mesa-vulkan-drivers for lavapipe");

  XrVulkanGraphicsDeviceGetInfoKHR gi{XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR};
  gi.systemId = system_;
  gi.vulkanInstance = vk_instance_;
  check(instance_, get_device(instance_, &gi, &vk_physical_), "xrGetVulkanGraphicsDevice2KHR");
  if (vk_physical_ == VK_NULL_HANDLE) throw XrAppError("no Vulkan device: the runtime chose none");
  VkPhysicalDeviceProperties pp{};
  vkGetPhysicalDeviceProperties(vk_physical_, &pp);
  vk_device_name_ = pp.deviceName;

  std::uint32_t nq = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(vk_physical_, &nq, nullptr);
  std::vector<VkQueueFamilyProperties> families(nq);
  vkGetPhysicalDeviceQueueFamilyProperties(vk_physical_, &nq, families.data());
  bool found = false;
  for (std::uint32_t i = 0; i < nq && !found; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      queue_family_ = i;
      found = true;
    }
  if (!found) throw XrAppError("no Vulkan device: " + vk_device_name_ + " has no graphics queue");

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = queue_family_;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  // multiDrawIndirect where the device has it: a cluster cut goes out as one indirect draw
  // per tint (render/frame_renderer.hpp) instead of a draw per run of clusters.
  VkPhysicalDeviceFeatures supported{}, enabled{};
  vkGetPhysicalDeviceFeatures(vk_physical_, &supported);
  enabled.multiDrawIndirect = supported.multiDrawIndirect;
  multi_draw_indirect_ = supported.multiDrawIndirect == VK_TRUE;
  // And Vulkan 1.2's drawIndirectCount where instance and device have 1.2: the cut a compute
  // pass selected is drawn with one vkCmdDrawIndexedIndirectCount (gazelod run --cluster-select gpu).
  render::Vulkan12Features features12 = render::vulkan12_features_to_enable(vk_physical_, app.apiVersion);
  draw_indirect_count_ = features12.enabled.drawIndirectCount == VK_TRUE;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.pNext = features12.has_vulkan_12 ? &features12.enabled : nullptr;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.pEnabledFeatures = &enabled;
  XrVulkanDeviceCreateInfoKHR xdi{XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR};
  xdi.systemId = system_;
  xdi.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
  xdi.vulkanPhysicalDevice = vk_physical_;
  xdi.vulkanCreateInfo = &dci;
  check(instance_, create_device(instance_, &xdi, &vk_device_, &vr), "xrCreateVulkanDeviceKHR");
  if (vr != VK_SUCCESS) throw XrAppError("vkCreateDevice failed (VkResult " + std::to_string(vr) + ")");
  vkGetDeviceQueue(vk_device_, queue_family_, 0, &queue_);
}

void XrApp::create_session() {
  XrGraphicsBindingVulkan2KHR binding{XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR};
  binding.instance = vk_instance_;
  binding.physicalDevice = vk_physical_;
  binding.device = vk_device_;
  binding.queueFamilyIndex = queue_family_;
  binding.queueIndex = 0;
  XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
  info.next = &binding;
  info.systemId = system_;
  check(instance_, xrCreateSession(instance_, &info, &session_), "xrCreateSession");

  XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  space.poseInReferenceSpace.orientation.w = 1.0f;
  check(instance_, xrCreateReferenceSpace(session_, &space, &local_space_), "xrCreateReferenceSpace(LOCAL)");
}

void XrApp::create_swapchains() {
  std::uint32_t n = 0;
  const auto stereo = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  check(instance_, xrEnumerateViewConfigurationViews(instance_, system_, stereo, 0, &n, nullptr),
        "xrEnumerateViewConfigurationViews");
  config_views_.assign(n, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
  check(instance_, xrEnumerateViewConfigurationViews(instance_, system_, stereo, n, &n, config_views_.data()),
        "xrEnumerateViewConfigurationViews");

  std::uint32_t nf = 0;
  check(instance_, xrEnumerateSwapchainFormats(session_, 0, &nf, nullptr), "xrEnumerateSwapchainFormats");
  std::vector<std::int64_t> formats(nf);
  check(instance_, xrEnumerateSwapchainFormats(session_, nf, &nf, formats.data()), "xrEnumerateSwapchainFormats");
  // sRGB formats first: the renderer writes linear colour.
  const std::array<std::int64_t, 4> preferred{VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB,
                                              VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM};
  std::int64_t format = 0;
  for (std::int64_t f : preferred)
    if (std::find(formats.begin(), formats.end(), f) != formats.end()) {
      format = f;
      break;
    }
  if (format == 0) throw XrAppError("the runtime offers no 8-bit RGBA swapchain format");

  for (const XrViewConfigurationView& cv : config_views_) {
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_SRC_BIT;
    info.format = format;
    info.sampleCount = 1;
    info.width = cv.recommendedImageRectWidth;
    info.height = cv.recommendedImageRectHeight;
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    XrSwapchainView sv;
    check(instance_, xrCreateSwapchain(session_, &info, &sv.handle), "xrCreateSwapchain");
    sv.width = static_cast<std::int32_t>(info.width);
    sv.height = static_cast<std::int32_t>(info.height);
    sv.format = format;
    std::uint32_t ni = 0;
    check(instance_, xrEnumerateSwapchainImages(sv.handle, 0, &ni, nullptr), "xrEnumerateSwapchainImages");
    std::vector<XrSwapchainImageVulkan2KHR> images(ni, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
    check(instance_,
          xrEnumerateSwapchainImages(sv.handle, ni, &ni, reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
          "xrEnumerateSwapchainImages");
    for (const auto& im : images) sv.images.push_back(im.image);
    swapchains_.push_back(std::move(sv));
  }
  projection_views_.assign(swapchains_.size(), {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW});
}

XrTime XrApp::now() const {
  if (!timespec_enabled_) return 0;
  if (!to_xr_time_) {
    PFN_xrVoidFunction f = nullptr;
    if (XR_FAILED(xrGetInstanceProcAddr(instance_, "xrConvertTimespecTimeToTimeKHR", &f)) || !f) return 0;
    to_xr_time_ = reinterpret_cast<void (*)()>(f);
  }
  timespec ts{};
  if (::clock_gettime(CLOCK_MONOTONIC, &ts) != 0) return 0;
  XrTime t = 0;
  const auto convert = reinterpret_cast<PFN_xrConvertTimespecTimeToTimeKHR>(to_xr_time_);
  return XR_SUCCEEDED(convert(instance_, &ts, &t)) ? t : 0;
}

XrTime XrApp::scenario_time_base() const {
  if (!simulator_state_enabled_) return 0;
  PFN_xrVoidFunction f = nullptr;
  if (XR_FAILED(xrGetInstanceProcAddr(instance_, "xrGetSimulatorStateGAZELOD", &f)) || !f) return 0;
  XrSimulatorStateGAZELOD state{};
  if (XR_FAILED(reinterpret_cast<PFN_xrGetSimulatorStateGAZELOD>(f)(session_, &state))) return 0;
  return state.scenarioTimeBase;
}

bool XrApp::poll_events(const std::function<void(XrSessionState, XrTime)>& on_state) {
  for (;;) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    const XrResult r = xrPollEvent(instance_, &event);
    if (r == XR_EVENT_UNAVAILABLE) return true;
    check(instance_, r, "xrPollEvent");
    switch (event.type) {
      case XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING:
        return false;
      case XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED: {
        const auto& e = *reinterpret_cast<const XrEventDataSessionStateChanged*>(&event);
        state_ = e.state;
        if (on_state) on_state(e.state, e.time);
        if (e.state == XR_SESSION_STATE_READY) {
          XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
          begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
          check(instance_, xrBeginSession(session_, &begin), "xrBeginSession");
          session_running_ = true;
        } else if (e.state == XR_SESSION_STATE_STOPPING) {
          check(instance_, xrEndSession(session_), "xrEndSession");
          session_running_ = false;
        } else if (e.state == XR_SESSION_STATE_EXITING || e.state == XR_SESSION_STATE_LOSS_PENDING) {
          session_running_ = false;
          return false;
        }
        break;
      }
      default:
        break;
    }
  }
}

XrFrameState XrApp::wait_frame() {
  XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO};
  XrFrameState state{XR_TYPE_FRAME_STATE};
  check(instance_, xrWaitFrame(session_, &wait, &state), "xrWaitFrame");
  return state;
}

void XrApp::begin_frame() {
  XrFrameBeginInfo begin{XR_TYPE_FRAME_BEGIN_INFO};
  check(instance_, xrBeginFrame(session_, &begin), "xrBeginFrame");
}

bool XrApp::locate_views(XrTime time, std::vector<XrView>& views) {
  XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO};
  info.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  info.displayTime = time;
  info.space = local_space_;
  XrViewState vs{XR_TYPE_VIEW_STATE};
  std::uint32_t n = static_cast<std::uint32_t>(swapchains_.size());
  views.assign(n, {XR_TYPE_VIEW});
  check(instance_, xrLocateViews(session_, &info, &vs, n, &n, views.data()), "xrLocateViews");
  const XrViewStateFlags need = XR_VIEW_STATE_POSITION_VALID_BIT | XR_VIEW_STATE_ORIENTATION_VALID_BIT;
  return (vs.viewStateFlags & need) == need;
}

std::uint32_t XrApp::acquire(std::size_t view) {
  XrSwapchainImageAcquireInfo acq{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
  std::uint32_t index = 0;
  check(instance_, xrAcquireSwapchainImage(swapchains_[view].handle, &acq, &index), "xrAcquireSwapchainImage");
  XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
  wait.timeout = XR_INFINITE_DURATION;
  check(instance_, xrWaitSwapchainImage(swapchains_[view].handle, &wait), "xrWaitSwapchainImage");
  return index;
}

void XrApp::release(std::size_t view) {
  XrSwapchainImageReleaseInfo rel{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
  check(instance_, xrReleaseSwapchainImage(swapchains_[view].handle, &rel), "xrReleaseSwapchainImage");
}

void XrApp::end_frame(XrTime display_time, const std::vector<XrView>& views) {
  XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  const XrCompositionLayerBaseHeader* layers[1] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = display_time;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  if (!views.empty() && views.size() == swapchains_.size()) {
    for (std::size_t i = 0; i < views.size(); ++i) {
      auto& pv = projection_views_[i];
      pv = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
      pv.pose = views[i].pose;
      pv.fov = views[i].fov;
      pv.subImage.swapchain = swapchains_[i].handle;
      pv.subImage.imageRect.extent = {swapchains_[i].width, swapchains_[i].height};
    }
    layer.space = local_space_;
    layer.viewCount = static_cast<std::uint32_t>(projection_views_.size());
    layer.views = projection_views_.data();
    end.layerCount = 1;
    end.layers = layers;
  }
  check(instance_, xrEndFrame(session_, &end), "xrEndFrame");
}

}  // namespace gazelod::xr_host
