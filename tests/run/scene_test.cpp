// SPDX-License-Identifier: Apache-2.0
// `gazelod bake` then `gazelod run --scene`: LOD comes from the baked chains.
#include "run_test_util.hpp"

#include "bake/baked_scene.hpp"
#include "render/lod_palette.hpp"
#include "render/lod_key.hpp"
#include "render/png_io.hpp"
#include "tests/bake/test_meshes.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace gazelod::test {
namespace {

TEST(RunScene, BakedGlbDrivesTheLods) {
  const auto dir = scratch_dir();
  const std::string in = bake::testing::write_model(bake::testing::scene_model(), (dir / "scene.glb").string());
  const std::string out = (dir / "baked.glb").string();
  CliResult r = run_cli({"bake", in, "-o", out});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto baked = bake::load_baked_scene(out);
  ASSERT_FALSE(baked.empty());
  std::uint64_t full = 0;
  for (const auto& b : baked) full += b.lods.front().triangles;

  use_simulated_runtime("");
  r = run_cli({"run", "--scene", out, "--frames", "30", "--out", (dir / "run").string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary.at("frames").get<int>(), 30);
  // Full detail is the baked scene's, every frame: the scenario's own objects are gone.
  EXPECT_EQ(summary.at("triangles_full").get<std::uint64_t>(), full * 30);
  EXPECT_LE(summary.at("triangles_drawn").get<std::uint64_t>(), full * 30);

  r = run_cli({"run", "--scene", (dir / "missing.glb").string(), "--frames", "5", "--out", (dir / "r2").string()});
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find("missing.glb"), std::string::npos) << r.err;
}

// frame.png draws a baked object with its levels' own triangles: two flat 4 m x 4 m walls 6 m
// ahead (the second mirrored by its node's scale, so its triangles must be turned over to face
// the viewer) each cover a square, which a stand-in sphere (a disc around the square's corners)
// would not: the covered pixels fill each wall's box.
TEST(RunScene, RenderedFrameDrawsTheBakedTriangles) {
  const auto dir = scratch_dir();
  tinygltf::Model model = bake::testing::single_mesh_model(bake::testing::grid(8, 4.0, 0.0));
  model.nodes[0].name = "Left";
  model.nodes[0].translation = {-4.5, -2.0, -6.0};
  tinygltf::Node mirrored;
  mirrored.name = "Right", mirrored.mesh = 0, mirrored.scale = {-1.0, 1.0, 1.0};
  mirrored.translation = {4.5, -2.0, -6.0};
  model.nodes.push_back(mirrored);
  model.scenes[0].nodes.push_back(1);
  const std::string in = bake::testing::write_model(model, (dir / "walls.glb").string());
  const std::string baked = (dir / "walls-baked.glb").string();
  CliResult r = run_cli({"bake", in, "-o", baked});
  ASSERT_EQ(r.rc, 0) << r.err;
  const std::string scenario = (dir / "still.json").string();
  std::ofstream(scenario) << R"({"version": 1, "name": "still", "display": "questpro", "duration_s": 1,
    "frame_rate_hz": 90, "seed": 1, "scene": {"objects": []}, "effects": []})";

  use_simulated_runtime("");
  r = run_cli({"run", "--scene", baked, "--scene-placement", "file", "--scenario", scenario, "--frames", "3", "--out",
               (dir / "run").string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const render::RgbaImage img = render::without_lod_key(render::read_png(dir / "run" / "frame.png"));
  ASSERT_GT(img.width, 0u);
  // Per half of the image (left wall, right wall): covered pixels and their box.
  for (const bool right : {false, true}) {
    SCOPED_TRACE(right ? "the mirrored wall" : "the wall");
    std::uint32_t x0 = img.width, x1 = 0, y0 = img.height, y1 = 0;
    std::size_t covered = 0;
    for (std::uint32_t y = 0; y < img.height; ++y)
      for (std::uint32_t x = right ? img.width / 2 : 0; x < (right ? img.width : img.width / 2); ++x) {
        const glm::vec3 c = img.rgb(x, y);
        // The level tints are saturated; the background and the circle's white (and their
        // blend at the dots' edges) are grey.
        if (glm::length(c - render::background_colour()) < 0.05f ||
            std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) < 0.15f)
          continue;
        ++covered;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    ASSERT_GT(covered, 1000u) << "the wall is not drawn";
    const double box = double(x1 - x0 + 1) * double(y1 - y0 + 1);
    EXPECT_GT(double(covered) / box, 0.95) << "a square fills its box; a disc fills pi/4 of it";
    const double aspect = double(x1 - x0 + 1) / double(y1 - y0 + 1);
    EXPECT_GT(aspect, 0.6);
    EXPECT_LT(aspect, 1.4);
  }
}

}  // namespace
}  // namespace gazelod::test
