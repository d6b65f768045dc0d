// SPDX-License-Identifier: Apache-2.0
// A colour key for the screenshots `gazelod run` saves (frame.png): a strip under the frame
// with one swatch per level tint (lod_palette.hpp), labelled L0 (full detail) to L7 (and
// deeper), so a reader can tell the levels apart without the source. The frame's own pixels
// are unchanged; readers that analyse the frame take the strip off with without_lod_key.
#pragma once

#include "render/rgba_image.hpp"

#include <cstdint>

namespace gazelod::render {

// The key grows with the frame (one key pixel per 600 frame pixels of width, 1 to 4), so it
// reads at the same size on a phone-sized frame and an 1800-pixel eye.
inline std::uint32_t lod_key_scale(std::uint32_t frame_width_px) {
  const std::uint32_t s = frame_width_px / 600u;
  return s < 1u ? 1u : (s > 4u ? 4u : s);
}
inline std::uint32_t lod_key_height_px(std::uint32_t frame_width_px) {
  return 24u * lod_key_scale(frame_width_px);
}

// The frame with the key strip under it: swatches for levels 0 .. levels - 1 (at most the
// palette's eight; the last reads "L7+" when deeper levels share its tint). A frame narrower
// than the key gets as many swatches as fit.
RgbaImage with_lod_key(const RgbaImage& frame, std::uint32_t levels);

// The frame without its key strip (an image shorter than the strip is returned as it is).
RgbaImage without_lod_key(const RgbaImage& image);

}  // namespace gazelod::render
