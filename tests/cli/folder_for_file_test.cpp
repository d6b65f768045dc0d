// SPDX-License-Identifier: Apache-2.0
// A folder given where a command reads or writes a file is bad input, for every command: exit 2
// (docs/error-policy.md, section 5), a message naming the option and the path, refused before
// any work and with nothing written. Outputs exited 1 after the work (bake, trace convert,
// scenario record and family, scene generate, run --decisions) where inputs exited 2.
#include "tests/cli_run.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::test {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(GAZELOD_BINARY_DIR) / "test-scratch" / ("FolderForFile." + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct Case {
  std::vector<std::string> args;
  std::string message;
};

void expect_refused(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    std::string line;
    for (const std::string& a : c.args) line += a + " ";
    const CliResult r = run_cli(c.args);
    EXPECT_EQ(r.rc, 2) << line << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << line << "\n" << r.err;
    EXPECT_EQ(r.err.find(": error: "), std::string::npos) << "a raw failure, not a refusal\n" << r.err;
  }
}

TEST(FolderForFile, AsAnOutputIsBadInputRefusedBeforeTheWork) {
  const fs::path dir = fresh_dir("output");
  const fs::path adir = dir / "adir.glb";  // a folder with a file's name
  fs::create_directories(adir);
  const std::string glb = (dir / "in.glb").string(), trace = (dir / "in.csv").string();
  ASSERT_EQ(run_cli({"scene", "generate", "terrain", glb, "--triangles", "1000"}).rc, 0);
  ASSERT_EQ(run_cli({"scenario", "record", "--default", "--duration", "0.2", "--out", trace}).rc, 0);
  const std::string a = adir.string();
  const std::string is_a_dir = "cannot write '" + a + "': is a directory";
  const fs::path out = dir / "run-out";
  expect_refused({
      {{"bake", glb, "-o", a}, "--output: " + is_a_dir},
      {{"bake", glb, a, "--clusters"}, "--output: " + is_a_dir},
      {{"trace", "convert", trace, a}, "OUT: " + is_a_dir},
      {{"scenario", "record", "--default", "--duration", "0.2", "--out", a}, "--out: " + is_a_dir},
      {{"scenario", "family", "--seed", "1", "--out", a}, "--out: " + is_a_dir},
      {{"scene", "generate", "terrain", a, "--triangles", "1000"}, "OUT: " + is_a_dir},
      {{"hid", "record", "--out", a, "--seconds", "1"}, "--out: " + is_a_dir},
      {{"run", "--frames", "2", "--no-render", "--quiet", "--decisions", a, "--out", out.string()},
       "--decisions: " + is_a_dir},
  });
  EXPECT_FALSE(fs::exists(out)) << "run refused before anything was written to --out";
  EXPECT_TRUE(fs::is_empty(adir));
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// As it was already: a folder for an input file is refused with exit 2.
TEST(FolderForFile, AsAnInputIsBadInput) {
  const fs::path dir = fresh_dir("input");
  const std::string d = dir.string();
  const fs::path out = dir / "run-out";
  expect_refused({
      {{"run", "--frames", "2", "--no-render", "--quiet", "--scenario", d, "--out", out.string()},
       "--scenario: " + d + ": is a directory"},
      {{"run", "--frames", "2", "--no-render", "--quiet", "--trace", d, "--out", out.string()},
       "--trace: " + d + ": is a directory"},
      {{"run", "--frames", "2", "--no-render", "--quiet", "--scene", d, "--out", out.string()},
       "--scene: " + d + ": is a directory"},
      {{"bake", d, "-o", (dir / "x.glb").string()}, d + ": is a directory"},
      {{"trace", "convert", d, (dir / "y.csv").string()}, d + ": is a directory"},
      {{"trace", "stats", d}, d + ": is a directory"},
      {{"scenario", "validate", d}, d + ": is a directory"},
  });
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir / "x.glb"));
  EXPECT_FALSE(fs::exists(dir / "y.csv"));
}

}  // namespace
}  // namespace gazelod::test
