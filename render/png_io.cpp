// SPDX-License-Identifier: Apache-2.0
#include "render/png_io.hpp"

#include "render/render_error.hpp"

#include <png.h>

#include <cstring>
#include <string>
#include <vector>

namespace gazelod::render {

namespace {

void check_image(const std::string& what, const RgbaImage& image) {
  if (image.width == 0 || image.height == 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4u)
    throw RenderError(what + ": cannot write an empty or inconsistent image (" + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + ", " + std::to_string(image.pixels.size()) + " bytes)");
}

}  // namespace

std::vector<unsigned char> encode_png(const RgbaImage& image) {
  check_image("PNG", image);
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = image.width;
  png.height = image.height;
  png.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;  // first the size, then the bytes
  if (png_image_write_to_memory(&png, nullptr, &size, 0, image.pixels.data(), 0, nullptr)) {
    std::vector<unsigned char> bytes(size);
    if (png_image_write_to_memory(&png, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr)) {
      bytes.resize(size);
      return bytes;
    }
  }
  const std::string why = png.message;
  png_image_free(&png);
  throw RenderError("cannot encode PNG: " + why);
}

void write_png(const std::filesystem::path& file, const RgbaImage& image) {
  check_image(file.string(), image);
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = image.width;
  png.height = image.height;
  png.format = PNG_FORMAT_RGBA;
  if (!png_image_write_to_file(&png, file.c_str(), 0, image.pixels.data(), 0, nullptr)) {
    const std::string why = png.message;
    png_image_free(&png);
    throw RenderError(file.string() + ": cannot write PNG: " + why);
  }
}

RgbaImage read_png(const std::filesystem::path& file) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, file.c_str())) {
    const std::string why = png.message;
    png_image_free(&png);
    throw RenderError(file.string() + ": cannot read PNG: " + why);
  }
  png.format = PNG_FORMAT_RGBA;
  RgbaImage image;
  image.width = png.width;
  image.height = png.height;
  image.pixels.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
    const std::string why = png.message;
    png_image_free(&png);
    throw RenderError(file.string() + ": cannot decode PNG: " + why);
  }
  return image;
}

}  // namespace gazelod::render
