// SPDX-License-Identifier: Apache-2.0
// Ctrl-C or SIGTERM during `gazelod run` (the program, as a user runs it): the run stops at a
// frame boundary, ends the session, writes the report of the frames done marked interrupted,
// commits --decisions, leaves no temporary file, and exits 128 + the signal. `gazelod eval
// family` stops with no report and no work folder left.
#include "run_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

extern char** environ;

namespace gazelod::test {
namespace {

// Starts `gazelod ARGS`, signals it once it has run a second and a half (and then at once with
// `then`, when given), returns the exit status or 1000 + the signal that ended it; its output
// goes to log.
int spawn_and_signal(std::vector<std::string> args, const std::string& log, int signal, int then = 0) {
  const std::string program = std::string(GAZELOD_BINARY_DIR) + "/apps/gazelod/gazelod";
  args.insert(args.begin(), program);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  EXPECT_EQ(posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, signal);
  if (then != 0) kill(pid, then);  // another signal: not merged with the first while pending
  int status = 0;
  // Bounded: a run that ignored the signal is killed after 30 s and fails the test.
  for (int i = 0; i < 300 && waitpid(pid, &status, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (waitpid(pid, &status, WNOHANG) == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    ADD_FAILURE() << "gazelod " << args[1] << " did not stop within 30 s of the signal";
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// `gazelod run` for far more frames than it will get.
int run_and_signal(const std::filesystem::path& out, int signal) {
  return spawn_and_signal({"run", "--frames", "1000000", "--no-render", "--quiet", "--out", out.string(), "--decisions",
                           (out / "decisions.csv").string()},
                          (out.parent_path() / "run.log").string(), signal);
}

TEST(RunSignals, FirstSignalStopsWithAReportMarkedInterrupted) {
  for (int signal : {SIGINT, SIGTERM}) {
    const auto dir = scratch_dir() / (signal == SIGINT ? "int" : "term");
    std::filesystem::create_directories(dir);
    use_simulated_runtime("");
    const auto out = dir / "out";
    EXPECT_EQ(run_and_signal(out, signal), 128 + signal) << read_text(dir / "run.log");
    const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
    EXPECT_EQ(summary["interrupted"], signal == SIGINT ? "SIGINT" : "SIGTERM");
    EXPECT_GT(summary["frames"].get<long>(), 0);
    // The decisions of every frame reported, committed: a header and one row per frame.
    std::ifstream d(out / "decisions.csv");
    long rows = -1;
    for (std::string line; std::getline(d, line);) ++rows;
    EXPECT_EQ(rows, summary["frames"].get<long>());
    for (const auto& e : std::filesystem::directory_iterator(out))
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
    EXPECT_NE(read_text(dir / "run.log").find("ending the session and writing the report"), std::string::npos);
  }
}

// A second signal ends the process at once, as the signal's default would; it left the
// temporaries of the files being written (the decisions file, open the whole run; the report
// file in progress). They are removed first: no temporary, no partial file, no report.
TEST(RunSignals, SecondSignalEndsAtOnceAndLeavesNoTemporary) {
  const auto dir = scratch_dir();
  use_simulated_runtime("");
  const auto out = dir / "out";
  const int rc = spawn_and_signal({"run", "--frames", "1000000", "--no-render", "--quiet", "--out", out.string(),
                                   "--decisions", (out / "decisions.csv").string()},
                                  (dir / "run.log").string(), SIGINT, SIGTERM);
  EXPECT_TRUE(rc == 1000 + SIGINT || rc == 1000 + SIGTERM) << rc << "\n" << read_text(dir / "run.log");
  for (const auto& e : std::filesystem::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  EXPECT_FALSE(std::filesystem::exists(out / "decisions.csv")) << "never committed";
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
}

// `gazelod scenario record` likewise: a second signal removes the trace's temporary (it left a
// 25 MB ".sr.csv.tmp-PID-0").
TEST(RunSignals, ScenarioRecordSecondSignalLeavesNoTemporary) {
  const auto dir = scratch_dir();
  const auto out = dir / "rec";
  std::filesystem::create_directories(out);
  const int rc = spawn_and_signal(
      {"scenario", "record", "--default", "--duration", "100000", "--rate", "1000", "--out", (out / "sr.csv").string()},
      (dir / "record.log").string(), SIGINT, SIGTERM);
  EXPECT_TRUE(rc == 1000 + SIGINT || rc == 1000 + SIGTERM) << rc << "\n" << read_text(dir / "record.log");
  EXPECT_TRUE(std::filesystem::is_empty(out)) << "a temporary or a partial trace was left";
}

// `gazelod eval family` stops too: between seeds or in a seed's run, with a message, exit 128 +
// the signal, no report, and its temporary work folder removed (it died with 143 and left it).
TEST(RunSignals, EvalFamilyStopsWithoutAReportAndRemovesItsWork) {
  for (int signal : {SIGINT, SIGTERM}) {
    const auto dir = scratch_dir() / (signal == SIGINT ? "family_int" : "family_term");
    std::filesystem::create_directories(dir / "tmp");
    use_simulated_runtime("");
    ASSERT_EQ(setenv("TMPDIR", (dir / "tmp").c_str(), 1), 0);
    const int rc =
        spawn_and_signal({"eval", "family", "--seeds", "1-500", "--duration", "2", "--out", (dir / "out").string()},
                         (dir / "family.log").string(), signal);
    unsetenv("TMPDIR");
    const std::string log = read_text(dir / "family.log");
    EXPECT_EQ(rc, 128 + signal) << log;
    EXPECT_NE(log.find(std::string("stopped by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM")), std::string::npos)
        << log;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "family.json"));
    EXPECT_TRUE(std::filesystem::is_empty(dir / "tmp")) << "the work folder was left in " << (dir / "tmp");
  }
}

}  // namespace
}  // namespace gazelod::test
