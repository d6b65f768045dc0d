// SPDX-License-Identifier: Apache-2.0
// gazelod eval clusters end to end on the simulated runtime (headless, a small generated
// terrain, a few frames of the terrain walk): the three columns, files, and bad input.
#include "apps/gazelod/commands/command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

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

}  // namespace
}  // namespace gazelod::cli
