// SPDX-License-Identifier: Apache-2.0
// `gazelod run --cluster-select gpu` on the simulated runtime and lavapipe: a generated terrain
// (`gazelod scene generate`, `gazelod bake --clusters`, the real commands) walked by
// sim/scenarios/terrain-walk.json. The compute shader selects each eye's cut from the plugin's
// viewer and one indirect-count draw draws it; every frame the GPU's decisions are read back and
// must equal the plugin's cut (the switch policy is off for clusters on this path). The report
// says so; the options it cannot serve are usage errors.
#include "tests/run/run_test_util.hpp"

#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/run/session.hpp"
#include "render/lod_palette.hpp"
#include "render/png_io.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace gazelod::test {
namespace {

class GpuSelectRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process (CTest runs each test as its own process).
    dir_ = std::filesystem::path(GAZELOD_BINARY_DIR) / "test-scratch" / ("GpuSelectRun-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    const std::string source = (dir_ / "terrain.glb").string();
    baked_ = (dir_ / "terrain-clusters.glb").string();
    CliResult r = run_cli({"scene", "generate", "terrain", source, "--triangles", "60000"});
    ASSERT_EQ(r.rc, 0) << r.err;
    r = run_cli({"bake", "--clusters", source, baked_});
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  void SetUp() override { use_simulated_runtime(""); }
  static std::string walk() { return std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/terrain-walk.json"; }

  static std::filesystem::path dir_;
  static std::string baked_;
};
std::filesystem::path GpuSelectRun::dir_;
std::string GpuSelectRun::baked_;

TEST_F(GpuSelectRun, TheGpuDrawsThePluginsCutEveryFrame) {
  const auto out = scratch_dir();
  constexpr int kFrames = 30;
  const CliResult r =
      run_cli({"run", "--frames", std::to_string(kFrames), "--scene", baked_, "--scene-placement", "file", "--scenario",
               walk(), "--cluster-select", "gpu", "--out", out.string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("cluster GPU     selected on the GPU 60 times (0 refused viewers)"), std::string::npos) << r.out;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  const auto& c = summary.at("clusters");
  const auto& g = c.at("gpu_select");
  ASSERT_TRUE(g.at("used").get<bool>()) << g.dump();
  EXPECT_EQ(g.at("selections").get<int>(), 2 * kFrames) << "one per eye and frame";
  EXPECT_EQ(g.at("frames_compared").get<int>(), kFrames);
  const auto clusters = c.at("clusters").get<std::uint64_t>();
  ASSERT_GT(clusters, 100u);
  EXPECT_EQ(g.at("decisions_compared").get<std::uint64_t>(), kFrames * clusters);
  EXPECT_EQ(g.at("differences_from_cpu").get<std::uint64_t>(), 0u) << g.dump();
  // Some clusters drawn, far fewer commands than clusters (the cut, culled to the eye's view).
  const double commands = g.at("commands_per_selection").get<double>();
  EXPECT_GT(commands, 10.0);
  EXPECT_LT(commands, 0.5 * static_cast<double>(clusters));
  // Without the hold the drawn cut is the perceptual one.
  EXPECT_EQ(c.at("triangles_drawn").get<std::uint64_t>(), c.at("triangles_perceptual").get<std::uint64_t>());
  EXPECT_EQ(c.at("audit").at("miscovered_leaf_frames").get<std::int64_t>(), 0);
}

// A frame budget the full cut does not fit coarsens the terrain by a detail scale; the GPU
// applies each mesh's scale (the mesh block's error factor) and still draws the plugin's cut.
TEST_F(GpuSelectRun, WithAFrameBudgetTheGpuAppliesEachMeshsScale) {
  const auto out = scratch_dir();
  const CliResult r =
      run_cli({"run", "--frames", "30", "--scene", baked_, "--scene-placement", "file", "--scenario", walk(),
               "--cluster-select", "gpu", "--budget-ms", "0.5", "--out", out.string(), "--quiet", "--no-audit"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto c = nlohmann::json::parse(read_text(out / "summary.json")).at("clusters");
  EXPECT_LT(c.at("triangles_drawn").get<double>(), 0.8 * c.at("triangles_perceptual").get<double>())
      << "the budget coarsened the cut";
  const auto& g = c.at("gpu_select");
  EXPECT_EQ(g.at("selections").get<int>(), 60);
  EXPECT_EQ(g.at("selections_refused").get<int>(), 0);
  EXPECT_EQ(g.at("differences_from_cpu").get<std::uint64_t>(), 0u) << g.dump();
}

// The same frame drawn from the GPU's commands (tinted per instance by depth) and from the
// plugin's cut on the CPU (one draw per run of clusters): pixel for pixel the same image. The
// CPU run's switch policy releases at once (no hold, no waiting for a saccade), as the GPU path
// draws, so any frame compares.
TEST_F(GpuSelectRun, FramePngEqualsTheCpuPathsPixelForPixel) {
  const auto dir = scratch_dir();
  cli::RunOptions opt;
  opt.frames = 25;
  opt.capture_frame = 20;
  opt.scenario_path = walk();
  opt.scene_path = baked_;
  opt.scene_placement = "file";
  opt.quiet = true;
  opt.audit = false;
  lod::SwitchPolicyConfig at_once;
  at_once.coarsen_hold_s = 0.0;
  at_once.prefer_suppression = false;
  opt.switching = at_once;
  opt.out_dir = dir / "cpu";
  cli::RunSummary cpu, gpu;
  ASSERT_NO_THROW(cpu = cli::run_for_summary(opt, "the CPU run"));
  opt.cluster_select = "gpu";
  opt.out_dir = dir / "gpu";
  ASSERT_NO_THROW(gpu = cli::run_for_summary(opt, "the GPU run"));
  ASSERT_TRUE(gpu.clusters.gpu.used);
  EXPECT_EQ(gpu.clusters.gpu.differences, 0u);
  EXPECT_EQ(cpu.clusters.triangles_drawn, gpu.clusters.triangles_drawn) << "the same cuts";
  const render::RgbaImage a = render::read_png(dir / "cpu" / "frame.png");
  const render::RgbaImage b = render::read_png(dir / "gpu" / "frame.png");
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  std::size_t differing = 0, coloured = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) {
      differing += a.rgb(x, y) != b.rgb(x, y);
      coloured += glm::length(a.rgb(x, y) - render::background_colour()) > 0.05f;
    }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(coloured, std::size_t{a.width} * a.height / 10) << "the lower part of the view is terrain";
}

TEST_F(GpuSelectRun, WhatItCannotServeIsAUsageError) {
  const auto out = scratch_dir() / "run";
  CliResult r = run_cli({"run", "--no-render", "--frames", "3", "--scene", baked_, "--scene-placement", "file",
                         "--scenario", walk(), "--cluster-select", "gpu", "--out", out.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("--cluster-select gpu: needs rendering (not --no-render)"), std::string::npos) << r.err;
  r = run_cli({"run", "--frames", "3", "--cluster-select", "gpu", "--out", out.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("--cluster-select gpu: the scene has no cluster meshes"), std::string::npos) << r.err;
  r = run_cli({"run", "--frames", "3", "--cluster-select", "fpga", "--out", out.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("--cluster-select"), std::string::npos) << r.err;
  // A mesh the scenario moves: the GPU path draws meshes where they were registered.
  std::string moving = read_text(walk());
  const std::string effects = "\"effects\": [";
  ASSERT_NE(moving.find(effects), std::string::npos);
  moving.replace(moving.find(effects), effects.size(),
                 effects + R"({ "type": "object_motion", "object": "terrain", "velocity_m_s": [0, 0, -1] },)");
  const std::string moving_path = (scratch_dir() / "moving.json").string();
  std::ofstream(moving_path) << moving;
  r = run_cli({"run", "--frames", "3", "--scene", baked_, "--scene-placement", "file", "--scenario", moving_path,
               "--cluster-select", "gpu", "--out", out.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("--cluster-select gpu: the scenario moves cluster mesh"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
}

}  // namespace
}  // namespace gazelod::test
