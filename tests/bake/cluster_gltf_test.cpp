// SPDX-License-Identifier: Apache-2.0
// bake --clusters through the library: GAZELOD_cluster_lod written and read back identical,
// the rest of the file unchanged, strips and fans, degenerate triangles reported, and the
// reader's and the bake's errors naming file and place.
#include "bake/bake.hpp"
#include "bake/bake_error.hpp"
#include "bake/baked_scene.hpp"
#include "bake/cluster/cluster_bake.hpp"
#include "bake/cluster/cluster_build.hpp"
#include "bake/cluster/cluster_lod_gltf.hpp"
#include "bake/gltf_load.hpp"
#include "bake/mesh_extract.hpp"
#include "tests/bake/cluster_invariants.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>

namespace gazelod::bake {
namespace {

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

using Value = tinygltf::Value;

struct Baked {
  std::string dir, in, out;
  ClusterBakeReport report;
};

Baked bake(const std::string& test, const tinygltf::Model& model) {
  Baked b;
  b.dir = testing::temp_dir(test);
  b.in = testing::write_model(model, b.dir + "/in.glb");
  b.out = b.dir + "/out.glb";
  b.report = bake_clusters_file(b.in, b.out, ClusterBakeOptions{});
  return b;
}

void expect_same(const lod::ClusterHierarchy& a, const lod::ClusterHierarchy& b) {
  EXPECT_EQ(a.self_center_x_m, b.self_center_x_m);
  EXPECT_EQ(a.self_center_y_m, b.self_center_y_m);
  EXPECT_EQ(a.self_center_z_m, b.self_center_z_m);
  EXPECT_EQ(a.self_radius_m, b.self_radius_m);
  EXPECT_EQ(a.self_error_m, b.self_error_m);
  EXPECT_EQ(a.parent_center_x_m, b.parent_center_x_m);
  EXPECT_EQ(a.parent_center_y_m, b.parent_center_y_m);
  EXPECT_EQ(a.parent_center_z_m, b.parent_center_z_m);
  EXPECT_EQ(a.parent_radius_m, b.parent_radius_m);
  EXPECT_EQ(a.parent_error_m, b.parent_error_m);
  EXPECT_EQ(a.first_index, b.first_index);
  EXPECT_EQ(a.index_count, b.index_count);
  EXPECT_EQ(a.depth, b.depth);
}

TEST(ClusterGltf, RoundTripGivesTheBuiltHierarchy) {
  const tinygltf::Model in = testing::scene_model();
  const Baked b = bake("cl_rt", in);
  ASSERT_EQ(b.report.primitives.size(), 3u);  // Sphere; Wavy's two primitives
  EXPECT_EQ(b.report.meshes, 2u);
  EXPECT_EQ(b.report.input_triangles, 5120u + 2048u);
  const BakedScene scene = load_baked(b.out);
  ASSERT_EQ(scene.cluster_meshes.size(), 2u);
  ASSERT_EQ(scene.cluster_meshes[1].primitives.size(), 2u);
  const tinygltf::Model original = load_gltf(b.in).model;
  const auto locks = testing::meeting_vertices_of(original);
  for (const BakedClusterMesh& m : scene.cluster_meshes)
    for (const BakedClusterPrimitive& p : m.primitives) {
      SCOPED_TRACE(primitive_label(original, m.mesh, p.primitive));
      const PrimitiveGeometry g = extract_primitive(original, m.mesh, p.primitive);
      ClusterBuildOptions o;
      o.locked_vertices = locks[static_cast<std::size_t>(m.mesh)][static_cast<std::size_t>(p.primitive)];
      const ClusterBuildResult direct = build_cluster_hierarchy(g.positions_xyz, g.indices, o);
      expect_same(p.hierarchy, direct.hierarchy);
      EXPECT_EQ(p.indices, direct.indices);
      EXPECT_EQ(p.levels, direct.levels);
      EXPECT_EQ(p.vertex_count, g.positions_xyz.size() / 3);
      EXPECT_GT(p.levels, 2u);
    }
  // Objects: one per mesh node, a one-level chain (the full mesh), linked to their clusters.
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.objects[0].name, "SphereNode");
  ASSERT_EQ(scene.objects[0].lods.size(), 1u);
  EXPECT_EQ(scene.objects[0].lods[0].triangles, 5120u);
  EXPECT_EQ(scene.objects[1].lods[0].triangles, 2048u);
  EXPECT_NEAR(scene.objects[0].radius_m, 1.0, 1e-5);
  ASSERT_NE(scene.clusters_of(scene.objects[2]), nullptr);
  EXPECT_EQ(scene.clusters_of(scene.objects[2])->mesh, 0);
  EXPECT_EQ(load_baked_scene(b.out).size(), 3u);
}

// Small primitives are built side by side, one thread each, and stored in mesh order: the file
// is the same byte for byte on one thread or several, with one progress line per mesh (in
// whichever order the meshes finish). Run under ThreadSanitizer in CI.
TEST(ClusterGltf, SideBySideBuildsWriteTheSameFile) {
  const std::string dir = testing::temp_dir("cluster_side_by_side");
  const std::string in = testing::write_model(testing::scene_model(), dir + "/in.glb");
  std::vector<std::string> files, lines[2];
  for (unsigned threads : {1u, 3u}) {
    ClusterBakeOptions o;
    o.build.threads = threads;
    std::vector<std::string>& mine = lines[files.size()];
    o.progress = [&mine](const std::string& line) { mine.push_back(line); };
    const std::string out = dir + "/out" + std::to_string(threads) + ".glb";
    const ClusterBakeReport r = bake_clusters_file(in, out, o);
    EXPECT_EQ(r.primitives.size(), 3u);
    ASSERT_EQ(r.primitives[0].label, "mesh 0 'Sphere' primitive 0");
    EXPECT_EQ(r.primitives[2].label, "mesh 1 'Wavy' primitive 1");
    std::ifstream f(out, std::ios::binary);
    files.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  }
  EXPECT_TRUE(files[0] == files[1]) << "a different file on 3 threads";
  for (const auto& l : lines)  // one line per mesh, in either order
    for (const char* mesh : {" done: mesh 0 'Sphere': 5120 triangles", " done: mesh 1 'Wavy': 2048 triangles"})
      EXPECT_EQ(
          std::count_if(l.begin(), l.end(), [&](const std::string& s) { return s.find(mesh) != std::string::npos; }), 1)
          << mesh;
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = std::uint32_t(bytes[i]) << 16 |
                            (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                            (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += k[n >> 18 & 63], out += k[n >> 12 & 63];
    out += i + 1 < bytes.size() ? k[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? k[n & 63] : '=';
  }
  return out;
}

TEST(ClusterGltf, DataUriImageIsEmbeddedUnchangedByBothBakes) {
  // tinygltf reads a data: URI image into bytes and clears its uri: those bytes are all there
  // is, and both bakes must embed them (before, the output's image had neither bufferView nor
  // uri, and the texture was lost).
  const std::string dir = testing::temp_dir("cl_data_uri");
  tinygltf::Model m = testing::scene_model();
  m.images[0].bufferView = -1;
  m.images[0].mimeType.clear();
  m.images[0].uri = "data:image/png;base64," + base64(testing::image_bytes());
  const std::string in = testing::write_model(m, dir + "/in.gltf");
  ASSERT_TRUE(load_gltf(in).model.images.at(0).uri.empty()) << "tinygltf keeps the data: URI now";
  bake_clusters_file(in, dir + "/clusters.glb", ClusterBakeOptions{});
  bake_file(in, dir + "/chains.glb", BakeOptions{});
  for (const char* name : {"/clusters.glb", "/chains.glb"}) {
    SCOPED_TRACE(name);
    const tinygltf::Model out = load_gltf(dir + name).model;
    ASSERT_EQ(out.images.size(), 1u);
    EXPECT_EQ(out.images[0].mimeType, "image/png");
    ASSERT_GE(out.images[0].bufferView, 0);
    const auto& iv = out.bufferViews[static_cast<std::size_t>(out.images[0].bufferView)];
    const auto* bytes = out.buffers[0].data.data() + iv.byteOffset;
    EXPECT_EQ(std::vector<unsigned char>(bytes, bytes + iv.byteLength), testing::image_bytes());
  }
}

TEST(ClusterGltf, TheRestOfTheFileIsUnchanged) {
  const Baked b = bake("cl_rest", testing::scene_model());
  const tinygltf::Model in = load_gltf(b.in).model, out = load_gltf(b.out).model;
  EXPECT_EQ(out.nodes.size(), in.nodes.size());
  EXPECT_EQ(out.meshes.size(), in.meshes.size());
  EXPECT_EQ(out.materials.size(), in.materials.size());
  ASSERT_EQ(out.images.size(), 1u);
  const auto& iv = out.bufferViews[static_cast<std::size_t>(out.images[0].bufferView)];
  const auto* bytes = out.buffers[0].data.data() + iv.byteOffset;
  EXPECT_EQ(std::vector<unsigned char>(bytes, bytes + iv.byteLength), testing::image_bytes());
  EXPECT_EQ(out.extensionsUsed, std::vector<std::string>{kClusterLodExtension});
  EXPECT_TRUE(out.extensionsRequired.empty()) << "other viewers still draw the full primitive";
  for (std::size_t n = 0; n < in.nodes.size(); ++n) {
    EXPECT_EQ(out.nodes[n].name, in.nodes[n].name);
    EXPECT_TRUE(out.nodes[n].extensions.empty());
    EXPECT_EQ(out.nodes[n].extras.IsObject(), in.nodes[n].extras.IsObject());
  }
  for (std::size_t mi = 0; mi < in.meshes.size(); ++mi)
    for (std::size_t p = 0; p < in.meshes[mi].primitives.size(); ++p) {
      const auto& a = in.meshes[mi].primitives[p];
      const auto& c = out.meshes[mi].primitives[p];
      EXPECT_EQ(c.material, a.material);
      EXPECT_EQ(c.mode, a.mode);
      EXPECT_EQ(c.attributes.size(), a.attributes.size());
      EXPECT_TRUE(c.extensions.count(kClusterLodExtension));
      const PrimitiveGeometry ga = extract_primitive(in, int(mi), int(p)), gc = extract_primitive(out, int(mi), int(p));
      EXPECT_EQ(gc.indices, ga.indices) << "the full-detail primitive is drawn as before";
      EXPECT_EQ(gc.positions_xyz, ga.positions_xyz);
    }
}

TEST(ClusterGltf, StripsAndFansAreBakedAsLists) {
  for (const int mode : {TINYGLTF_MODE_TRIANGLE_STRIP, TINYGLTF_MODE_TRIANGLE_FAN}) {
    SCOPED_TRACE(mode);
    // A fan around vertex 0 of a hexagon, or a strip along a band: 6 / 10 vertices.
    testing::TestMesh m;
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      m.positions = {0, 0, 0};
      for (int k = 0; k <= 6; ++k)
        m.positions.insert(m.positions.end(), {std::cos(float(k) * 1.0472f), std::sin(float(k) * 1.0472f), 0.0f});
      m.positions.resize(3 * 7);
      m.indices = {0, 1, 2, 3, 4, 5, 6, 1};
    } else {
      for (int k = 0; k < 10; ++k) m.positions.insert(m.positions.end(), {float(k / 2), float(k % 2), 0.0f});
      m.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    }
    tinygltf::Model model = testing::single_mesh_model(m);
    model.meshes[0].primitives[0].mode = mode;
    const Baked b = bake("cl_mode" + std::to_string(mode), model);
    ASSERT_EQ(b.report.primitives.size(), 1u);
    EXPECT_EQ(b.report.primitives[0].source_triangles, m.indices.size() - 2);
    const std::vector<std::uint32_t> list =
        mode == TINYGLTF_MODE_TRIANGLE_FAN ? fan_to_list(m.indices) : strip_to_list(m.indices);
    const BakedScene scene = load_baked(b.out);
    const BakedClusterPrimitive& p = scene.cluster_meshes.at(0).primitives.at(0);
    EXPECT_EQ(p.indices.size(), list.size()) << "one cluster";
    // Every triangle keeps the first one's winding (glTF's strip / fan rule).
    auto winding = [&](std::size_t t) {
      const float* a = &m.positions[3 * list[t]];
      const float* c1 = &m.positions[3 * list[t + 1]];
      const float* c2 = &m.positions[3 * list[t + 2]];
      return (c1[0] - a[0]) * (c2[1] - a[1]) - (c1[1] - a[1]) * (c2[0] - a[0]);
    };
    for (std::size_t t = 0; t < list.size(); t += 3) EXPECT_GT(winding(t) * winding(0), 0.0f) << t / 3;
    // The plain bake takes them too, and its coarser levels are lists.
    const std::string msft = b.dir + "/msft.glb";
    bake_file(b.in, msft, BakeOptions{});
    for (const auto& mesh : load_gltf(msft).model.meshes)
      for (const auto& prim : mesh.primitives)
        if (mesh.name != "M") {
          EXPECT_EQ(prim.mode, TINYGLTF_MODE_TRIANGLES);
        }
  }
}

TEST(ClusterGltf, DegenerateTrianglesAreReported) {
  testing::TestMesh m = testing::grid(16, 1.0, 0.1);
  m.indices.insert(m.indices.end(), {0, 0, 1, 2, 2, 2});
  const Baked b = bake("cl_degen", testing::single_mesh_model(m));
  ASSERT_EQ(b.report.primitives.size(), 1u);
  EXPECT_EQ(b.report.primitives[0].degenerate_triangles, 2u);
  EXPECT_EQ(b.report.primitives[0].source_triangles, 512u);
  const std::string summary = format_cluster_summary(b.report);
  EXPECT_HAS(summary, "warning: 2 degenerate triangles (two corners at one position) dropped in 1 primitive");
  EXPECT_HAS(summary, "total: 1 mesh, 1 primitive with GAZELOD_cluster_lod, 514 input triangles");
}

TEST(ClusterGltf, SingleTriangleIsOneCluster) {
  testing::TestMesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.indices = {0, 1, 2};
  const Baked b = bake("cl_one", testing::single_mesh_model(m));
  const BakedScene scene = load_baked(b.out);
  const BakedClusterPrimitive& p = scene.cluster_meshes.at(0).primitives.at(0);
  ASSERT_EQ(p.hierarchy.size(), 1u);
  EXPECT_EQ(p.hierarchy.parent_error_m[0], lod::kNoParentError);
  EXPECT_EQ(p.levels, 1u);
}

std::string bake_error(const tinygltf::Model& model, const std::string& test) {
  const std::string dir = testing::temp_dir(test);
  const std::string in = testing::write_model(model, dir + "/in.glb");
  try {
    bake_clusters_file(in, dir + "/out.glb", ClusterBakeOptions{});
  } catch (const BakeError& e) {
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.glb"));
    return e.what();
  }
  return "";
}

// A primitive left with no triangle once its degenerate ones are dropped gets no hierarchy and
// a warning naming it; a file where every triangle primitive is like that is refused, and no
// output is left (written unchanged it would look like a bake that worked).
TEST(ClusterGltf, APrimitiveOfDegenerateTrianglesIsNamedAndAFileOfThemRefused) {
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  // Primitive 1: the same positions, every triangle with two corners at one vertex.
  const std::vector<std::uint32_t> degenerate{0, 0, 1, 2, 2, 2, 3, 4, 3};
  tinygltf::Buffer& buffer = m.buffers[0];
  while (buffer.data.size() % 4) buffer.data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.data.size();
  view.byteLength = degenerate.size() * 4;
  view.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
  const auto* bytes = reinterpret_cast<const unsigned char*>(degenerate.data());
  buffer.data.insert(buffer.data.end(), bytes, bytes + view.byteLength);
  m.bufferViews.push_back(view);
  tinygltf::Accessor indices;
  indices.bufferView = static_cast<int>(m.bufferViews.size() - 1);
  indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.count = degenerate.size();
  m.accessors.push_back(indices);
  tinygltf::Primitive prim = m.meshes[0].primitives[0];
  prim.indices = static_cast<int>(m.accessors.size() - 1);
  m.meshes[0].primitives.push_back(prim);

  const Baked b = bake("cl_degen_prim", m);
  ASSERT_EQ(b.report.primitives.size(), 1u);
  EXPECT_EQ(b.report.primitives[0].primitive, 0);
  EXPECT_HAS(format_cluster_summary(b.report),
             "warning: mesh 0 'M' primitive 1: no triangles left, no cluster hierarchy");
  const tinygltf::Model out = load_gltf(b.out).model;
  ASSERT_EQ(out.meshes[0].primitives.size(), 2u);
  EXPECT_EQ(out.meshes[0].primitives[0].extensions.count(kClusterLodExtension), 1u);
  EXPECT_EQ(out.meshes[0].primitives[1].extensions.count(kClusterLodExtension), 0u);

  m.meshes[0].primitives.erase(m.meshes[0].primitives.begin());
  EXPECT_HAS(bake_error(m, "cl_degen_all"),
             "in.glb: nothing to bake: no triangle primitive has a triangle left once degenerate ones");
}

TEST(ClusterGltf, BadGeometryNamesFileMeshAndVertex) {
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(1, 1.0));
  const auto& pa = m.accessors[std::size_t(m.meshes[0].primitives[0].attributes["POSITION"])];
  float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(m.buffers[0].data.data() + m.bufferViews[std::size_t(pa.bufferView)].byteOffset + 12 * 7 + 4, &nan, 4);
  EXPECT_HAS(bake_error(m, "cl_nan"), "in.glb: mesh 0 'M' primitive 0: POSITION 7 is not finite");
  m = testing::single_mesh_model(testing::icosphere(1, 1.0));
  const auto& ia = m.accessors[std::size_t(m.meshes[0].primitives[0].indices)];
  const std::uint32_t big = 1000;
  std::memcpy(m.buffers[0].data.data() + m.bufferViews[std::size_t(ia.bufferView)].byteOffset + 4 * 5, &big, 4);
  EXPECT_HAS(bake_error(m, "cl_range"),
             "in.glb: mesh 0 'M' primitive 0: index 5 is 1000, but there are only 42 vertices");
  // Fresh indices: the line primitive's are checked too (BakeErrors.CarriedAttributesAreChecked).
  m = testing::single_mesh_model(testing::icosphere(1, 1.0));
  m.meshes[0].primitives[0].mode = TINYGLTF_MODE_LINE;
  EXPECT_HAS(bake_error(m, "cl_lines"), "in.glb: nothing to bake: the meshes the nodes use have no triangle primitive");
  m.nodes[0].mesh = -1;
  EXPECT_HAS(bake_error(m, "cl_nomesh"), "in.glb: nothing to bake: no node uses a mesh");
}

TEST(ClusterGltf, PointsAndLinesBesideTrianglesAreKeptAsTheyAre) {
  // A CAD export's edges as a LINES primitive next to the faces: the faces get a hierarchy,
  // the lines stay as they are, and the bake says so.
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  tinygltf::Primitive lines = m.meshes[0].primitives[0];
  lines.mode = TINYGLTF_MODE_LINE;  // 960 indices: 480 segments
  m.meshes[0].primitives.push_back(lines);
  tinygltf::Primitive points = lines;
  points.mode = TINYGLTF_MODE_POINTS;
  m.meshes[0].primitives.push_back(points);
  const std::string dir = testing::temp_dir("cl_keep_lines");
  const std::string in = testing::write_model(m, dir + "/in.glb"), out = dir + "/out.glb";
  const ClusterBakeReport rep = bake_clusters_file(in, out, ClusterBakeOptions{});
  ASSERT_EQ(rep.primitives.size(), 1u);
  EXPECT_EQ(rep.primitives[0].primitive, 0);
  const auto warned = [&](const std::string& what) {
    return std::any_of(rep.warnings.begin(), rep.warnings.end(),
                       [&](const std::string& w) { return w.find(what) != std::string::npos; });
  };
  EXPECT_TRUE(warned("mesh 0 'M' primitive 1: mode 1 (LINES) kept as it is"));
  EXPECT_TRUE(warned("mesh 0 'M' primitive 2: mode 0 (POINTS) kept as it is"));
  const tinygltf::Model a = load_gltf(in).model, b = load_gltf(out).model;
  ASSERT_EQ(b.meshes[0].primitives.size(), 3u);
  EXPECT_EQ(b.meshes[0].primitives[0].extensions.count(kClusterLodExtension), 1u);
  for (std::size_t p = 1; p < 3; ++p) {
    const tinygltf::Primitive &pa = a.meshes[0].primitives[p], &pb = b.meshes[0].primitives[p];
    EXPECT_EQ(pb.mode, pa.mode);
    EXPECT_TRUE(pb.extensions.empty());
    EXPECT_EQ(pb.attributes, pa.attributes);
    EXPECT_EQ(read_index_accessor(b, pb.indices, 1u << 20, "out"), read_index_accessor(a, pa.indices, 1u << 20, "in"));
  }
  const BakedScene scene = load_baked(out);
  ASSERT_EQ(scene.cluster_meshes.size(), 1u);
  EXPECT_EQ(scene.cluster_meshes[0].primitives.size(), 1u);
}

TEST(ClusterGltf, EmptyNodesAndScenesStayObjects) {
  // tinygltf writes an object with no properties as null, which glTF forbids.
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(1, 1.0));
  m.nodes.emplace_back();
  m.scenes.emplace_back();
  const std::string dir = testing::temp_dir("cl_empty_objects");
  const std::string in = dir + "/in.gltf", out = dir + "/out.glb";
  {  // tinygltf writes the test's input with the same nulls: `{}` put back by hand
    std::ifstream f(testing::write_model(m, dir + "/raw.gltf"));
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    for (std::size_t at; (at = text.find("null")) != std::string::npos;) text.replace(at, 4, "{}");
    std::ofstream(in) << text;
  }
  ASSERT_EQ(load_gltf(in).model.nodes.size(), 2u);
  bake_clusters_file(in, out, ClusterBakeOptions{});
  std::ifstream f(out, std::ios::binary);
  const std::string glb((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  ASSERT_GT(glb.size(), 20u);
  std::uint32_t json_length = 0, total = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  std::memcpy(&total, glb.data() + 8, 4);
  EXPECT_EQ(total, glb.size());
  EXPECT_EQ(json_length % 4, 0u);
  const std::string json = glb.substr(20, json_length);
  EXPECT_EQ(json.find("null"), std::string::npos) << json.substr(0, 400);
  EXPECT_NE(json.find("\"nodes\":[{\"mesh\":0,\"name\":\"N\"},{}]"), std::string::npos) << json.substr(0, 400);
  const tinygltf::Model b = load_gltf(out).model;  // the BIN chunk still where it was
  EXPECT_EQ(b.nodes.size(), 2u);
  EXPECT_EQ(b.scenes.size(), 2u);
  EXPECT_EQ(load_baked(out).cluster_meshes.size(), 1u);
}

// Bakes the sphere, edits the output's extension or data, and returns load_baked's error.
std::string reader_error(const std::string& test, const std::function<void(tinygltf::Model&, Value::Object&)>& edit) {
  const Baked b = bake(test, testing::single_mesh_model(testing::icosphere(3, 1.0)));
  tinygltf::Model m = load_gltf(b.out).model;
  Value::Object ext = m.meshes[0].primitives[0].extensions[kClusterLodExtension].Get<Value::Object>();
  edit(m, ext);
  m.meshes[0].primitives[0].extensions[kClusterLodExtension] = Value(ext);
  testing::write_model(m, b.dir + "/edited.glb");
  try {
    load_baked(b.dir + "/edited.glb");
  } catch (const BakeError& e) {
    return e.what();
  }
  return "";
}

// The bytes of accessor `key` of the extension (tightly packed as the writer stores them).
unsigned char* data_of(tinygltf::Model& m, Value::Object& ext, const std::string& key) {
  const auto& a = m.accessors[std::size_t(ext[key].GetNumberAsInt())];
  return m.buffers[0].data.data() + m.bufferViews[std::size_t(a.bufferView)].byteOffset + a.byteOffset;
}

TEST(ClusterGltf, ReaderNamesTheJsonPath) {
  const std::string p = "edited.glb: /meshes/0/primitives/0/extensions/GAZELOD_cluster_lod";
  EXPECT_EQ(reader_error("cl_r_ok", [](tinygltf::Model&, Value::Object&) {}), "");
  EXPECT_HAS(reader_error("cl_r_version", [](tinygltf::Model&, Value::Object& e) { e["version"] = Value(2); }),
             p + "/version: is 2, this reader knows 1");
  EXPECT_HAS(reader_error("cl_r_missing", [](tinygltf::Model&, Value::Object& e) { e.erase("errors"); }),
             p + "/errors: missing");
  EXPECT_HAS(reader_error("cl_r_type", [](tinygltf::Model&, Value::Object& e) { e["errors"] = e["ranges"]; }),
             p + "/errors: accessor");
  EXPECT_HAS(reader_error("cl_r_count",
                          [](tinygltf::Model&, Value::Object& e) {
                            e["clusterCount"] = Value(e["clusterCount"].GetNumberAsInt() + 1);
                          }),
             "elements, clusterCount is");
  EXPECT_HAS(reader_error("cl_r_range",
                          [](tinygltf::Model& m, Value::Object& e) {
                            const std::uint32_t huge = 1u << 30;
                            std::memcpy(data_of(m, e, "ranges") + 8 * 3, &huge, 4);
                          }),
             p + "/ranges: element 3: first 1073741824");
  EXPECT_HAS(reader_error("cl_r_monotone",
                          [](tinygltf::Model& m, Value::Object& e) {
                            const float big = 1e6f;
                            std::memcpy(data_of(m, e, "errors"), &big, 4);  // self error of cluster 0
                          }),
             p + "/errors: element 0: need 0 <= self error <= parent error");
  EXPECT_HAS(reader_error("cl_r_nan",
                          [](tinygltf::Model& m, Value::Object& e) {
                            const float nan = std::numeric_limits<float>::quiet_NaN();
                            std::memcpy(data_of(m, e, "selfSpheres") + 16 * 2, &nan, 4);
                          }),
             p + "/selfSpheres: element 2 is not finite");
  EXPECT_HAS(reader_error("cl_r_sphere",
                          [](tinygltf::Model& m, Value::Object& e) {
                            const float tiny = 1e-6f;
                            std::memcpy(data_of(m, e, "parentSpheres") + 12, &tiny, 4);  // radius of cluster 0
                          }),
             p + "/parentSpheres: element 0: does not contain the self sphere");
  EXPECT_HAS(reader_error("cl_r_depth", [](tinygltf::Model&, Value::Object& e) { e["levelCount"] = Value(1); }),
             p + "/depths: element");
  EXPECT_HAS(reader_error("cl_r_index",
                          [](tinygltf::Model& m, Value::Object& e) {
                            const std::uint16_t big = 60000;
                            std::memcpy(data_of(m, e, "indices") + 2 * 7, &big, 2);
                          }),
             p + "/indices: index 7 is 60000, but there are only 642 vertices");
}

}  // namespace
}  // namespace gazelod::bake
