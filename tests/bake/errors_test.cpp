// SPDX-License-Identifier: Apache-2.0
// Every bake error path gives a message naming the file and the place, and no output file.
#include "bake/bake.hpp"
#include "bake/cluster/cluster_bake.hpp"
#include "bake/bake_error.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

namespace gazelod::bake {
namespace {

namespace fs = std::filesystem;

// Runs bake_file and returns the BakeError message ("" when none was thrown).
std::string bake_error(const std::string& in, const std::string& out) {
  try {
    bake_file(in, out, BakeOptions{});
  } catch (const BakeError& e) {
    return e.what();
  }
  return "";
}

struct Case {
  std::string dir, in, out;
};

// Writes the single-mesh model after `edit`, bakes it, and checks the output is absent.
std::string bake_edited(const std::string& name, const std::function<void(tinygltf::Model&)>& edit) {
  const std::string dir = testing::temp_dir("err_" + name);
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  edit(m);
  const std::string in = testing::write_model(m, dir + "/in.glb");
  const std::string msg = bake_error(in, dir + "/out.glb");
  EXPECT_FALSE(fs::exists(dir + "/out.glb")) << name;
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
  return msg;
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

// The cluster bake's BakeError message for model `m` ("" when none), no output left.
std::string clusters_error(const std::string& name, const tinygltf::Model& m) {
  const std::string dir = testing::temp_dir(name + "_clusters");
  const std::string in = testing::write_model(m, dir + "/in.glb");
  std::string msg;
  try {
    bake_clusters_file(in, dir + "/out.glb", ClusterBakeOptions{});
  } catch (const BakeError& e) {
    msg = e.what();
  }
  EXPECT_FALSE(fs::exists(dir + "/out.glb")) << name;
  return msg;
}

// The same edit refused by the chain bake and the cluster bake with `message`, no output left.
void expect_both_bakes_refuse(const std::string& name, const std::function<void(tinygltf::Model&)>& edit,
                              const std::string& message) {
  EXPECT_HAS(bake_edited(name, edit), message);
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  edit(m);
  EXPECT_HAS(clusters_error(name, m), message);
}

TEST(BakeErrors, MissingFile) {
  const std::string dir = testing::temp_dir("err_missing");
  const std::string m = bake_error(dir + "/nope.glb", dir + "/out.glb");
  EXPECT_HAS(m, dir + "/nope.glb: cannot open for reading");
}

TEST(BakeErrors, EmptyFileAndDirectory) {
  const std::string dir = testing::temp_dir("err_empty");
  write_bytes(dir + "/empty.gltf", "");
  EXPECT_HAS(bake_error(dir + "/empty.gltf", dir + "/out.glb"), "empty.gltf: file is empty");
  EXPECT_HAS(bake_error(dir, dir + "/out.glb"), ": is a directory");
}

TEST(BakeErrors, TruncatedGlbNamesDeclaredAndActualLength) {
  const std::string dir = testing::temp_dir("err_trunc_glb");
  const std::string full = read_bytes(testing::write_model(testing::scene_model(), dir + "/full.glb"));
  write_bytes(dir + "/cut.glb", full.substr(0, full.size() / 2));
  const std::string m = bake_error(dir + "/cut.glb", dir + "/out.glb");
  EXPECT_HAS(m, "cut.glb: truncated GLB: header (byte 8) declares " + std::to_string(full.size()) +
                    " bytes, file has " + std::to_string(full.size() / 2));
  write_bytes(dir + "/tiny.glb", full.substr(0, 10));
  EXPECT_HAS(bake_error(dir + "/tiny.glb", dir + "/out.glb"), "tiny.glb: truncated GLB: 10 bytes");
  EXPECT_FALSE(fs::exists(dir + "/out.glb"));
}

TEST(BakeErrors, TruncatedGltfJson) {
  const std::string dir = testing::temp_dir("err_trunc_gltf");
  const std::string full = read_bytes(testing::write_model(testing::scene_model(), dir + "/full.gltf"));
  write_bytes(dir + "/cut.gltf", full.substr(0, full.size() / 3));
  const std::string m = bake_error(dir + "/cut.gltf", dir + "/out.glb");
  EXPECT_HAS(m, "cut.gltf: invalid glTF: ");
}

TEST(BakeErrors, MissingPosition) {
  const std::string m = bake_edited("nopos", [](tinygltf::Model& g) {
    auto& at = g.meshes[0].primitives[0].attributes;  // tinygltf needs some attribute
    at["TEXCOORD_0"] = at["POSITION"];
    at.erase("POSITION");
  });
  EXPECT_HAS(m, "in.glb: mesh 0 'M' primitive 0: has no POSITION attribute");
}

TEST(BakeErrors, SparseAccessor) {
  const std::string m = bake_edited("sparse", [](tinygltf::Model& g) {
    auto& a = g.accessors[std::size_t(g.meshes[0].primitives[0].attributes["POSITION"])];
    a.sparse.isSparse = true;
    a.sparse.count = 1;
    a.sparse.indices.bufferView = a.bufferView;
    a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.sparse.values.bufferView = a.bufferView;
  });
  EXPECT_HAS(m, "mesh 0 'M' primitive 0 POSITION (accessor 0): sparse accessors are not supported");
}

TEST(BakeErrors, UnsupportedModes) {
  // Strips and fans are read as triangle lists (cluster_gltf_test.cpp); points are not triangles.
  const std::string points =
      bake_edited("points", [](tinygltf::Model& g) { g.meshes[0].primitives[0].mode = TINYGLTF_MODE_POINTS; });
  EXPECT_HAS(points, "mesh 0 'M' primitive 0: mode 0 (POINTS) is not supported");
  const std::string lines =
      bake_edited("lines", [](tinygltf::Model& g) { g.meshes[0].primitives[0].mode = TINYGLTF_MODE_LINE; });
  EXPECT_HAS(lines, "mode 1 (LINES) is not supported");
}

TEST(BakeErrors, MeshWithoutPrimitivesNamesItsJsonPath) {
  // Read as no primitives (as tinygltf reads a "primitives" that is not an array): refused on
  // load, before a bake could write the invalid mesh back.
  const std::string m = bake_edited("noprims", [](tinygltf::Model& g) { g.meshes[0].primitives.clear(); });
  EXPECT_HAS(m, "in.glb: /meshes/0/primitives: a mesh needs at least one primitive");
}

TEST(BakeErrors, CompressedGeometryIsNamed) {
  // As assimp-testmodels' draco/2CylinderEngine.gltf: tinygltf alone says "accessor[0] invalid
  // bufferView".
  const std::string m = bake_edited("draco", [](tinygltf::Model& g) {
    g.extensionsUsed = {"KHR_draco_mesh_compression"};
    g.extensionsRequired = {"KHR_draco_mesh_compression"};
  });
  EXPECT_HAS(
      m,
      "in.glb: /extensionsRequired: KHR_draco_mesh_compression (compressed geometry), which gazelod does not decode");
}

TEST(BakeErrors, IndexOutOfRange) {
  const std::string m = bake_edited("index", [](tinygltf::Model& g) {
    const auto& a = g.accessors[std::size_t(g.meshes[0].primitives[0].indices)];
    const auto& bv = g.bufferViews[std::size_t(a.bufferView)];
    const std::uint32_t bad = 1000;
    std::memcpy(g.buffers[0].data.data() + bv.byteOffset + 4 * 5, &bad, 4);
  });
  EXPECT_HAS(m, "mesh 0 'M' primitive 0: index 5 is 1000, but there are only 162 vertices");
}

TEST(BakeErrors, AccessorPastItsBuffer) {
  const std::string m = bake_edited("range", [](tinygltf::Model& g) {
    g.accessors[std::size_t(g.meshes[0].primitives[0].attributes["POSITION"])].count += 10;
  });
  EXPECT_HAS(m, "POSITION (accessor 0): reads past the end of its bufferView 0");
}

// Attributes the bakes copy unread (here TEXCOORD_0 over the positions' bytes) are checked too:
// before, a bake wrote them out as they were, a file that reads past its buffer.
TEST(BakeErrors, CarriedAttributesAreChecked) {
  const auto texcoord = [](std::size_t byte_offset, std::size_t count) {
    return [=](tinygltf::Model& g) {
      tinygltf::Accessor uv = g.accessors[0];
      uv.type = TINYGLTF_TYPE_VEC2, uv.byteOffset = byte_offset, uv.count = count;
      uv.minValues.clear(), uv.maxValues.clear();
      g.accessors.push_back(uv);
      g.meshes[0].primitives[0].attributes["TEXCOORD_0"] = int(g.accessors.size() - 1);
    };
  };
  // POSITION: 162 VEC3 floats, 1944 bytes; 162 VEC2 floats from byte 652 end 4 bytes past them.
  expect_both_bakes_refuse("uv_past", texcoord(652, 162),
                           "TEXCOORD_0 (accessor 2): reads past the end of its bufferView 0");
  expect_both_bakes_refuse("uv_count", texcoord(0, 161),
                           "TEXCOORD_0 accessor 2 has 161 elements, but the primitive has 162");
  // A line primitive the cluster bake carries over: its indices are checked as well.
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  tinygltf::Primitive lines = m.meshes[0].primitives[0];
  lines.mode = TINYGLTF_MODE_LINE;
  const auto& bv = m.bufferViews[std::size_t(m.accessors[std::size_t(lines.indices)].bufferView)];
  const std::uint32_t bad = 999;
  std::memcpy(m.buffers[0].data.data() + bv.byteOffset + 4 * 3, &bad, 4);
  m.meshes[0].primitives.push_back(lines);
  m.meshes[0].primitives[0].indices = -1;  // the triangles stay valid, unindexed
  EXPECT_HAS(clusters_error("lines", m), "mesh 0 'M' primitive 1: index 3 is 999, but there are only 162 vertices");
}

TEST(BakeErrors, NonFloatPositionAndNonFinite) {
  const std::string q =
      bake_edited("quant", [](tinygltf::Model& g) { g.accessors[0].componentType = TINYGLTF_COMPONENT_TYPE_SHORT; });
  EXPECT_HAS(q, "POSITION accessor 0 must be float VEC3");
  const std::string nan = bake_edited("nan", [](tinygltf::Model& g) {
    const float x = NAN;
    std::memcpy(g.buffers[0].data.data() + g.bufferViews[0].byteOffset + 12 * 7 + 4, &x, 4);
  });
  EXPECT_HAS(nan, "mesh 0 'M' primitive 0: POSITION 7 is not finite");
}

TEST(BakeErrors, IndexCountNotTriangles) {
  const std::string m = bake_edited(
      "count", [](tinygltf::Model& g) { g.accessors[std::size_t(g.meshes[0].primitives[0].indices)].count -= 1; });
  EXPECT_HAS(m, "959 indices is not a whole number of triangles");
}

TEST(BakeErrors, UnwritableOutputLeavesNothingBehind) {
  const std::string dir = testing::temp_dir("err_output");
  const std::string in = testing::write_model(testing::scene_model(), dir + "/in.glb");
  try {
    bake_file(in, dir + "/missing/out.glb", BakeOptions{});
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_HAS(std::string(e.what()), "missing/out.glb: output folder");
  }
  fs::create_directory(dir + "/isdir.glb");
  try {
    bake_file(in, dir + "/isdir.glb", BakeOptions{});
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_HAS(std::string(e.what()), "isdir.glb: output is a directory");
  }
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);  // in.glb only: no temporary left
}

TEST(BakeErrors, FailedBakeKeepsAnExistingOutput) {
  const std::string dir = testing::temp_dir("err_keep");
  write_bytes(dir + "/out.glb", "previous");
  write_bytes(dir + "/bad.gltf", "{\"asset\":{\"version\":\"2.0\"},");
  EXPECT_NE(bake_error(dir + "/bad.gltf", dir + "/out.glb"), "");
  EXPECT_EQ(read_bytes(dir + "/out.glb"), "previous");
}

TEST(BakeErrors, BadOptions) {
  const std::string dir = testing::temp_dir("err_options");
  const std::string in = testing::write_model(testing::scene_model(), dir + "/in.glb");
  BakeOptions o;
  o.chain.ratios = {0.5, 0.7};
  try {
    bake_file(in, dir + "/out.glb", o);
    FAIL() << "no error";
  } catch (const BakeError& e) {
    EXPECT_HAS(std::string(e.what()), "ratios must decrease strictly");
  }
  EXPECT_FALSE(fs::exists(dir + "/out.glb"));
}

}  // namespace
}  // namespace gazelod::bake

namespace gazelod::bake {
namespace {

// The output may not be a file the input reads: a .gltf's own .bin was overwritten (exit 0) and
// the next bake of that input failed on the buffer's size. Both bakes, before they bake.
TEST(BakeErrors, OutputOverTheInputsBufferIsRefused) {
  const std::string dir = testing::temp_dir("err_over_buffer");
  tinygltf::Model m = testing::single_mesh_model(testing::icosphere(2, 1.0));
  m.buffers[0].uri = "in.bin";
  tinygltf::TinyGLTF w;
  ASSERT_TRUE(w.WriteGltfSceneToFile(&m, dir + "/in.gltf", true, false, true, false));
  ASSERT_TRUE(fs::exists(dir + "/in.bin"));
  const auto size = fs::file_size(dir + "/in.bin");
  EXPECT_HAS(bake_error(dir + "/in.gltf", dir + "/./in.bin"), "the bake would write over its own input");
  std::string msg;
  try {
    bake_clusters_file(dir + "/in.gltf", dir + "/in.bin", ClusterBakeOptions{});
  } catch (const BakeError& e) {
    msg = e.what();
  }
  EXPECT_HAS(msg, "the bake would write over its own input");
  EXPECT_EQ(fs::file_size(dir + "/in.bin"), size) << "the buffer was written over";
  bake_file(dir + "/in.gltf", dir + "/out.glb", BakeOptions{});  // still bakes elsewhere
  EXPECT_TRUE(fs::exists(dir + "/out.glb"));
}

// A node without a mesh (tinygltf writes a node with no field set as null, not {}).
tinygltf::Node named_node() {
  tinygltf::Node n;
  n.name = "empty";
  return n;
}

// The scene graph `run --scene` needs, checked by the loader both bakes share: the same
// BakeError from chains and --clusters, and no output (they wrote such files with exit 0).
TEST(BakeErrors, SceneGraphProblemsAreRefusedByBothBakes) {
  struct GraphCase {
    const char* name;
    std::function<void(tinygltf::Model&)> edit;
    const char* message;
  };
  const std::vector<GraphCase> cases = {
      {"cycle",
       [](tinygltf::Model& m) {
         m.nodes.push_back(m.nodes[0]);
         m.nodes[0].children = {1};
         m.nodes[1].children = {0};
       },
       "node graph has a cycle"},
      {"child", [](tinygltf::Model& m) { m.nodes[0].children = {7}; }, "/nodes/0/children/0: no node 7"},
      // glTF 2.0 allows one parent per node: shared children made the walks exponential.
      {"two_parents",
       [](tinygltf::Model& m) {
         m.nodes.push_back(named_node());
         m.nodes[0].children = {1, 1};
       },
       "/nodes/0/children/1: node 1 is already a child of node 0"},
      {"scene_child",
       [](tinygltf::Model& m) {
         m.nodes.push_back(named_node());
         m.nodes[0].children = {1};
         m.scenes[0].nodes.push_back(1);
       },
       "node 1 is a child of node 0, not a root"},
      {"default_scene", [](tinygltf::Model& m) { m.defaultScene = 3; }, "/scene: no scene 3 (the file has 1)"},
      // Deep enough to overflow the stack of the walks after loading (20 000 did).
      {"deep",
       [](tinygltf::Model& m) {
         for (int i = 1; i <= 1100; ++i) {
           m.nodes.push_back(named_node());
           m.nodes[static_cast<std::size_t>(i - 1)].children = {i};
         }
       },
       "node graph deeper than 1024 levels"},
      {"deep_json",
       [](tinygltf::Model& m) {
         tinygltf::Value v(1.0);
         for (int i = 0; i < 300; ++i) v = tinygltf::Value(tinygltf::Value::Array{v});
         m.nodes[0].extras = v;
       },
       "JSON nested deeper than 256 levels"},
      {"scene", [](tinygltf::Model& m) { m.scenes[0].nodes.push_back(9); }, "/scenes/0/nodes/1: no node 9"},
      {"mesh", [](tinygltf::Model& m) { m.nodes[0].mesh = 5; }, "/nodes/0/mesh: no mesh 5"},
      {"zero_scale",
       [](tinygltf::Model& m) {
         m.nodes[0].scale = {1.0, 0.0, 1.0};
       },
       "collapses the node"},
      {"huge_scale",
       [](tinygltf::Model& m) {
         m.nodes[0].scale = {1e200, 1e200, 1e200};
       },
       "scale or matrix too large"},
      {"zero_matrix", [](tinygltf::Model& m) { m.nodes[0].matrix.assign(16, 0.0); }, "matrix is singular"},
      // (No NaN case: JSON cannot carry one; a rotation of zeros collapses the node too.)
      {"zero_rotation",
       [](tinygltf::Model& m) {
         m.nodes[0].rotation = {0.0, 0.0, 0.0, 0.0};
       },
       "a zero quaternion"},
  };
  for (const GraphCase& c : cases) expect_both_bakes_refuse(std::string("graph_") + c.name, c.edit, c.message);
}

}  // namespace
}  // namespace gazelod::bake

namespace gazelod::bake {
namespace {

// What run --scene would refuse is refused by both bakes with one message: positions whose
// size makes every distance and bound overflow, and a file whose triangles are all degenerate.
TEST(BakeErrors, HugePositionsAndAllDegenerateRefusedByBothBakes) {
  struct GeometryCase {
    const char* name;
    std::function<void(tinygltf::Model&)> edit;
    const char* message;
  };
  const std::vector<GeometryCase> cases = {
      {"huge",
       [](tinygltf::Model& g) {
         const float x = 3e38f;
         std::memcpy(g.buffers[0].data.data() + g.bufferViews[0].byteOffset + 12 * 7, &x, 4);
       },
       "mesh 0 'M' primitive 0: POSITION 7 is out of range"},
      {"degenerate",
       [](tinygltf::Model& g) {
         // Every triangle's first two corners at one vertex.
         auto& acc = g.accessors[std::size_t(g.meshes[0].primitives[0].indices)];
         const auto& view = g.bufferViews[std::size_t(acc.bufferView)];
         const std::size_t size = acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT     ? 4
                                  : acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                                                                                : 1;
         for (std::size_t t = 0; t < acc.count / 3; ++t) {
           unsigned char* p = g.buffers[0].data.data() + view.byteOffset + acc.byteOffset + 3 * size * t;
           std::memcpy(p + size, p, size);
         }
       },
       "nothing to bake: no triangle primitive has a triangle left once degenerate ones"},
  };
  for (const GeometryCase& c : cases) expect_both_bakes_refuse(std::string("geom_") + c.name, c.edit, c.message);
}

}  // namespace
}  // namespace gazelod::bake
