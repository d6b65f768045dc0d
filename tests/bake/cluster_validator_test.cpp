// Integration: bake --clusters output checked by Khronos's glTF-Validator (npm gltf-validator,
// run with node; scripts/install-gltf-validator.sh installs it under the build folder), and a
// real model: Debian's assimp-testmodels ship Khronos's 2CylinderEngine (29 meshes, 75730
// triangles, some degenerate) and the glTF-Asset-Generator's strip and fan primitives. Tests
// skip, saying why, when node, the validator or the models are missing.
#include "bake/baked_scene.hpp"
#include "bake/cluster_bake.hpp"
#include "bake/gltf_load.hpp"
#include "bake/mesh_extract.hpp"
#include "tests/bake/cluster_invariants.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::bake {
namespace {

namespace fs = std::filesystem;

const std::string kModels = "/usr/share/assimp/models/glTF2";

// The node_modules folder holding gltf-validator: $GAZELOD_GLTF_VALIDATOR_PATH, else the one
// scripts/install-gltf-validator.sh makes in the build folder; "" when there is none.
std::string validator_path() {
  if (std::system("command -v node >/dev/null 2>&1") != 0) return "";
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("GAZELOD_GLTF_VALIDATOR_PATH")) dirs.emplace_back(env);
  dirs.push_back(std::string(GAZELOD_BINARY_DIR) + "/gltf-validator/node_modules");
  for (const std::string& d : dirs)
    if (fs::exists(d + "/gltf-validator/package.json")) return d;
  return "";
}

struct Validation {
  int rc = -1;
  std::string output;
};

Validation validate(const std::string& node_path, const std::string& file) {
  const std::string log = file + ".validator.txt";
  const std::string cmd = "NODE_PATH='" + node_path + "' node '" GAZELOD_SOURCE_DIR
                          "/tests/bake/gltf_validate.js' '" + file + "' >'" + log + "' 2>&1";
  Validation v;
  const int status = std::system(cmd.c_str());
  v.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream s;
  s << in.rdbuf();
  v.output = s.str();
  return v;
}

#define SKIP_WITHOUT_VALIDATOR(path)                                                        \
  const std::string path = validator_path();                                                \
  if (path.empty())                                                                         \
  GTEST_SKIP() << "node or gltf-validator not installed (bash scripts/install-gltf-validator.sh " \
               << GAZELOD_BINARY_DIR << "/gltf-validator)"

TEST(ClusterValidator, GeneratedMeshesValidate) {
  SKIP_WITHOUT_VALIDATOR(node_path);
  const std::string dir = testing::temp_dir("clv_generated");
  for (const auto& [name, mesh] : {std::pair{"sphere", testing::icosphere(5, 0.5)},
                                   std::pair{"grid", testing::grid(100, 10.0, 1.0)}}) {
    SCOPED_TRACE(name);
    const std::string in = testing::write_model(testing::single_mesh_model(mesh), dir + "/" + name + ".glb");
    const std::string out = dir + "/" + name + "_clusters.glb";
    bake_clusters_file(in, out, ClusterBakeOptions{});
    const Validation v = validate(node_path, out);
    std::printf("%s: %s", out.c_str(), v.output.c_str());
    EXPECT_EQ(v.rc, 0) << v.output;
    EXPECT_NE(v.output.find("errors 0 warnings 0 "), std::string::npos) << v.output;
  }
}

TEST(ClusterValidator, RealModelBakesValidatesAndKeepsItsInvariants) {
  const std::string model = kModels + "/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  if (!fs::exists(model)) GTEST_SKIP() << model << " missing (Debian package assimp-testmodels)";
  const std::string out = testing::temp_dir("clv_engine") + "/engine.glb";
  const ClusterBakeReport rep = bake_clusters_file(model, out, ClusterBakeOptions{});
  std::printf("%s", format_cluster_summary(rep).c_str());
  EXPECT_EQ(rep.meshes, 29u);
  EXPECT_EQ(rep.input_triangles, 75730u);
  std::size_t degenerate = 0;
  for (const auto& p : rep.primitives) degenerate += p.degenerate_triangles;
  EXPECT_GT(degenerate, 0u) << "the model has degenerate triangles (the validator counts them)";
  // CAD parts with hard edges everywhere: with seams kept the hierarchies stop at about a third
  // of the source; stuck groups simplified across them take the tops under 5 %.
  const auto top_share = [](const ClusterBakeReport& r) {
    std::size_t top = 0, source = 0;
    for (const auto& p : r.primitives) top += p.top_triangles, source += p.source_triangles;
    return double(top) / double(source);
  };
  ClusterBakeOptions keep;
  keep.build.stuck_across_seams = false;
  const double kept_share = top_share(bake_clusters_file(model, out + ".kept.glb", keep));
  std::printf("top clusters: %.3f of the source triangles, %.3f with seams kept\n", top_share(rep), kept_share);
  EXPECT_LT(top_share(rep), 0.05);
  EXPECT_GT(kept_share, 0.2);
  EXPECT_GT(rep.groups_across_seams, 0u);

  const BakedScene scene = load_baked(out);
  EXPECT_EQ(scene.cluster_meshes.size(), 29u);
  const tinygltf::Model original = load_gltf(model).model;
  const auto locks = testing::meeting_vertices_of(original);
  for (const BakedClusterMesh& m : scene.cluster_meshes)
    for (const BakedClusterPrimitive& p : m.primitives) {
      SCOPED_TRACE(primitive_label(original, m.mesh, p.primitive));
      const PrimitiveGeometry g = extract_primitive(original, m.mesh, p.primitive);
      ClusterBuildOptions o;
      o.locked_vertices = locks[static_cast<std::size_t>(m.mesh)][static_cast<std::size_t>(p.primitive)];
      ClusterBuildResult r;  // what was stored, with the group links the file does not keep
      r = build_cluster_hierarchy(g.positions_xyz, g.indices, o);
      EXPECT_EQ(r.indices, p.indices);
      EXPECT_EQ(r.hierarchy.parent_error_m, p.hierarchy.parent_error_m);
      testing::expect_hierarchy_invariants(r, g.positions_xyz, g.indices, o);
    }
  if (const std::string node_path = validator_path(); !node_path.empty()) {
    const Validation in = validate(node_path, model), v = validate(node_path, out);
    std::printf("input: %soutput: %s", in.output.c_str(), v.output.c_str());
    EXPECT_EQ(v.rc, 0) << v.output;
    EXPECT_NE(v.output.find("errors 0 warnings 0 "), std::string::npos) << v.output;
  }
}

TEST(ClusterValidator, RealStripAndFanPrimitives) {
  // glTF-Asset-Generator Mesh_PrimitiveMode 04/11: strip, 05/12: fan (without / with indices).
  for (const char* n : {"04", "05", "11", "12"}) {
    const std::string model = kModels + "/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_" + n + ".gltf";
    if (!fs::exists(model)) GTEST_SKIP() << model << " missing (Debian package assimp-testmodels)";
    SCOPED_TRACE(model);
    const std::string out = testing::temp_dir(std::string("clv_mode") + n) + "/out.glb";
    const ClusterBakeReport rep = bake_clusters_file(model, out, ClusterBakeOptions{});
    ASSERT_EQ(rep.primitives.size(), 1u);
    EXPECT_EQ(rep.primitives[0].source_triangles, 2u) << "4 vertices: two triangles";
    EXPECT_EQ(load_baked(out).cluster_meshes.at(0).primitives.at(0).indices.size(), 6u);
    if (const std::string node_path = validator_path(); !node_path.empty()) {
      const Validation v = validate(node_path, out);
      EXPECT_EQ(v.rc, 0) << v.output;
    }
  }
}

}  // namespace
}  // namespace gazelod::bake
