// SPDX-License-Identifier: Apache-2.0
// Colour images the renderer can draw into without a swapchain (tests, benchmarks,
// `gazelod bake`): R8G8B8A8_UNORM, usable as colour attachment and transfer source.
#pragma once

#include "render/device_context.hpp"
#include "render/frame_renderer.hpp"
#include "render/gpu_memory.hpp"

#include <cstdint>
#include <vector>

namespace gazelod::render {

class OffscreenTarget {
 public:
  // Throws RenderError (sizes of 0 or above 16384 pixels included).
  OffscreenTarget(const DeviceContext& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t image_count = 1,
                  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM);

  // What a FrameRenderer draws into; valid while this object lives.
  const RenderTarget& target() const { return target_; }

 private:
  std::vector<DeviceImage> images_;
  RenderTarget target_;
};

}  // namespace gazelod::render
