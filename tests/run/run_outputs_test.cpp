// SPDX-License-Identifier: Apache-2.0
// What `gazelod run` leaves in --out: only this run's report (an earlier run's frame.png stayed
// beside a --no-render report and passed for its picture), and nothing at all when the run is
// refused up front (a plan refused for memory left scenario.json).
#include "auxiliary/folder_lock.hpp"
#include "tests/held_by_another_process.hpp"
#include "run_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gazelod::test {
namespace {

namespace fs = std::filesystem;

// An earlier run's report files that this run does not write are removed (only the report's
// own names: other files in the folder stay).
TEST(RunOutputs, NoStaleReportFileFromAnEarlierRun) {
  use_simulated_runtime("");
  const fs::path dir = scratch_dir() / "out";
  CliResult r = run_cli({"run", "--frames", "6", "--quiet", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir / "frame.png"));
  ASSERT_TRUE(fs::exists(dir / "audit.svg"));
  std::ofstream(dir / "notes.txt") << "mine";
  std::ofstream(dir / "frame.png.bak") << "mine";
  fs::create_symlink(dir / "notes.txt", dir / "elsewhere.png");

  // Not rendered, no audit: no frame.png, no audit.svg of this run, so none at all.
  r = run_cli({"run", "--frames", "4", "--quiet", "--no-render", "--no-audit", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "frame.png")) << "the earlier run's picture is still there";
  EXPECT_FALSE(fs::exists(dir / "audit.svg"));
  EXPECT_EQ(r.out.find("frame.png"), std::string::npos) << r.out;
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "summary.json")).at("frames").get<int>(), 4);
  for (const char* kept : {"notes.txt", "frame.png.bak", "frames.csv", "frames.svg", "scenario.json"})
    EXPECT_TRUE(fs::exists(dir / kept)) << kept;
  EXPECT_TRUE(fs::is_symlink(dir / "elsewhere.png"));
  EXPECT_EQ(read_text(dir / "notes.txt"), "mine");

  // Rendered, but the capture frame past the last one: no frame.png either.
  r = run_cli({"run", "--frames", "6", "--quiet", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir / "frame.png"));
  r = run_cli({"run", "--frames", "3", "--quiet", "--capture-frame", "10", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "frame.png"));
  EXPECT_TRUE(fs::exists(dir / "audit.svg"));
}

// A run that fails once the runtime is opening (here: no runtime at the manifest's path) keeps
// the earlier run's report whole: before, its files were removed up front.
TEST(RunOutputs, FailedRunKeepsTheEarlierReport) {
  use_simulated_runtime("");
  const fs::path scratch = scratch_dir(), dir = scratch / "kept";
  CliResult r = run_cli({"run", "--frames", "4", "--quiet", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  const std::string summary = read_text(dir / "summary.json");
  ::setenv("XR_RUNTIME_JSON", (scratch / "no-runtime.json").c_str(), 1);
  r = run_cli({"run", "--frames", "3", "--quiet", "--no-render", "--out", dir.string()});
  use_simulated_runtime("");
  EXPECT_NE(r.rc, 0) << r.out;
  EXPECT_EQ(read_text(dir / "summary.json"), summary);
  for (const char* kept : {"frames.csv", "frames.svg", "audit.svg", "frame.png"})
    EXPECT_TRUE(fs::exists(dir / kept)) << kept;
}

// Every refusal the run can decide before its first write comes before it: --out is not created,
// and an earlier run's report in it is left as it was.
TEST(RunOutputs, RefusedUpFrontWritesNothing) {
  use_simulated_runtime("");
  const fs::path dir = scratch_dir();
  CliResult r = run_cli({"scenario", "print", "--default"});
  ASSERT_EQ(r.rc, 0) << r.err;
  nlohmann::json huge = nlohmann::json::parse(r.out);
  huge["duration_s"] = 1e6;  // 10^9 frames at 1 kHz: their records exceed any machine's memory
  huge["frame_rate_hz"] = 1000;
  { std::ofstream(dir / "huge.json") << huge.dump(); }
  { std::ofstream(dir / "empty.csv") << "t_ns,gaze_x,gaze_y,gaze_z\n"; }
  {
    std::ofstream(dir / "late_bad.csv") << "t_ns,gaze_x,gaze_y,gaze_z,head_qw,head_qx,head_qy,head_qz\n"
                                           "0,0,0,-1,1,0,0,0\n4000000,0,0,-1,1,0,0,0\n8000000,0,0,-1,1,0,0,0\n"
                                           "12000000,0,0,-1,1,0\n";
  }
  {
    std::ofstream(dir / "blind.csv")
        << "t_ns,gaze_x,gaze_y,gaze_z,valid\n0,0,0,-1,0\n4000000,0,0,-1,0\n8000000,0,0,-1,1\n";
  }
  struct Case {
    std::vector<std::string> args;
    std::string message;
    int rc = 2;
  };
  const std::vector<Case> cases = {
      {{"--scenario", (dir / "huge.json").string()}, "frames would keep about"},
      {{"--cluster-select", "gpu"}, "--cluster-select gpu: needs rendering"},
      {{"--runtime", "nosuch"}, "--runtime: must be 'sim' or 'system'"},
      {{"--cluster-decisions", (dir / "c.csv").string()}, "--cluster-decisions: the scene has no cluster meshes"},
      {{"--trace", (dir / "empty.csv").string(), "--trace-head", "scenario"}, "has no samples"},
      // A bad row after the first head pose: named in the trace, not as the scenario's effect
      // the --trace head adds ("default + --trace head: effects[7].file: ...").
      {{"--trace", (dir / "late_bad.csv").string()}, "--trace: " + (dir / "late_bad.csv").string() + ":5:"},
      // One valid sample: no gaze to replay (it ran with the gaze "valid in 0.0% of frames").
      {{"--trace", (dir / "blind.csv").string()}, "has 1 valid gaze sample of 3; a replay needs at least two"},
      {{"--decisions", (dir / "missing" / "d.csv").string()}, "--decisions: cannot write", 1},
  };
  for (const bool earlier : {false, true}) {
    const fs::path out = dir / (earlier ? "earlier" : "none");
    if (earlier) {
      fs::create_directories(out);
      std::ofstream(out / "summary.json") << "{\"frames\": 7}";
      std::ofstream(out / "frame.png") << "earlier";
      std::ofstream(out / "scenario.json") << "earlier";
    }
    for (const Case& c : cases) {
      std::vector<std::string> args = {"run", "--frames", "3", "--no-render", "--quiet", "--out", out.string()};
      if (c.args.front() == "--scenario") args.erase(args.begin() + 1, args.begin() + 3);  // its own length
      args.insert(args.end(), c.args.begin(), c.args.end());
      r = run_cli(args);
      EXPECT_EQ(r.rc, c.rc) << c.args.front() << "\n" << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
      if (!earlier) {
        EXPECT_FALSE(fs::exists(out)) << c.args.front() << ": --out was written";
      } else {
        EXPECT_EQ(read_text(out / "summary.json"), "{\"frames\": 7}") << c.args.front();
        EXPECT_EQ(read_text(out / "frame.png"), "earlier") << c.args.front();
        EXPECT_EQ(read_text(out / "scenario.json"), "earlier") << c.args.front();
        std::size_t files = 0;
        for (const auto& e : fs::directory_iterator(out)) files += e.is_regular_file() ? 1 : 0;
        EXPECT_EQ(files, 3u) << c.args.front() << ": a file was left in --out";
      }
    }
  }
}

// One writer per --out: with the folder locked (here by this process, as another gazelod would
// hold it), run, compare and eval family refuse it before writing anything (exit 1); with the
// lock gone, the run goes ahead. Before, two runs into one folder left a mix of both reports.
TEST(RunOutputs, FolderBeingWrittenIsRefused) {
  use_simulated_runtime("");
  const fs::path dir = scratch_dir() / "locked";
  fs::create_directories(dir);
  {
    test::HeldByAnotherProcess other(dir.string());
    ASSERT_TRUE(other.locked());
    const std::vector<std::vector<std::string>> commands = {
        {"run", "--frames", "3", "--no-render", "--quiet", "--out", dir.string()},
        {"compare", "--hmd", "questpro", "--frames", "3", "--out", dir.string()},
        {"eval", "family", "--seeds", "1000-1000", "--duration", "1", "--out", dir.string()},
    };
    for (const auto& args : commands) {
      const CliResult r = run_cli(args);
      EXPECT_EQ(r.rc, 1) << args.front() << "\n" << r.err;
      EXPECT_NE(r.err.find("--out: '" + dir.string() + "' is being written by another gazelod process"),
                std::string::npos)
          << r.err;
      EXPECT_TRUE(fs::is_empty(dir)) << args.front() << " wrote into the locked folder";
    }
    EXPECT_THROW(aux::FolderLock(dir / "nosuch"), aux::FolderLockError);
  }
  const CliResult r = run_cli({"run", "--frames", "3", "--no-render", "--quiet", "--out", dir.string()});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
}

// One command given overlapping folders (eval family's --out is one of its seeds' folders
// under --work): the seed's run is refused by the family's own hold, and said so; it was
// reported as "being written by another gazelod process".
TEST(RunOutputs, OverlappingFoldersOfOneCommandAreNamedAsSuch) {
  use_simulated_runtime("");
  const fs::path work = scratch_dir() / "work";
  const CliResult r = run_cli({"eval", "family", "--seeds", "1000-1000", "--duration", "1", "--work", work.string(),
                               "--out", (work / "seed-1000").string()});
  EXPECT_EQ(r.rc, 1) << r.err;
  EXPECT_NE(r.err.find("is being written by this gazelod command already"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("another gazelod process"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(work / "seed-1000" / "family.md"));
  // Held and released: the same folder is free again once the command has ended.
  {
    aux::FolderLock first(work.string());
    try {
      aux::FolderLock second(work.string());
      ADD_FAILURE() << "a second hold in the same process was granted";
    } catch (const aux::FolderLockError& e) {
      EXPECT_NE(std::string(e.what()).find("by this gazelod command already"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(aux::FolderLock again(work.string()));
}

}  // namespace
}  // namespace gazelod::test
