// SPDX-License-Identifier: Apache-2.0
// PNG files of rendered frames (libpng's simplified API): screenshots from `gazelod run`
// and the tests' round trips.
#pragma once

#include "render/rgba_image.hpp"

#include <filesystem>
#include <vector>

namespace gazelod::render {

// Throws RenderError naming the file and libpng's reason (unwritable folder, ...).
void write_png(const std::filesystem::path& file, const RgbaImage& image);
// The PNG file's bytes, for callers that write files their own way (atomically: `gazelod run`).
std::vector<unsigned char> encode_png(const RgbaImage& image);

// Any PNG, converted to 8-bit RGBA. Throws RenderError naming the file and the reason.
RgbaImage read_png(const std::filesystem::path& file);

}  // namespace gazelod::render
