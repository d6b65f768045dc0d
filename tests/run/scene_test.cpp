// `gazelod bake` then `gazelod run --scene`: LOD comes from the baked chains.
#include "run_test_util.hpp"

#include "bake/baked_scene.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace gazelod::test
