// SPDX-License-Identifier: Apache-2.0
// gazelod eval gltfpack through gazelod::cli::run: the bake's chain beside meshoptimizer's
// gltfpack (Debian package gltfpack; the tests that run it skip, saying why, without it).
#include "tests/cli_run.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "tests/bake/test_meshes.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

namespace gazelod::cli {
namespace {

using test::run_cli;

#define EXPECT_HAS(haystack, needle) EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

bool have_gltfpack() {
  return std::system("command -v gltfpack >/dev/null 2>&1") == 0;
}

TEST(CliEvalGltfpack, OneMeshAgreesWithGltfpack) {
  if (!have_gltfpack())
    GAZELOD_SKIP_OR_FAIL("gltfpack not installed (Debian package gltfpack; bash scripts/install-deps.sh)");
  const std::string dir = bake::testing::temp_dir("cli_eval_gltfpack");
  const std::string in = bake::testing::write_model(
      bake::testing::single_mesh_model(bake::testing::grid(64, 10.0, 0.5)), dir + "/grid.glb");
  const test::CliResult r =
      run_cli({"eval", "gltfpack", in, "--ratios", "0.25", "0.0625", "--out", dir + "/out", "--work", dir + "/work"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_HAS(r.err, "gazelod eval gltfpack [");
  EXPECT_HAS(r.out, "| gazelod bake | 0.25 |");
  EXPECT_HAS(r.out, "| gltfpack -sa | 0.0625 |");
  std::ifstream f(dir + "/out/gltfpack.json");
  const nlohmann::json j = nlohmann::json::parse(f);
  EXPECT_EQ(j.at("source_triangles").get<std::size_t>(), 2u * 64u * 64u);
  // One mesh, the same meshoptimizer: both tools reach the ratio with about the same triangles
  // and error (gltfpack re-indexes first, so not to the triangle).
  std::map<std::pair<std::string, double>, nlohmann::json> rows;
  for (const nlohmann::json& row : j.at("rows")) rows[{row.at("tool"), row.at("ratio")}] = row;
  for (const double ratio : {0.25, 0.0625}) {
    SCOPED_TRACE(ratio);
    const nlohmann::json &ours = rows.at({"gazelod bake", ratio}), &peer = rows.at({"gltfpack -sa", ratio});
    const double t_ours = ours.at("triangles"), t_peer = peer.at("triangles");
    EXPECT_NEAR(t_ours, ratio * 8192.0, 0.02 * ratio * 8192.0);
    EXPECT_NEAR(t_peer, t_ours, 0.05 * t_ours);
    const double e_ours = ours.at("source_to_result").at("max_m"), e_peer = peer.at("source_to_result").at("max_m");
    EXPECT_GT(e_ours, 0.0);
    EXPECT_LT(e_ours, 2.0 * e_peer + 1e-6);
    EXPECT_LT(e_peer, 2.0 * e_ours + 1e-6);
    EXPECT_LT(ours.at("result_to_source").at("max_m").get<double>(), 1e-5);  // vertices stay on the source
  }
}

TEST(CliEvalGltfpack, SaysWhatIsMissing) {
  const std::string dir = bake::testing::temp_dir("cli_eval_gltfpack_bad");
  const std::string in =
      bake::testing::write_model(bake::testing::single_mesh_model(bake::testing::icosphere(1, 1.0)), dir + "/s.glb");
  test::CliResult r = run_cli({"eval", "gltfpack", in, "--gltfpack", dir + "/no-such-gltfpack", "--out", dir + "/o"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_HAS(r.err, "--gltfpack: cannot run '" + dir + "/no-such-gltfpack' (Debian package gltfpack");
  r = run_cli({"eval", "gltfpack", dir + "/missing.glb", "--out", dir + "/o"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "MODEL: '" + dir + "/missing.glb' is not a file");
  r = run_cli({"eval", "gltfpack", in, "--ratios", "0.5", "0.6", "--out", dir + "/o"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_HAS(r.err, "--ratios: each in (0, 1), strictly decreasing; got 0.6");
}

}  // namespace
}  // namespace gazelod::cli
