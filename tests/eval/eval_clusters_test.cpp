// SPDX-License-Identifier: Apache-2.0
// gazelod eval clusters end to end on the simulated runtime (headless, a small generated
// terrain, a few frames of the terrain walk): the three columns, files, and bad input.
#include "apps/gazelod/commands/command.hpp"
#include "tests/held_by_another_process.hpp"
#include "tests/interrupt_when_handled.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace gazelod::cli {
namespace {

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

struct Result {
  int rc = 0;
  std::string out, err;
};

Result cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  Result r;
  r.rc = run(args, out, err);
  r.out = out.str(), r.err = err.str();
  return r;
}

std::filesystem::path scratch(const std::string& name) {
  auto dir = std::filesystem::path(GAZELOD_BINARY_DIR) / "test-scratch" / ("eval_clusters." + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

const std::string kWalk = std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/terrain-walk.json";

TEST(EvalClusters, ThreeColumnsSideBySide) {
  ::setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
  const auto dir = scratch("smoke");
  const Result r = cli({"eval", "clusters", "--triangles", "20000", "--frames", "45", "--render-frames", "0",
                        "--scenario", kWalk, "--out", (dir / "out").string(), "--work", (dir / "work").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_HAS(r.err, "gazelod eval clusters [");
  EXPECT_HAS(r.err, "gazelod bake --clusters ");
  EXPECT_HAS(r.out, "| triangles drawn per frame (mean, per eye) |");
  EXPECT_HAS(r.out, "Target (cluster LOD <= 1/3");
  std::ifstream in(dir / "out" / "clusters.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const char* key : {"per_object", "per_object_cluster_rule", "clusters"}) {
    SCOPED_TRACE(key);
    ASSERT_TRUE(j.contains(key));
    EXPECT_EQ(j[key]["frames"], 45);
    const double share = j[key]["share_of_full"];
    EXPECT_GT(share, 0.0);
    EXPECT_LE(share, 1.0);
    EXPECT_GE(j[key]["audit_unit_frames"].get<double>(), 1.0);
    const double in_view = j[key]["in_view_triangles_per_frame"];  // a part of what is drawn
    EXPECT_GT(in_view, 0.0);
    EXPECT_LE(in_view, j[key]["triangles_per_frame"].get<double>());
  }
  EXPECT_GT(j["in_view_triangle_ratio"].get<double>(), 0.0);
  // One mesh around the viewer: under the cluster rule its one level must be the finest
  // (the nearest point is under the eye); the clusters draw less than that.
  EXPECT_DOUBLE_EQ(j["per_object_cluster_rule"]["share_of_full"], 1.0);
  EXPECT_LT(j["clusters"]["share_of_full"].get<double>(), 1.0);
  EXPECT_GT(j["triangle_ratio_same_rule"].get<double>(), 0.0);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "clusters.svg"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "clusters.md"));
  EXPECT_TRUE(std::filesystem::exists(dir / "work" / "clusters" / "summary.json"));  // --work is kept
}

TEST(EvalClusters, BadInputSaysWhatAndWritesNothing) {
  const auto dir = scratch("bad");
  const std::string out = (dir / "out").string();
  Result r = cli({"eval", "clusters", "--scenario", (dir / "none.json").string(), "--out", out});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--scenario: '" + (dir / "none.json").string() + "' is not a file");
  r = cli({"eval", "clusters", "--scenario", kWalk, "--scene-source", (dir / "none.glb").string(), "--out", out});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--scene-source: ");
  std::ofstream(dir / "some.glb") << "not a glb";
  r = cli({"eval", "clusters", "--scenario", kWalk, "--scene-source", (dir / "some.glb").string(), "--tiles", "2",
           "--out", out});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--tiles: only for the generated terrain");
  r = cli({"eval", "clusters", "--scenario", kWalk, "--scene-source", (dir / "some.glb").string(), "--out", out});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "failed (exit 2)");
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "clusters.md"));
}

// --out is held as `run`, `compare` and `eval family` hold theirs: another gazelod writing
// there is refused before anything is made or written.
TEST(EvalClusters, HeldOutFolderIsRefused) {
  const auto dir = scratch("held");
  const auto out = dir / "out";
  std::filesystem::create_directories(out);
  test::HeldByAnotherProcess other(out.string());
  ASSERT_TRUE(other.locked());
  const Result r = cli({"eval", "clusters", "--triangles", "2000", "--frames", "3", "--render-frames", "0",
                        "--scenario", kWalk, "--out", out.string(), "--work", (dir / "work").string()});
  EXPECT_EQ(r.rc, 1) << r.err;
  EXPECT_HAS(r.err, "--out: '" + out.string() + "' is being written by another gazelod process");
  EXPECT_TRUE(std::filesystem::is_empty(out));
  EXPECT_FALSE(std::filesystem::exists(dir / "work")) << "work began before --out was held";
}

// Ctrl-C during the bakes and runs (minutes at the default size): exit 128 + SIGINT, no
// report, and the temporary work folder (the bakes, hundreds of MB at 20 M triangles) removed.
// Without a handler the default action ended the process and left the folder in /tmp.
TEST(EvalClusters, StoppedBySignalLeavesNoReportAndNoWorkFolder) {
  ::setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
  const auto dir = scratch("signal");
  const auto work = std::filesystem::temp_directory_path() / ("gazelod-eval-clusters-" + std::to_string(::getpid()));
  Result r;
  std::thread eval([&] {
    r = cli({"eval", "clusters", "--triangles", "20000", "--frames", "45", "--render-frames", "0", "--scenario", kWalk,
             "--out", (dir / "out").string()});
  });
  EXPECT_TRUE(test::interrupt_when_handled(SIGINT));
  eval.join();
  EXPECT_EQ(r.rc, 128 + SIGINT) << r.err;
  EXPECT_HAS(r.err, "stopped by SIGINT during ");
  EXPECT_HAS(r.err, "; no report written");
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "clusters.md"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "clusters.json"));
  EXPECT_FALSE(std::filesystem::exists(work)) << "the temporary work folder was left";
  struct sigaction after {};
  ::sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, SIG_DFL) << "the command's handler was left in place";
}

}  // namespace
}  // namespace gazelod::cli
