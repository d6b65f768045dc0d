// SPDX-License-Identifier: Apache-2.0
// Integration: bake --clusters output checked by Khronos's glTF-Validator (npm gltf-validator,
// run with node; scripts/install-gltf-validator.sh installs it under the build folder), and a
// real model: Debian's assimp-testmodels ship Khronos's 2CylinderEngine (29 meshes, 75730
// triangles, some degenerate) and the glTF-Asset-Generator's strip and fan primitives. Tests
// skip, saying why, when node, the validator or the models are missing.
#include "bake/bake.hpp"
#include "bake/bake_error.hpp"
#include "bake/baked_scene.hpp"
#include "bake/cluster/cluster_bake.hpp"
#include "bake/gltf_load.hpp"
#include "bake/mesh_extract.hpp"
#include "tests/bake/cluster_invariants.hpp"
#include "tests/bake/test_meshes.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
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
  const std::string cmd = "NODE_PATH='" + node_path + "' node '" GAZELOD_SOURCE_DIR "/tests/bake/gltf_validate.js' '" +
                          file + "' >'" + log + "' 2>&1";
  Validation v;
  const int status = std::system(cmd.c_str());
  v.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream s;
  s << in.rdbuf();
  v.output = s.str();
  return v;
}

#define SKIP_WITHOUT_VALIDATOR(path)                                                                   \
  const std::string path = validator_path();                                                           \
  if (path.empty())                                                                                    \
  GAZELOD_SKIP_OR_FAIL("node or gltf-validator not installed (bash scripts/install-gltf-validator.sh " \
                       << GAZELOD_BINARY_DIR << "/gltf-validator)")

TEST(ClusterValidator, GeneratedMeshesValidate) {
  SKIP_WITHOUT_VALIDATOR(node_path);
  const std::string dir = testing::temp_dir("clv_generated");
  for (const auto& [name, mesh] :
       {std::pair{"sphere", testing::icosphere(5, 0.5)}, std::pair{"grid", testing::grid(100, 10.0, 1.0)}}) {
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
  if (!fs::exists(model)) GAZELOD_SKIP_OR_FAIL(model << " missing (Debian package assimp-testmodels)");
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
    if (!fs::exists(model)) GAZELOD_SKIP_OR_FAIL(model << " missing (Debian package assimp-testmodels)");
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

// Each file's "error codes: ..." line of a gltf_validate.js run on several files, by file.
std::map<std::string, std::set<std::string>> error_codes(const std::string& node_path,
                                                         const std::vector<std::string>& files,
                                                         const std::string& log) {
  std::string cmd = "NODE_PATH='" + node_path + "' node '" GAZELOD_SOURCE_DIR "/tests/bake/gltf_validate.js'";
  for (const std::string& f : files) cmd += " '" + f + "'";
  cmd += " >'" + log + "' 2>&1";
  (void)std::system(cmd.c_str());  // exit 1 when any file has an error: read the log instead
  std::ifstream in(log);
  std::map<std::string, std::set<std::string>> out;
  std::string file;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("== ", 0) == 0) file = line.substr(3);
    if (line.rfind("error codes:", 0) != 0) continue;
    std::istringstream codes(line.substr(12));
    std::set<std::string>& set = out[file];
    for (std::string c; codes >> c;) set.insert(c);
  }
  return out;
}

std::vector<unsigned char> image_bytes_of(const tinygltf::Model& m, const tinygltf::Image& im) {
  if (im.bufferView < 0) return im.image;
  const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(im.bufferView));
  const auto* b = m.buffers.at(static_cast<std::size_t>(v.buffer)).data.data() + v.byteOffset;
  return {b, b + v.byteLength};
}

TEST(ClusterValidator, EveryAssimpModelBakesOrSaysWhy) {
  // Every glTF 2.0 file assimp-testmodels ships (Khronos samples, the Asset Generator's modes,
  // and malformed files), through both bakes: each either succeeds, keeping every image's bytes
  // (and, --clusters, every point or line primitive as it was) and adding no validator error
  // the input did not have, or fails with a message that starts with the file's path, leaving
  // no output.
  if (!fs::exists(kModels)) GAZELOD_SKIP_OR_FAIL(kModels << " missing (Debian package assimp-testmodels)");
  std::vector<std::string> models;
  for (const auto& e : fs::recursive_directory_iterator(kModels))
    if (e.path().extension() == ".glb" || e.path().extension() == ".gltf") models.push_back(e.path().string());
  std::sort(models.begin(), models.end());
  ASSERT_GE(models.size(), 40u);
  const std::string dir = testing::temp_dir("clv_every_model");
  std::vector<std::string> validate_files;
  std::size_t baked = 0, refused = 0, chains_baked = 0;
  for (std::size_t i = 0; i < models.size(); ++i)
    for (const bool clusters : {true, false}) {
      SCOPED_TRACE(models[i] + (clusters ? " (--clusters)" : " (chains)"));
      const std::string out = dir + "/out" + std::to_string(i) + (clusters ? "c" : "") + ".glb";
      try {
        if (clusters)
          bake_clusters_file(models[i], out, ClusterBakeOptions{});
        else
          bake_file(models[i], out, BakeOptions{});
      } catch (const BakeError& e) {
        refused += clusters;
        EXPECT_EQ(std::string(e.what()).rfind(models[i] + ": ", 0), 0u) << e.what();
        EXPECT_FALSE(fs::exists(out));
        continue;
      }
      (clusters ? baked : chains_baked) += 1;
      const tinygltf::Model a = load_gltf(models[i]).model, b = load_gltf(out).model;
      ASSERT_EQ(b.images.size(), a.images.size());
      for (std::size_t k = 0; k < a.images.size(); ++k) {
        EXPECT_EQ(image_bytes_of(b, b.images[k]), image_bytes_of(a, a.images[k])) << "image " << k;
      }
      ASSERT_GE(b.meshes.size(), a.meshes.size());
      for (std::size_t mi = 0; clusters && mi < a.meshes.size(); ++mi)
        for (std::size_t p = 0; p < a.meshes[mi].primitives.size(); ++p)
          if (!draws_triangles(a.meshes[mi].primitives[p])) {
            EXPECT_EQ(b.meshes[mi].primitives[p].mode, a.meshes[mi].primitives[p].mode);
            EXPECT_TRUE(b.meshes[mi].primitives[p].extensions.empty());
          }
      validate_files.push_back(models[i]);
      validate_files.push_back(out);
    }
  std::printf("%zu models: --clusters %zu baked, %zu refused with a reason; chains %zu baked\n", models.size(), baked,
              refused, chains_baked);
  EXPECT_GE(baked, 25u);
  EXPECT_GE(chains_baked, 25u);
  const std::string node_path = validator_path();
  if (node_path.empty()) return;
  const auto codes = error_codes(node_path, validate_files, dir + "/validator.txt");
  for (std::size_t k = 0; k + 1 < validate_files.size(); k += 2) {
    const std::string &in = validate_files[k], &out = validate_files[k + 1];
    ASSERT_TRUE(codes.count(in) && codes.count(out)) << "no validator report for " << in << " or " << out;
    for (const std::string& c : codes.at(out))
      EXPECT_TRUE(codes.at(in).count(c)) << out << " (from " << in << "): validator error " << c
                                         << " that the input does not have";
  }
}

}  // namespace
}  // namespace gazelod::bake
