// SPDX-License-Identifier: Apache-2.0
// Swapchain images as real VkImages on the application's VkDevice (XR_KHR_vulkan_enable2
// "Swapchain Images"): allocated and bound at xrCreateSwapchain, moved to the attachment layout
// the specification promises at their first xrAcquireSwapchainImage, one of the four functions
// in which a runtime may use the application's VkQueue (XR_KHR_vulkan_enable "Concurrency").
#pragma once

#include "sim/runtime/runtime_state.hpp"

#include <vector>

namespace gazelod::xrrt {

// Formats the session's physical device can render to (colour first, in preference order).
std::vector<std::int64_t> vulkan_swapchain_formats(const Session& session);
// Creates `count` images for the swapchain's create info. XR_ERROR_VALIDATION_FAILURE for an
// image no device can make (a cube with unequal sides, more mip levels than the full chain);
// XR_ERROR_FEATURE_UNSUPPORTED when this device cannot (a usage the format does not allow, a
// limit passed); XR_ERROR_RUNTIME_FAILURE (with a message on stderr) when Vulkan refuses.
XrResult create_vulkan_images(const Session& session, Swapchain& swapchain, std::uint32_t count);
// Moves image `index` to its attachment layout the first time it is acquired (queue work, so
// only from xrAcquireSwapchainImage).
XrResult prepare_vulkan_image(const Session& session, Swapchain& swapchain, std::uint32_t index);
void destroy_vulkan_images(const Session& session, Swapchain& swapchain);

}  // namespace gazelod::xrrt
