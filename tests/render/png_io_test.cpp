// SPDX-License-Identifier: Apache-2.0
// PNG round trip and errors that name the file.
#include "render/png_io.hpp"
#include "render/render_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace gazelod::render {
namespace {

std::filesystem::path temp_dir() {
  auto dir = std::filesystem::temp_directory_path() /
             ("gazelod_png_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(PngIo, RoundTripKeepsEveryByte) {
  RgbaImage img;
  img.width = 3;
  img.height = 2;
  for (int i = 0; i < 24; ++i) img.pixels.push_back(static_cast<std::uint8_t>(i * 11));
  const auto file = temp_dir() / "round.png";
  write_png(file, img);
  const RgbaImage back = read_png(file);
  EXPECT_EQ(back.width, 3u);
  EXPECT_EQ(back.height, 2u);
  EXPECT_EQ(back.pixels, img.pixels);
  std::filesystem::remove_all(file.parent_path());
}

// encode_png gives the same file write_png writes (`gazelod run` writes those bytes atomically).
TEST(PngIo, EncodedBytesAreTheFile) {
  RgbaImage img;
  img.width = 4;
  img.height = 3;
  for (int i = 0; i < 48; ++i) img.pixels.push_back(static_cast<std::uint8_t>(i * 5));
  const auto dir = temp_dir();
  write_png(dir / "written.png", img);
  const std::vector<unsigned char> bytes = encode_png(img);
  std::ifstream in(dir / "written.png", std::ios::binary);
  const std::vector<unsigned char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes, file);
  EXPECT_THROW(encode_png(RgbaImage{2, 2, {1, 2, 3}}), RenderError);
  std::filesystem::remove_all(dir);
}

TEST(PngIo, ErrorsNameTheFile) {
  RgbaImage img{1, 1, {1, 2, 3, 4}};
  const auto missing = std::filesystem::path("/nonexistent-gazelod-dir/x.png");
  try {
    write_png(missing, img);
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  const auto dir = temp_dir();
  const auto junk = dir / "junk.png";
  std::ofstream(junk) << "not a png";
  try {
    read_png(junk);
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("junk.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_png(dir / "empty.png", RgbaImage{}), RenderError);
  EXPECT_THROW(write_png(dir / "short.png", RgbaImage{2, 2, {1, 2, 3, 4}}), RenderError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace gazelod::render
