// SPDX-License-Identifier: Apache-2.0
// Generated test scenes (bake/terrain_mesh.hpp, bake/city_mesh.hpp, bake/generated_scene.hpp)
// and `gazelod scene generate`: sizes, determinism by seed, the flat path, orientation, tile
// seams, the glTF written, bad options and unwritable outputs.
#include "bake/bake_error.hpp"
#include "bake/gltf_load.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/city_mesh.hpp"
#include "bake/fractal_noise.hpp"
#include "bake/generated_scene.hpp"
#include "bake/terrain_mesh.hpp"
#include "tests/bake/test_meshes.hpp"
#include "tests/cli_run.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <set>

namespace gazelod::bake {
namespace {

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

// The y component of each triangle's (b - a) x (c - a), i.e. its winding seen from above.
std::size_t triangles_facing_down(const GeneratedMesh& m) {
  std::size_t down = 0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const float* a = &m.positions[3 * m.indices[t]];
    const float* b = &m.positions[3 * m.indices[t + 1]];
    const float* c = &m.positions[3 * m.indices[t + 2]];
    const double ny = double(b[2] - a[2]) * (c[0] - a[0]) - double(b[0] - a[0]) * (c[2] - a[2]);
    if (ny <= 0.0) ++down;
  }
  return down;
}

TEST(FractalNoise, BoundedDeterministicAndSeeded) {
  FractalNoiseOptions o;
  EXPECT_EQ(fractal_noise_error(o), "");
  o.octaves = 0;
  EXPECT_NE(fractal_noise_error(o), "");
  o = FractalNoiseOptions{};
  double lo = 1, hi = -1, diff = 0;
  for (int i = 0; i < 2000; ++i) {
    const double x = 0.37 * i, y = -0.11 * i;
    const double v = fractal_noise(o, x, y);
    lo = std::min(lo, v), hi = std::max(hi, v);
    EXPECT_EQ(v, fractal_noise(o, x, y));
    FractalNoiseOptions other = o;
    other.seed = 2;
    diff = std::max(diff, std::abs(v - fractal_noise(other, x, y)));
  }
  EXPECT_GE(lo, -1.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_GT(hi - lo, 0.3);                          // not flat
  EXPECT_GT(diff, 0.1);                             // another seed, another field
  EXPECT_EQ(gradient_noise(3.0, -4.0, 1, 0), 0.0);  // zero at lattice points
  EXPECT_EQ(gradient_noise(NAN, 1.0, 1, 0), 0.0);
}

TEST(TerrainMesh, SizeBoundsPathAndOrientation) {
  TerrainOptions o;
  o.triangles = 20'000;
  const std::vector<GeneratedMesh> m = terrain_meshes(o);
  ASSERT_EQ(m.size(), 1u);
  const std::uint32_t n = terrain_quads_per_side(o);
  EXPECT_EQ(n, 100u);  // 2 * 100^2 = 20000
  EXPECT_EQ(m[0].triangles(), 20'000u);
  const GeneratedStats s = generated_stats(m);
  EXPECT_EQ(s.vertices, 101u * 101u);
  EXPECT_FLOAT_EQ(float(s.min_m[0]), -150.0f);
  EXPECT_FLOAT_EQ(float(s.max_m[2]), 150.0f);
  EXPECT_GE(s.min_m[1], -20.0);
  EXPECT_LE(s.max_m[1], 20.0);
  EXPECT_GT(s.max_m[1] - s.min_m[1], 5.0);  // hills
  EXPECT_EQ(triangles_facing_down(m[0]), 0u);
  for (std::size_t v = 0; v < m[0].positions.size(); v += 3) {
    if (std::abs(m[0].positions[v]) < o.path_half_width_m) {
      EXPECT_EQ(m[0].positions[v + 1], 0.0f);
    }
    const double len = std::hypot(m[0].normals[v], m[0].normals[v + 1], m[0].normals[v + 2]);
    EXPECT_NEAR(len, 1.0, 1e-5);
    EXPECT_GT(m[0].normals[v + 1], 0.0f);
  }
  EXPECT_EQ(terrain_height_m(o, 1.0, 40.0), 0.0);  // on the path
  // At least the triangles asked for: 20001 needs 101 quads per side.
  o.triangles = 20'001;
  EXPECT_EQ(terrain_quads_per_side(o), 101u);
  o.triangles = 1'000'000;
  EXPECT_GE(2ull * terrain_quads_per_side(o) * terrain_quads_per_side(o), 1'000'000ull);
}

TEST(TerrainMesh, DeterministicBySeedAndTilesShareSeams) {
  TerrainOptions o;
  o.triangles = 5'000;
  const auto a = terrain_meshes(o), b = terrain_meshes(o);
  EXPECT_EQ(a[0].positions, b[0].positions);
  o.seed = 2;
  EXPECT_NE(terrain_meshes(o)[0].positions, a[0].positions);
  o.seed = 1;
  o.tiles = 2;  // 50 quads per side, already even
  const auto tiled = terrain_meshes(o);
  ASSERT_EQ(tiled.size(), 4u);
  EXPECT_EQ(tiled[3].name, "terrain_1_1");
  std::set<std::array<float, 3>> whole, parts;
  for (std::size_t v = 0; v < a[0].positions.size(); v += 3)
    whole.insert({a[0].positions[v], a[0].positions[v + 1], a[0].positions[v + 2]});
  std::size_t triangles = 0;
  for (const GeneratedMesh& t : tiled) {
    triangles += t.triangles();
    for (std::size_t v = 0; v < t.positions.size(); v += 3)
      parts.insert({t.positions[v], t.positions[v + 1], t.positions[v + 2]});
  }
  EXPECT_EQ(triangles, a[0].triangles());
  EXPECT_EQ(parts, whole);  // seam vertices bit-identical on both sides, none extra
}

TEST(TerrainMesh, BadOptionsSayWhich) {
  TerrainOptions o;
  o.triangles = 1;
  EXPECT_HAS(terrain_options_error(o), "--triangles: must be in [2, 20000000], got 1");
  EXPECT_THROW(terrain_meshes(o), std::invalid_argument);
  o = TerrainOptions{};
  o.tiles = 65;
  EXPECT_HAS(terrain_options_error(o), "--tiles");
  o = TerrainOptions{};
  o.relief_m = NAN;
  EXPECT_HAS(terrain_options_error(o), "relief");
}

TEST(CityMesh, EnoughTrianglesStreetAtTheOriginOutwardFaces) {
  CityOptions o;
  o.triangles = 30'000;
  const std::vector<GeneratedMesh> m = city_meshes(o);
  ASSERT_GE(m.size(), 2u);
  EXPECT_EQ(m.back().name, "ground");
  EXPECT_GE(generated_stats(m).triangles, 30'000u);
  for (std::size_t i = 0; i + 1 < m.size(); ++i) {
    const GeneratedMesh& b = m[i];
    for (std::size_t v = 0; v < b.positions.size(); v += 3) {
      // The street along Z through the origin stays clear.
      EXPECT_GE(std::abs(b.positions[v]), 0.5 * o.street_m - 1e-4) << b.name;
      ASSERT_GE(b.positions[v + 1], 0.0f);
    }
    // Every triangle's winding agrees with its stored (outward) normal.
    for (std::size_t t = 0; t < b.indices.size(); t += 3) {
      const float* p0 = &b.positions[3 * b.indices[t]];
      const float* p1 = &b.positions[3 * b.indices[t + 1]];
      const float* p2 = &b.positions[3 * b.indices[t + 2]];
      const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const double w[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      const float* nrm = &b.normals[3 * b.indices[t]];
      ASSERT_GT(c[0] * nrm[0] + c[1] * nrm[1] + c[2] * nrm[2], 0.0) << b.name << " triangle " << t / 3;
    }
  }
  EXPECT_EQ(city_meshes(o)[0].positions, m[0].positions);  // deterministic
  o.height_min_m = 70.0;
  EXPECT_HAS(city_options_error(o), "heights");
}

TEST(GeneratedScene, WritesAGlbThatBakeReads) {
  const std::string dir = testing::temp_dir("generated_scene");
  TerrainOptions o;
  o.triangles = 2'000;
  o.tiles = 2;
  const std::vector<GeneratedMesh> meshes = terrain_meshes(o);
  write_generated_glb(meshes, dir + "/t.glb");
  // Read back as the bake reads it: the same meshes, positions and indices bit for bit.
  const LoadedGltf back = load_gltf(dir + "/t.glb");
  ASSERT_EQ(back.model.meshes.size(), 4u);
  ASSERT_EQ(back.model.nodes.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const PrimitiveGeometry g = extract_primitive(back.model, i, 0);
    EXPECT_EQ(g.positions_xyz, meshes[std::size_t(i)].positions);
    EXPECT_EQ(g.indices, meshes[std::size_t(i)].indices);
    EXPECT_EQ(back.model.nodes[std::size_t(i)].name, meshes[std::size_t(i)].name);
  }
  // Bad meshes name themselves; a missing folder leaves nothing behind.
  GeneratedMesh bad = terrain_meshes(TerrainOptions{.triangles = 8})[0];
  bad.indices[4] = 1000;
  EXPECT_THROW(
      {
        try {
          generated_model({bad});
        } catch (const std::invalid_argument& e) {
          EXPECT_HAS(std::string(e.what()),
                     "generated mesh 0 'terrain': index 4 is 1000, but there are only 9 vertices");
          throw;
        }
      },
      std::invalid_argument);
  EXPECT_THROW(write_generated_glb(terrain_meshes(o), dir + "/missing/t.glb"), OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir + "/missing"));
}

TEST(CliSceneGenerate, WritesReportsAndRefusesBadInput) {
  const std::string dir = testing::temp_dir("cli_scene_generate");
  test::CliResult r =
      test::run_cli({"scene", "generate", "terrain", dir + "/t.glb", "--triangles", "3000", "--seed", "4"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_HAS(r.out, "wrote " + dir + "/t.glb: terrain 300 x 300 m, 39 x 39 quads");
  EXPECT_HAS(r.out, "3042 triangles, 1600 vertices in 1 mesh;");
  const auto size = std::filesystem::file_size(dir + "/t.glb");
  ASSERT_EQ(test::run_cli({"scene", "generate", "terrain", dir + "/u.glb", "--triangles", "3000", "--seed", "4"}).rc,
            0);
  EXPECT_EQ(std::filesystem::file_size(dir + "/u.glb"), size);
  r = test::run_cli({"scene", "generate", "city", dir + "/c.glb", "--triangles", "5000"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_HAS(r.out, "city of ");
  EXPECT_EQ(test::run_cli({"bake", "--clusters", dir + "/t.glb", dir + "/tc.glb"}).rc, 0);

  r = test::run_cli({"scene", "generate", "terrain", dir + "/t.gltf"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "OUT: must name a .glb file");
  r = test::run_cli({"scene", "generate", "volcano", dir + "/v.glb"});
  EXPECT_EQ(r.rc, 2);
  r = test::run_cli({"scene", "generate", "terrain", dir + "/v.glb", "--triangles", "1"});
  EXPECT_EQ(r.rc, 2);
  r = test::run_cli({"scene", "generate", "city", dir + "/v.glb", "--tiles", "2"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--tiles: only for terrain");
  r = test::run_cli({"scene", "generate", "terrain", dir + "/no/such/v.glb", "--triangles", "100"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_HAS(r.err, "does not exist");
  EXPECT_FALSE(std::filesystem::exists(dir + "/v.glb"));
}

}  // namespace
}  // namespace gazelod::bake
