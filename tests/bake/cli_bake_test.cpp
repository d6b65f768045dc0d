// SPDX-License-Identifier: Apache-2.0
// gazelod bake through gazelod::cli::run: exit codes, progress, summary, usage errors.
#include "tests/cli_run.hpp"
#include "bake/baked_scene.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

namespace gazelod::cli {
namespace {

using Result = test::CliResult;
using test::run_cli;

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

std::string scene(const std::string& test) {
  const std::string dir = bake::testing::temp_dir(test);
  return bake::testing::write_model(bake::testing::scene_model(), dir + "/in.gltf");
}

TEST(CliBake, BakesWithProgressAndSummary) {
  const std::string in = scene("cli_ok");
  const std::string out = in.substr(0, in.rfind('/')) + "/out.glb";
  const Result r = run_cli({"bake", in, "-o", out, "--levels", "3"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_HAS(r.err, "bake: mesh 1/2 mesh 0 'Sphere' (1 primitive) ...");
  EXPECT_HAS(r.err, "overall 100%");
  EXPECT_HAS(r.out, "triangles");
  EXPECT_HAS(r.out, "5120");
  EXPECT_HAS(r.out, "total: 2 meshes, 3 nodes with MSFT_lod, 7168 input triangles");
  const auto objs = bake::load_baked_scene(out);
  ASSERT_EQ(objs.size(), 3u);
  EXPECT_EQ(objs[0].lods.size(), 3u);
}

// The output naming the input (by another spelling too) would replace it: refused before reading,
// in chain and cluster mode alike, the input left as it was.
TEST(CliBake, OutputThatIsTheInputIsRefused) {
  const std::string in = scene("cli_same");
  const std::string dir = in.substr(0, in.rfind('/'));
  const auto before = std::filesystem::file_size(in);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"bake", in, "-o", in}, {"bake", in, "-o", dir + "/./in.gltf", "--clusters"}}) {
    const Result r = run_cli(args);
    EXPECT_EQ(r.rc, 2) << r.err;
    EXPECT_HAS(r.err, "is the input file");
  }
  EXPECT_EQ(std::filesystem::file_size(in), before);
}

TEST(CliBake, RatiosAndTargetError) {
  const std::string in = scene("cli_ratios");
  const std::string out = in.substr(0, in.rfind('/')) + "/out.glb";
  const Result r = run_cli({"bake", in, "-o", out, "--ratios", "0.5,0.1", "--target-error", "0.5", "--lock-borders"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(bake::load_baked_scene(out)[0].lods.size(), 3u);
}

TEST(CliBake, UsageErrors) {
  const std::string in = scene("cli_usage");
  const std::string out = in.substr(0, in.rfind('/')) + "/out.glb";
  Result r = run_cli({"bake", in, "-o", out, "--levels", "1"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--levels: must be in [2, 16], got 1");
  r = run_cli({"bake", in, "-o", out, "--levels", "3", "--ratios", "0.5"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "give either --levels or --ratios");
  r = run_cli({"bake", in, "-o", out, "--ratios", "0.5,abc"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--ratios: 'abc' is not a finite number");
  r = run_cli({"bake", in, "-o", out, "--ratios", "0.2,0.5"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "ratios must decrease strictly");
  r = run_cli({"bake", in, "-o", out, "--target-error", "-1"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "target error must be finite and > 0");
  r = run_cli({"bake", in});
  EXPECT_NE(r.rc, 0);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliBake, InputAndOutputErrorsHaveDistinctExitCodes) {
  const std::string in = scene("cli_io");
  const std::string dir = in.substr(0, in.rfind('/'));
  Result r = run_cli({"bake", dir + "/missing.glb", "-o", dir + "/out.glb"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "missing.glb: cannot open for reading");
  r = run_cli({"bake", in, "-o", dir + "/no/such/out.glb"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_HAS(r.err, "no/such/out.glb: output folder");
}

}  // namespace
}  // namespace gazelod::cli
