// SPDX-License-Identifier: Apache-2.0
// A glTF's external files: only regular files inside its own folder, unless the user allows
// more (bake --allow-outside-uris). An escape (../../etc/passwd), a FIFO (which would block the
// reader forever) and a directory are refused with the uri and the reason.
#include "bake/bake_error.hpp"
#include "bake/gltf_load.hpp"
#include "tests/bake/test_meshes.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace gazelod::bake {
namespace {

namespace fs = std::filesystem;

// A one-triangle glTF in `dir`/name whose buffer is `uri` (36 bytes of positions).
std::string triangle_gltf(const std::string& dir, const std::string& name, const std::string& uri) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << R"({"asset":{"version":"2.0"},"buffers":[{"uri":")" << uri
                      << R"(","byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
                      << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
                      << R"("min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
                      << R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
  return path;
}

void write_triangle_bin(const std::string& path) {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(p), sizeof p);
}

std::string load_error(const std::string& path, GltfLoadOptions o = {}) {
  try {
    load_gltf(path, o);
  } catch (const BakeError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

TEST(GltfUris, InsideTheFolderLoads) {
  const std::string dir = testing::temp_dir("uri_inside");
  fs::create_directories(dir + "/data");
  write_triangle_bin(dir + "/data/tri.bin");
  EXPECT_EQ(load_error(triangle_gltf(dir, "a.gltf", "data/tri.bin")), "");
}

TEST(GltfUris, EscapesAreRefusedUnlessAllowed) {
  const std::string dir = testing::temp_dir("uri_escape");
  fs::create_directories(dir + "/model");
  write_triangle_bin(dir + "/outside.bin");
  const std::string gltf = triangle_gltf(dir + "/model", "a.gltf", "../outside.bin");
  const std::string m = load_error(gltf);
  EXPECT_HAS(m, "outside the glTF's folder");
  EXPECT_HAS(m, "--allow-outside-uris");
  EXPECT_EQ(load_error(gltf, GltfLoadOptions{true}), "") << "allowed explicitly";
  EXPECT_HAS(load_error(triangle_gltf(dir + "/model", "p.gltf", "../../../../../../../../etc/passwd")),
             "outside the glTF's folder");
}

TEST(GltfUris, FifoAndDirectoryAreRefusedWithoutBlocking) {
  const std::string dir = testing::temp_dir("uri_special");
  ASSERT_EQ(::mkfifo((dir + "/pipe.bin").c_str(), 0600), 0) << std::strerror(errno);
  fs::create_directories(dir + "/folder.bin");
  EXPECT_HAS(load_error(triangle_gltf(dir, "f.gltf", "pipe.bin")), "not a regular file");
  EXPECT_HAS(load_error(triangle_gltf(dir, "d.gltf", "folder.bin")), "not a regular file");
  EXPECT_HAS(load_error(triangle_gltf(dir, "m.gltf", "missing.bin")), "no such file");
}

// glTF 1.0 (its objects keyed by id) was read by tinygltf as an empty 2.0 file, and the bake
// said "nothing to bake". Named by its version now: written here, and Debian's
// assimp-testmodels' own glTF 1.0 box, as text and as a binary glTF 1.0.
TEST(GltfVersion, Gltf1IsRefusedByItsVersion) {
  const std::string dir = testing::temp_dir("gltf1");
  std::ofstream(dir + "/v1.gltf") << R"({"asset":{"version":"1.0"},"meshes":{"m":{"primitives":[]}}})";
  EXPECT_HAS(load_error(dir + "/v1.gltf"),
             "v1.gltf: /asset/version: \"1.0\": gazelod reads glTF 2.0 only; convert the file to glTF 2.0 first");
  const std::string models = "/usr/share/assimp/models/glTF/BoxTextured-glTF";
  if (!fs::exists(models + "/BoxTextured.gltf")) GAZELOD_SKIP_OR_FAIL("no assimp-testmodels at " << models);
  EXPECT_HAS(load_error(models + "/BoxTextured.gltf"), "BoxTextured.gltf: /asset/version: \"1.0\"");
  const std::string glb = "/usr/share/assimp/models/glTF/BoxTextured-glTF-Binary/BoxTextured.glb";
  EXPECT_HAS(load_error(glb), "BoxTextured.glb: GLB container version 1 (byte 4): gazelod reads glTF 2.0");
}

}  // namespace
}  // namespace gazelod::bake
