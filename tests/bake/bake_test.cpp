// SPDX-License-Identifier: Apache-2.0
// bake_file on the generated scene: MSFT_lod structure, extras, and what must survive.
#include "bake/bake.hpp"
#include "bake/detail.hpp"
#include "bake/gltf_load.hpp"
#include "bake/summary.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

namespace gazelod::bake {
namespace {

using tinygltf::Model;
using tinygltf::Value;

struct Baked {
  Model in, out;
  BakeReport report;
};

Baked bake_scene(const std::string& test, const std::string& ext, BakeOptions o = {}) {
  // One folder per test and input format: parameterised cases run in parallel under ctest.
  const std::string dir = testing::temp_dir(test + (ext == ".glb" ? "_glb" : "_gltf"));
  Baked b;
  b.in = testing::scene_model();
  const std::string in = testing::write_model(b.in, dir + "/scene" + ext);
  b.report = bake_file(in, dir + "/out.glb", o);
  b.out = load_gltf(dir + "/out.glb").model;
  b.in = load_gltf(in).model;  // as tinygltf reads it back, for like-for-like comparisons
  return b;
}

const Value& lod_extras(const Model& m, int node) {
  return m.nodes.at(std::size_t(node)).extras.Get("gazelod_lod");
}

std::size_t triangles_of_mesh(const Model& m, int mesh) {
  std::size_t t = 0;
  for (const auto& p : m.meshes.at(std::size_t(mesh)).primitives) t += m.accessors.at(std::size_t(p.indices)).count / 3;
  return t;
}

std::vector<unsigned char> view_bytes(const Model& m, int view) {
  const auto& bv = m.bufferViews.at(std::size_t(view));
  const auto& d = m.buffers.at(std::size_t(bv.buffer)).data;
  return {d.begin() + long(bv.byteOffset), d.begin() + long(bv.byteOffset + bv.byteLength)};
}

std::vector<float> floats_of(const Model& m, int accessor) {
  const auto& a = m.accessors.at(std::size_t(accessor));
  const auto bytes = view_bytes(m, a.bufferView);
  std::vector<float> f(a.count * 3);
  std::memcpy(f.data(), bytes.data() + a.byteOffset, f.size() * 4);
  return f;
}

class BakeScene : public ::testing::TestWithParam<const char*> {};

TEST_P(BakeScene, EveryMeshNodeGetsAnMsftLodChain) {
  const Baked b = bake_scene(std::string("chain") + (GetParam()[2] == 'g' ? "_gltf" : "_glb"), GetParam());
  EXPECT_NE(std::find(b.out.extensionsUsed.begin(), b.out.extensionsUsed.end(), "MSFT_lod"),
            b.out.extensionsUsed.end());
  for (int node : {1, 2, 3}) {
    SCOPED_TRACE("node " + std::to_string(node));
    const auto& n = b.out.nodes[std::size_t(node)];
    ASSERT_TRUE(n.extensions.count("MSFT_lod"));
    const Value& ids = n.extensions.at("MSFT_lod").Get("ids");
    ASSERT_EQ(ids.ArrayLen(), 3u);  // default: 4 levels in all
    std::vector<int> chain = {node};
    for (std::size_t k = 0; k < 3; ++k) chain.push_back(ids.Get(int(k)).GetNumberAsInt());
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const auto& l = b.out.nodes[std::size_t(chain[k])];
      const Value& e = lod_extras(b.out, chain[k]);
      EXPECT_EQ(e.Get("level").GetNumberAsInt(), int(k));
      // The recorded triangle count is the one in the file.
      EXPECT_EQ(std::size_t(e.Get("triangles").GetNumberAsDouble()), triangles_of_mesh(b.out, l.mesh));
      if (k == 0) {
        EXPECT_EQ(e.Get("error_m").GetNumberAsDouble(), 0.0);
        EXPECT_EQ(e.Get("detail_cycles_per_diameter").GetNumberAsDouble(), 0.0);
        continue;
      }
      const Value& prev = lod_extras(b.out, chain[k - 1]);
      EXPECT_LT(e.Get("triangles").GetNumberAsDouble(), prev.Get("triangles").GetNumberAsDouble());
      EXPECT_GT(e.Get("error_m").GetNumberAsDouble(), prev.Get("error_m").GetNumberAsDouble());
      const double d = e.Get("diameter_m").GetNumberAsDouble(), err = e.Get("error_m").GetNumberAsDouble();
      EXPECT_NEAR(e.Get("detail_cycles_per_diameter").GetNumberAsDouble(), d / (2 * err), 1e-9 * d / err);
      // LOD nodes: same transform, name + "_lodK", no children, in no scene.
      const auto& base = b.in.nodes[std::size_t(node)];
      EXPECT_EQ(l.name, base.name + "_lod" + std::to_string(k));
      EXPECT_EQ(l.translation, base.translation);
      EXPECT_EQ(l.rotation, base.rotation);
      EXPECT_EQ(l.scale, base.scale);
      EXPECT_EQ(l.matrix, base.matrix);
      EXPECT_TRUE(l.children.empty());
      for (const auto& s : b.out.scenes) EXPECT_EQ(std::count(s.nodes.begin(), s.nodes.end(), chain[k]), 0);
      for (const auto& other : b.out.nodes)
        EXPECT_EQ(std::count(other.children.begin(), other.children.end(), chain[k]), 0);
    }
  }
  // The sphere of diameter 1 (radius 0.5, node scale not applied: mesh units).
  EXPECT_NEAR(lod_extras(b.out, 1).Get("diameter_m").GetNumberAsDouble(), 1.0, 1e-6);
}

TEST_P(BakeScene, NamesMaterialsTexturesTransformsSurvive) {
  const Baked b = bake_scene(std::string("survive") + (GetParam()[2] == 'g' ? "_gltf" : "_glb"), GetParam());
  for (std::size_t i = 0; i < b.in.nodes.size(); ++i) {
    EXPECT_EQ(b.out.nodes[i].name, b.in.nodes[i].name);
    EXPECT_EQ(b.out.nodes[i].translation, b.in.nodes[i].translation);
    EXPECT_EQ(b.out.nodes[i].rotation, b.in.nodes[i].rotation);
    EXPECT_EQ(b.out.nodes[i].scale, b.in.nodes[i].scale);
    EXPECT_EQ(b.out.nodes[i].matrix, b.in.nodes[i].matrix);
    EXPECT_EQ(b.out.nodes[i].children, b.in.nodes[i].children);
    EXPECT_EQ(b.out.nodes[i].mesh, b.in.nodes[i].mesh);
  }
  EXPECT_EQ(b.out.nodes[3].extras.Get("tag").Get<std::string>(), "keep");
  ASSERT_EQ(b.out.materials.size(), 2u);
  EXPECT_EQ(b.out.materials[0].name, "Red");
  EXPECT_EQ(b.out.materials[0].pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1, 0, 0, 1}));
  EXPECT_EQ(b.out.materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
  ASSERT_EQ(b.out.textures.size(), 1u);
  ASSERT_EQ(b.out.images.size(), 1u);
  EXPECT_EQ(b.out.images[0].mimeType, "image/png");
  EXPECT_EQ(view_bytes(b.out, b.out.images[0].bufferView), testing::image_bytes());
  EXPECT_EQ(b.out.scenes.size(), 1u);
  EXPECT_EQ(b.out.scenes[0].name, "Main");
  EXPECT_EQ(b.out.scenes[0].nodes, (std::vector<int>{0, 3}));
  // Level-0 meshes are untouched; coarser ones keep each primitive's material and attributes.
  for (std::size_t mi = 0; mi < b.in.meshes.size(); ++mi) {
    EXPECT_EQ(b.out.meshes[mi].name, b.in.meshes[mi].name);
    ASSERT_EQ(b.out.meshes[mi].primitives.size(), b.in.meshes[mi].primitives.size());
    for (std::size_t p = 0; p < b.in.meshes[mi].primitives.size(); ++p) {
      const int pa = b.out.meshes[mi].primitives[p].attributes.at("POSITION");
      EXPECT_EQ(floats_of(b.out, pa), floats_of(b.in, b.in.meshes[mi].primitives[p].attributes.at("POSITION")));
      EXPECT_EQ(triangles_of_mesh(b.out, int(mi)), triangles_of_mesh(b.in, int(mi)));
    }
  }
  const auto& wavy_lod = b.out.meshes[std::size_t(
      b.out.nodes[std::size_t(b.out.nodes[2].extensions.at("MSFT_lod").Get("ids").Get(0).GetNumberAsInt())].mesh)];
  EXPECT_EQ(wavy_lod.name, "Wavy_lod1");
  ASSERT_EQ(wavy_lod.primitives.size(), 2u);
  EXPECT_EQ(wavy_lod.primitives[0].material, 0);
  EXPECT_EQ(wavy_lod.primitives[1].material, 1);
  EXPECT_EQ(wavy_lod.primitives[1].attributes, b.out.meshes[1].primitives[1].attributes);
  EXPECT_EQ(b.out.buffers.size(), 1u);  // everything in the GLB BIN chunk
}

TEST(Bake, ExternalImageIsEmbeddedUnchanged) {
  const std::string dir = testing::temp_dir("extimage");
  Model m = testing::scene_model();
  m.images[0].bufferView = -1;
  m.images[0].mimeType.clear();
  m.images[0].uri = "tex.png";
  const auto bytes = testing::image_bytes();
  std::ofstream(dir + "/tex.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  const std::string in = testing::write_model(m, dir + "/scene.gltf");
  bake_file(in, dir + "/out.glb", BakeOptions{});
  const Model out = load_gltf(dir + "/out.glb").model;
  ASSERT_EQ(out.images.size(), 1u);
  EXPECT_TRUE(out.images[0].uri.empty());
  EXPECT_EQ(out.images[0].mimeType, "image/png");
  ASSERT_GE(out.images[0].bufferView, 0);
  EXPECT_EQ(view_bytes(out, out.images[0].bufferView), bytes);
  EXPECT_EQ(out.images[0].name, "checker");
}

INSTANTIATE_TEST_SUITE_P(InputFormats, BakeScene, ::testing::Values(".gltf", ".glb"));

TEST(Bake, SharedMeshIsSimplifiedOnce) {
  const Baked b = bake_scene("shared", ".glb");
  // Nodes 1 and 3 both use mesh 0: their level-k nodes share one "Sphere_lodK" mesh.
  const Value& a = b.out.nodes[1].extensions.at("MSFT_lod").Get("ids");
  const Value& c = b.out.nodes[3].extensions.at("MSFT_lod").Get("ids");
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(b.out.nodes[std::size_t(a.Get(k).GetNumberAsInt())].mesh,
              b.out.nodes[std::size_t(c.Get(k).GetNumberAsInt())].mesh);
  EXPECT_EQ(b.out.meshes.size(), 2u + 2u * 3u);
  EXPECT_EQ(b.report.meshes.size(), 2u);
  EXPECT_EQ(b.report.lod_nodes, 3u);
  EXPECT_EQ(b.report.input_triangles, 5120u + 2048u);
}

TEST(Bake, RatiosAndLevelsShapeTheChain) {
  BakeOptions o;
  o.chain.ratios = {0.5};
  const Baked b = bake_scene("ratios", ".glb", o);
  EXPECT_EQ(b.out.nodes[1].extensions.at("MSFT_lod").Get("ids").ArrayLen(), 1u);
  EXPECT_EQ(b.report.meshes[0].levels.size(), 2u);
  EXPECT_NEAR(b.report.meshes[0].levels[1].triangles, 2560.0, 0.2 * 2560.0);
  EXPECT_EQ(ratios_for_levels(3), (std::vector<double>{0.25, 0.0625}));
  EXPECT_TRUE(ratios_for_levels(1).empty());
}

TEST(Bake, ProgressNamesEveryMeshAndTheOverallShare) {
  BakeOptions o;
  std::vector<std::string> lines;
  o.progress = [&](const std::string& l) { lines.push_back(l); };
  bake_scene("progress", ".glb", o);
  auto has = [&](const std::string& s) {
    return std::any_of(lines.begin(), lines.end(), [&](const auto& l) { return l.find(s) != l.npos; });
  };
  EXPECT_TRUE(has("mesh 1/2 mesh 0 'Sphere'"));
  EXPECT_TRUE(has("mesh 2/2 mesh 1 'Wavy' (2 primitives)"));
  EXPECT_TRUE(has("overall 50%"));
  EXPECT_TRUE(has("overall 100%"));
  EXPECT_TRUE(has("writing"));
}

TEST(Bake, TooSmallMeshEndsItsChainEarlyAndSaysWhy) {
  const std::string dir = testing::temp_dir("small");
  testing::TestMesh tri;
  tri.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  tri.indices = {0, 1, 3, 0, 3, 2};  // 2 triangles: no coarser level can have fewer than 1... once
  const std::string in = testing::write_model(testing::single_mesh_model(tri), dir + "/in.glb");
  const BakeReport r = bake_file(in, dir + "/out.glb", BakeOptions{});
  ASSERT_EQ(r.meshes.size(), 1u);
  EXPECT_LT(r.meshes[0].levels.size(), 4u);
  EXPECT_NE(r.meshes[0].note.find("cannot get below"), std::string::npos);
  // The summary names the mesh by its index as its table does (a nameless one gave "note:  ").
  const std::string summary = format_summary(r);
  EXPECT_NE(summary.find("  note: mesh 0" + std::string(r.meshes[0].name.empty() ? "" : " " + r.meshes[0].name) +
                         " stops at level"),
            std::string::npos)
      << summary;
  const Model out = load_gltf(dir + "/out.glb").model;
  EXPECT_EQ(
      out.nodes[0].extensions.count("MSFT_lod") ? out.nodes[0].extensions.at("MSFT_lod").Get("ids").ArrayLen() + 1 : 1u,
      r.meshes[0].levels.size());
}

}  // namespace
}  // namespace gazelod::bake
