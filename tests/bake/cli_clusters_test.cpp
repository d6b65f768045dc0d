// SPDX-License-Identifier: Apache-2.0
// gazelod bake --clusters through gazelod::cli::run: progress with throughput, summary, the
// output form (second argument or -o), usage errors, exit codes.
#include "tests/cli_run.hpp"
#include "bake/baked_scene.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "tests/bake/test_meshes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace gazelod::cli {
namespace {

using test::run_cli;

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

struct Paths {
  std::string dir, in, out;
};

Paths scene(const std::string& test) {
  Paths p;
  p.dir = bake::testing::temp_dir(test);
  p.in = bake::testing::write_model(bake::testing::scene_model(), p.dir + "/in.gltf");
  p.out = p.dir + "/out.glb";
  return p;
}

TEST(CliBakeClusters, BakesWithProgressAndSummary) {
  const Paths p = scene("cli_clusters");
  const test::CliResult r = run_cli({"bake", "--clusters", p.in, p.out});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_HAS(r.err, "bake: building 3 primitives of 2 meshes (0 large ones alone, the rest side by side on ");
  EXPECT_HAS(r.err, " done: mesh 0 'Sphere': 5120 triangles -> ");  // the meshes finish in either order
  EXPECT_HAS(r.err, " done: mesh 1 'Wavy': 2048 triangles -> ");
  EXPECT_HAS(r.err, "input triangles/s); overall 50%");
  EXPECT_HAS(r.err, "overall 100%");
  EXPECT_HAS(r.err, "bake: writing " + p.out);
  EXPECT_HAS(r.out, "mesh 1 'Wavy' primitive 1");
  EXPECT_HAS(r.out, "total: 2 meshes, 3 primitives with GAZELOD_cluster_lod, 7168 input triangles, hierarchy ");
  // A good run ends with its total (notes and warnings come before it).
  const std::size_t last = r.out.rfind('\n', r.out.size() - 2);
  EXPECT_EQ(r.out.compare(last == std::string::npos ? 0 : last + 1, 6, "total:"), 0) << r.out;
  const bake::BakedScene s = bake::load_baked(p.out);
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.cluster_meshes.size(), 2u);
  // -o works as well.
  EXPECT_EQ(run_cli({"bake", p.in, "--clusters", "-o", p.dir + "/o.glb"}).rc, 0);
  EXPECT_TRUE(std::filesystem::exists(p.dir + "/o.glb"));
}

TEST(CliBakeClusters, UsageErrors) {
  const Paths p = scene("cli_clusters_usage");
  test::CliResult r = run_cli({"bake", "--clusters", p.in, p.out, "--levels", "3"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--clusters: cannot be combined with --levels");
  r = run_cli({"bake", "--clusters", p.in, p.out, "--profile", "6"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--clusters: cannot be combined with --profile");
  r = run_cli({"bake", "--clusters", p.in, p.out, "-o", p.dir + "/other.glb"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--output: give the output once");
  r = run_cli({"bake", "--clusters", p.in});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--output: missing");
  EXPECT_FALSE(std::filesystem::exists(p.out));
}

// --threads changes how long a bake takes, not what it writes: byte for byte, on a terrain
// large enough that every level but the last few has groups for several threads.
TEST(CliBakeClusters, SameFileOnAnyThreadCount) {
  const std::string dir = bake::testing::temp_dir("cli_clusters_threads");
  const std::string in = dir + "/terrain.glb";
  ASSERT_EQ(run_cli({"scene", "generate", "terrain", in, "--triangles", "100000"}).rc, 0);
  auto bytes = [](const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  std::string first;
  for (const char* threads : {"1", "3", "0"}) {
    const std::string out = dir + "/out" + threads + ".glb";
    const test::CliResult r = run_cli({"bake", "--clusters", in, out, "--threads", threads});
    ASSERT_EQ(r.rc, 0) << r.err;
    const std::string b = bytes(out);
    ASSERT_GT(b.size(), 1000u);
    if (first.empty()) first = b;
    EXPECT_TRUE(b == first) << "--threads " << threads << " wrote a different file";
  }
  test::CliResult r = run_cli({"bake", "--clusters", in, dir + "/bad.glb", "--threads", "-1"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--threads");
  r = run_cli({"bake", in, dir + "/chain.glb", "--threads", "2"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--threads: only with --clusters");
  EXPECT_FALSE(std::filesystem::exists(dir + "/bad.glb"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/chain.glb"));
}

// --fold-retries: 0 keeps meshopt's first result per group (more folds counted in the
// summary), the default 2 retries folded groups; out of range or without --clusters: refused.
TEST(CliBakeClusters, FoldRetriesOption) {
  const std::string dir = bake::testing::temp_dir("cli_clusters_folds");
  const std::string in = dir + "/city.glb";
  ASSERT_EQ(run_cli({"scene", "generate", "city", in, "--triangles", "30000"}).rc, 0);
  const auto folded = [](const std::string& summary) {
    // "note: N of the stored simplified triangles face against ... (folded over by ...)"
    const std::size_t at = summary.find(" of the stored simplified triangles face against");
    if (at == std::string::npos) return std::size_t{0};
    const std::size_t note = summary.rfind("note: ", at);
    return static_cast<std::size_t>(std::stoul(summary.substr(note + 6, at - note - 6)));
  };
  const test::CliResult none = run_cli({"bake", "--clusters", in, dir + "/r0.glb", "--fold-retries", "0"});
  ASSERT_EQ(none.rc, 0) << none.err;
  const test::CliResult two = run_cli({"bake", "--clusters", in, dir + "/r2.glb"});
  ASSERT_EQ(two.rc, 0) << two.err;
  EXPECT_GT(folded(none.out), 0u) << none.out;
  EXPECT_LT(folded(two.out), folded(none.out)) << two.out;
  test::CliResult r = run_cli({"bake", "--clusters", in, dir + "/bad.glb", "--fold-retries", "9"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--fold-retries");
  r = run_cli({"bake", in, dir + "/chain.glb", "--fold-retries", "1"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--fold-retries: only with --clusters");
  EXPECT_FALSE(std::filesystem::exists(dir + "/bad.glb"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/chain.glb"));
}

// A generated city's boxes have hard edges (split vertices): some groups only simplify across
// them, which the summary counts; --keep-seams never does; without --clusters it is refused.
TEST(CliBakeClusters, KeepSeamsOption) {
  const std::string dir = bake::testing::temp_dir("cli_clusters_seams");
  const std::string in = dir + "/city.glb";
  ASSERT_EQ(run_cli({"scene", "generate", "city", in, "--triangles", "30000"}).rc, 0);
  const std::string key = "groups simplified across attribute seams";
  const test::CliResult across = run_cli({"bake", "--clusters", in, dir + "/across.glb"});
  ASSERT_EQ(across.rc, 0) << across.err;
  EXPECT_HAS(across.out, key);
  const test::CliResult kept = run_cli({"bake", "--clusters", in, dir + "/kept.glb", "--keep-seams"});
  ASSERT_EQ(kept.rc, 0) << kept.err;
  EXPECT_EQ(kept.out.find(key), std::string::npos) << kept.out;
  EXPECT_NE(kept.out, across.out);
  const test::CliResult r = run_cli({"bake", in, dir + "/chain.glb", "--keep-seams"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--keep-seams: only with --clusters");
  EXPECT_FALSE(std::filesystem::exists(dir + "/chain.glb"));
}

TEST(CliBakeClusters, InputAndOutputErrorsHaveDistinctExitCodes) {
  const Paths p = scene("cli_clusters_io");
  test::CliResult r = run_cli({"bake", "--clusters", p.dir + "/missing.glb", p.out});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "missing.glb: cannot open for reading");
  r = run_cli({"bake", "--clusters", p.in, p.dir + "/no/such/out.glb"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_HAS(r.err, "no/such/out.glb: output folder");
}

}  // namespace
}  // namespace gazelod::cli
