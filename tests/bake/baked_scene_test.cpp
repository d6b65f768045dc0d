// SPDX-License-Identifier: Apache-2.0
// Round trip: bake the generated scene, read it back with load_baked_scene.
#include "bake/bake.hpp"
#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_bake.hpp"
#include "bake/baked_scene.hpp"
#include "bake/gltf_load.hpp"
#include "lod/object_set.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::bake {
namespace {

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

std::string baked(const std::string& test, BakeReport* report = nullptr) {
  const std::string dir = testing::temp_dir(test);
  const std::string in = testing::write_model(testing::scene_model(), dir + "/in.glb");
  const BakeReport r = bake_file(in, dir + "/out.glb", BakeOptions{});
  if (report) *report = r;
  return dir + "/out.glb";
}

std::string load_error(const std::string& path) {
  try {
    load_baked_scene(path);
  } catch (const BakeError& e) {
    return e.what();
  }
  return "";
}

TEST(BakedScene, RoundTripGivesOneObjectPerMeshNode) {
  BakeReport rep;
  const auto objs = load_baked_scene(baked("rt", &rep));
  ASSERT_EQ(objs.size(), 3u);  // scene order: Root's children first, then SphereCopy
  EXPECT_EQ(objs[0].name, "SphereNode");
  EXPECT_EQ(objs[1].name, "WavyNode");
  EXPECT_EQ(objs[2].name, "SphereCopy");
  for (const auto& o : objs) {
    SCOPED_TRACE(o.name);
    ASSERT_EQ(o.lods.size(), 4u);
    EXPECT_EQ(lod::validate_chain(o.lods), "");
    EXPECT_EQ(o.lods[0].detail, 0.0);
    for (std::size_t k = 1; k < o.lods.size(); ++k) {
      EXPECT_EQ(o.lods[k].detail_kind, lod::DetailKind::removed_cycles_per_diameter);
      EXPECT_LT(o.lods[k].triangles, o.lods[k - 1].triangles);
      if (k > 1) {
        EXPECT_LT(o.lods[k].detail, o.lods[k - 1].detail);  // coarser removes more
      }
    }
  }
  // The chains are the ones the bake reported (sphere = mesh 0, wavy = mesh 1).
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(objs[0].lods[k].triangles, rep.meshes[0].levels[k].triangles);
    EXPECT_EQ(objs[1].lods[k].triangles, rep.meshes[1].levels[k].triangles);
    EXPECT_EQ(objs[2].lods[k].triangles, rep.meshes[0].levels[k].triangles);
    EXPECT_DOUBLE_EQ(objs[0].lods[k].detail, rep.meshes[0].levels[k].detail_cycles_per_diameter);
  }
  EXPECT_EQ(objs[0].lods[0].triangles, 5120u);
  EXPECT_EQ(objs[0].lods[0].vertices, 2562u);  // 10 * 4^4 + 2
}

// bake --clusters carries points and lines over unbaked (docs/bake.md); run --scene then
// refused the file ("extras/gazelod_lod: missing") or, drawing, the lines primitive. A mesh of
// lines only is no object; a mixed mesh's level geometry is its triangles.
TEST(BakedScene, PointsAndLinesCarriedOverByClustersAreSkipped) {
  const std::string dir = testing::temp_dir("lines_clusters");
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  tinygltf::Primitive lines = m.meshes[0].primitives[0];
  lines.mode = TINYGLTF_MODE_LINE;  // the icosphere's 960 indices, read as 480 segments
  tinygltf::Mesh only_lines;
  only_lines.name = "Wire";
  only_lines.primitives = {lines};
  m.meshes.push_back(only_lines);
  m.meshes[0].primitives.push_back(lines);  // mixed: triangles, then lines
  tinygltf::Node wire;
  wire.name = "WireNode";
  wire.mesh = 1;
  m.nodes.push_back(wire);
  m.scenes[0].nodes.push_back(static_cast<int>(m.nodes.size() - 1));
  const std::string in = testing::write_model(m, dir + "/in.glb");
  bake_clusters_file(in, dir + "/out.glb", ClusterBakeOptions{});
  const BakedScene scene = load_baked(dir + "/out.glb", BakedLoad::with_level_geometry);
  ASSERT_EQ(scene.objects.size(), 1u) << "the lines-only mesh is no object";
  ASSERT_FALSE(scene.objects[0].level_meshes.empty());
  EXPECT_EQ(scene.objects[0].level_meshes[0].indices.size(), 960u) << "the triangles, not the lines";
}

TEST(BakedScene, BoundingSpheresAreInWorldSpace) {
  const auto objs = load_baked_scene(baked("spheres"));
  // SphereNode: radius 0.5 scaled by 2 under Root at (1, 2, 3); centred on the origin of the
  // mesh, so rotation does not move it.
  EXPECT_NEAR(objs[0].radius_m, 1.0, 1e-5);
  EXPECT_NEAR(objs[0].center_m.x, 1.0, 1e-5);
  EXPECT_NEAR(objs[0].center_m.y, 2.0, 1e-5);
  EXPECT_NEAR(objs[0].center_m.z, 3.0, 1e-5);
  // WavyNode: [0,1]^2 x [-0.05, 0.05] grid, matrix translation z -4, under Root.
  EXPECT_NEAR(objs[1].center_m.x, 1.5, 1e-5);
  EXPECT_NEAR(objs[1].center_m.y, 2.5, 1e-5);
  EXPECT_NEAR(objs[1].center_m.z, -1.0, 0.06);
  EXPECT_NEAR(objs[1].radius_m, std::sqrt(0.5), 0.06);
  EXPECT_GE(objs[1].radius_m, std::sqrt(0.5) - 1e-6);  // encloses the corners
  // SphereCopy at (-5, 0, 0), unscaled.
  EXPECT_NEAR(objs[2].radius_m, 0.5, 1e-5);
  EXPECT_NEAR(objs[2].center_m.x, -5.0, 1e-5);
}

TEST(BakedScene, UnbakedFileNamesTheMissingExtras) {
  const std::string dir = testing::temp_dir("unbaked");
  const std::string in = testing::write_model(testing::scene_model(), dir + "/in.glb");
  EXPECT_HAS(load_error(in), "in.glb: /nodes/1/extras/gazelod_lod: missing");
}

TEST(BakedScene, BrokenIdsAndChainsAreNamedByJsonPath) {
  const std::string path = baked("broken");
  const std::string dir = path.substr(0, path.rfind('/'));
  {
    tinygltf::Model m = load_gltf(path).model;
    m.nodes[1].extensions["MSFT_lod"] = tinygltf::Value(
        tinygltf::Value::Object{{"ids", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(999)})}});
    testing::write_model(m, dir + "/ids.glb");
    EXPECT_HAS(load_error(dir + "/ids.glb"), "ids.glb: /nodes/1/extensions/MSFT_lod/ids/0: not a node index");
  }
  {
    tinygltf::Model m = load_gltf(path).model;
    const int lod2 = m.nodes[1].extensions["MSFT_lod"].Get("ids").Get(1).GetNumberAsInt();
    auto extras = m.nodes[std::size_t(lod2)].extras.Get<tinygltf::Value::Object>();
    auto lod = extras["gazelod_lod"].Get<tinygltf::Value::Object>();
    lod["detail_cycles_per_diameter"] = tinygltf::Value(1e9);  // finer than level 1: inconsistent
    extras["gazelod_lod"] = tinygltf::Value(lod);
    m.nodes[std::size_t(lod2)].extras = tinygltf::Value(extras);
    testing::write_model(m, dir + "/chain.glb");
    EXPECT_HAS(load_error(dir + "/chain.glb"), "chain.glb: /nodes/1: LOD chain: level 2: must remove no finer detail");
  }
  {
    tinygltf::Model m = load_gltf(path).model;
    auto extras = m.nodes[1].extras.Get<tinygltf::Value::Object>();
    auto lod = extras["gazelod_lod"].Get<tinygltf::Value::Object>();
    lod["triangles"] = tinygltf::Value(std::string("many"));
    extras["gazelod_lod"] = tinygltf::Value(lod);
    m.nodes[1].extras = tinygltf::Value(extras);
    testing::write_model(m, dir + "/tri.glb");
    EXPECT_HAS(load_error(dir + "/tri.glb"), "tri.glb: /nodes/1/extras/gazelod_lod/triangles: must be a finite number");
  }
  EXPECT_HAS(load_error(dir + "/none.glb"), "none.glb: cannot open for reading");
}

// A finite but extreme scale (1e100 on the root; 1e200 along x, squared to inf by a child's)
// made the sphere huge or NaN, refused later without the node's name.
TEST(BakedScene, TransformPastAnyDistanceNamesTheNode) {
  const std::string path = baked("far");
  const std::string dir = path.substr(0, path.rfind('/'));
  tinygltf::Model m = load_gltf(path).model;
  m.nodes[0].scale = {1e100, 1e100, 1e100};
  testing::write_model(m, dir + "/far.glb");
  EXPECT_HAS(load_error(dir + "/far.glb"), "far.glb: /nodes/1: vertex 0 of its mesh's primitive 0 lands at");
  m.nodes[0].scale = {1e200, 1.0, 1.0};
  m.nodes[1].scale = {1e200, 1.0, 1.0};
  testing::write_model(m, dir + "/inf.glb");
  EXPECT_HAS(load_error(dir + "/inf.glb"), "m in the world (at most 1e+09 m): check the scale");
}

// With the level geometry (what `gazelod run` draws): one triangle list per level, as many
// triangles as the chain says, in the mesh's own space (the sphere mesh within radius 0.5);
// none without it; a level mesh that is not triangles is named.
TEST(BakedScene, LevelGeometryMatchesTheChain) {
  const std::string path = baked("geometry");
  EXPECT_TRUE(load_baked(path).objects.at(0).level_meshes.empty());
  const BakedScene scene = load_baked(path, BakedLoad::with_level_geometry);
  for (const BakedObject& o : scene.objects) {
    SCOPED_TRACE(o.name);
    ASSERT_EQ(o.level_meshes.size(), o.lods.size());
    for (std::size_t l = 0; l < o.lods.size(); ++l) {
      const BakedLevelMesh& g = o.level_meshes[l];
      EXPECT_EQ(g.indices.size(), 3 * std::size_t{o.lods[l].triangles}) << "level " << l;
      for (std::uint32_t i : g.indices) ASSERT_LT(i, g.positions_xyz.size() / 3);
    }
  }
  for (std::size_t v = 0; v < scene.objects[0].level_meshes[0].positions_xyz.size(); ++v)
    ASSERT_LE(std::abs(scene.objects[0].level_meshes[0].positions_xyz[v]), 0.5f + 1e-5f);

  const std::string dir = path.substr(0, path.rfind('/'));
  tinygltf::Model m = load_gltf(path).model;
  const int lod1 = m.nodes[1].extensions["MSFT_lod"].Get("ids").Get(0).GetNumberAsInt();
  const int mesh = m.nodes[std::size_t(lod1)].mesh;
  m.meshes[std::size_t(mesh)].primitives[0].mode = TINYGLTF_MODE_POINTS;
  testing::write_model(m, dir + "/points.glb");
  EXPECT_NO_THROW(load_baked(dir + "/points.glb")) << "the chains alone do not read the geometry";
  try {
    load_baked(dir + "/points.glb", BakedLoad::with_level_geometry);
    ADD_FAILURE() << "a points primitive was read as triangles";
  } catch (const BakeError& e) {
    EXPECT_HAS(std::string(e.what()), "points.glb: mesh " + std::to_string(mesh));
  }
}

}  // namespace
}  // namespace gazelod::bake
