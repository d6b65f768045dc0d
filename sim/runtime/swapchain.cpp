// SPDX-License-Identifier: Apache-2.0
// Swapchains (OpenXR 1.0 section 10.1): formats, creation on the application's VkDevice, and
// the acquire -> wait -> release cycle with its XR_ERROR_CALL_ORDER_INVALID rules. A headless
// session offers no format (XR_MND_headless).
#include "sim/runtime/entry_points.hpp"
#include "sim/runtime/system_info.hpp"
#include "sim/runtime/vulkan_images.hpp"

#include <algorithm>

namespace gazelod::xrrt {
namespace {

constexpr std::uint32_t kImagesPerSwapchain = 3;

}  // namespace

XrResult EnumerateSwapchainFormats(XrSession session, uint32_t capacity, uint32_t* count, int64_t* formats) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    return two_call(capacity, count, formats, vulkan_swapchain_formats(*s));
  });
}

XrResult CreateSwapchain(XrSession session, const XrSwapchainCreateInfo* info, XrSwapchain* swapchain) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Session* s = find_session(session);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || swapchain == nullptr || info->type != XR_TYPE_SWAPCHAIN_CREATE_INFO)
      return XR_ERROR_VALIDATION_FAILURE;
    if (info->createFlags & XR_SWAPCHAIN_CREATE_PROTECTED_CONTENT_BIT) return XR_ERROR_FEATURE_UNSUPPORTED;
    if (info->width == 0 || info->height == 0 || info->width > kMaxImageSize || info->height > kMaxImageSize ||
        info->sampleCount != 1 || info->arraySize == 0 || info->mipCount == 0 ||
        (info->faceCount != 1 && info->faceCount != 6))
      return XR_ERROR_VALIDATION_FAILURE;
    const std::vector<std::int64_t> formats = vulkan_swapchain_formats(*s);
    if (std::find(formats.begin(), formats.end(), info->format) == formats.end())
      return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    auto sc = std::make_unique<Swapchain>();
    sc->session_id = s->id;
    sc->info = *info;
    sc->info.next = nullptr;
    const bool is_static = info->createFlags & XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT;
    if (XrResult r = create_vulkan_images(*s, *sc, is_static ? 1 : kImagesPerSwapchain); r != XR_SUCCESS) return r;
    Runtime& rt = runtime();
    sc->id = rt.next_id++;
    *swapchain = to_handle<XrSwapchain>(sc->id);
    rt.swapchains.live.emplace(sc->id, std::move(sc));
    return XR_SUCCESS;
  });
}

XrResult DestroySwapchain(XrSwapchain swapchain) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    if (find_swapchain(swapchain) == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_swapchain(handle_id(swapchain));
    return XR_SUCCESS;
  });
}

XrResult EnumerateSwapchainImages(XrSwapchain swapchain, uint32_t capacity, uint32_t* count,
                                  XrSwapchainImageBaseHeader* images) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Swapchain* sc = find_swapchain(swapchain);
    if (sc == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const auto n = static_cast<std::uint32_t>(sc->images.size());
    *count = n;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
    if (images == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    auto* vk = reinterpret_cast<XrSwapchainImageVulkanKHR*>(images);
    for (std::uint32_t i = 0; i < n; ++i) {
      if (vk[i].type != XR_TYPE_SWAPCHAIN_IMAGE_VULKAN_KHR) return XR_ERROR_VALIDATION_FAILURE;
      vk[i].image = sc->images[i].image;
    }
    return XR_SUCCESS;
  });
}

XrResult AcquireSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageAcquireInfo* info, uint32_t* index) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Swapchain* sc = find_swapchain(swapchain);
    if (sc == nullptr) return XR_ERROR_HANDLE_INVALID;
    if ((info != nullptr && info->type != XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO) || index == nullptr)
      return XR_ERROR_VALIDATION_FAILURE;
    const bool is_static = sc->info.createFlags & XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT;
    if (is_static && sc->static_acquired) return XR_ERROR_CALL_ORDER_INVALID;
    if (sc->acquired.size() >= sc->images.size()) return XR_ERROR_CALL_ORDER_INVALID;
    const Session* s = runtime().sessions.find(sc->session_id);
    if (s == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (XrResult r = prepare_vulkan_image(*s, *sc, sc->next_index); r != XR_SUCCESS) return r;
    *index = sc->next_index;
    sc->acquired.push_back(sc->next_index);
    sc->next_index = (sc->next_index + 1) % static_cast<std::uint32_t>(sc->images.size());
    if (is_static) sc->static_acquired = true;
    return XR_SUCCESS;
  });
}

XrResult WaitSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageWaitInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Swapchain* sc = find_swapchain(swapchain);
    if (sc == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info == nullptr || info->type != XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (sc->acquired.empty() || sc->waited) return XR_ERROR_CALL_ORDER_INVALID;
    // The simulated compositor never holds an image: it is ready at once.
    sc->waited = true;
    return XR_SUCCESS;
  });
}

XrResult ReleaseSwapchainImage(XrSwapchain swapchain, const XrSwapchainImageReleaseInfo* info) {
  return guarded([&] {
    std::lock_guard lock(runtime_mutex());
    Swapchain* sc = find_swapchain(swapchain);
    if (sc == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (info != nullptr && info->type != XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO) return XR_ERROR_VALIDATION_FAILURE;
    if (sc->acquired.empty() || !sc->waited) return XR_ERROR_CALL_ORDER_INVALID;
    sc->acquired.pop_front();
    sc->waited = false;
    sc->released_once = true;
    return XR_SUCCESS;
  });
}

}  // namespace gazelod::xrrt
