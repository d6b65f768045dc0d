// SPDX-License-Identifier: Apache-2.0
#include "render/offscreen_target.hpp"

#include "render/render_error.hpp"

#include <string>

namespace gazelod::render {

OffscreenTarget::OffscreenTarget(const DeviceContext& ctx, std::uint32_t width, std::uint32_t height,
                                 std::uint32_t image_count, VkFormat format) {
  constexpr std::uint32_t kMaxSide = 16384;
  if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide || image_count == 0)
    throw RenderError("offscreen target: bad size " + std::to_string(width) + "x" + std::to_string(height) + " x" +
                      std::to_string(image_count) + " (each side 1.." + std::to_string(kMaxSide) + ")");
  target_.format = format;
  target_.width = width;
  target_.height = height;
  for (std::uint32_t i = 0; i < image_count; ++i) {
    images_.emplace_back(ctx, width, height, format,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT);
    target_.images.push_back(images_.back().image());
  }
}

}  // namespace gazelod::render
