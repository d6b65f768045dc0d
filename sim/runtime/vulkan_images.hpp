// SPDX-License-Identifier: Apache-2.0
// Swapchain images as real VkImages on the application's VkDevice (XR_KHR_vulkan_enable2
// "Swapchain Images"): allocated, bound and moved to the attachment layout the specification
// promises at acquire time.
#pragma once

#include "sim/runtime/runtime_state.hpp"

#include <vector>

namespace gazelod::xrrt {

// Formats the session's physical device can render to (colour first, in preference order).
std::vector<std::int64_t> vulkan_swapchain_formats(const Session& session);
// Creates `count` images for the swapchain's create info; XR_ERROR_RUNTIME_FAILURE (with a
// message on stderr) when Vulkan refuses.
XrResult create_vulkan_images(const Session& session, Swapchain& swapchain, std::uint32_t count);
void destroy_vulkan_images(const Session& session, Swapchain& swapchain);

}  // namespace gazelod::xrrt
