// SPDX-License-Identifier: Apache-2.0
// Ctrl-C or SIGTERM during `gazelod run` (the program, as a user runs it): the run stops at a
// frame boundary, ends the session, writes the report of the frames done marked interrupted,
// commits --decisions, leaves no temporary file, and exits 128 + the signal.
#include "run_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

extern char** environ;

namespace gazelod::test {
namespace {

// Starts `gazelod run` for far more frames than it will get, signals it once it has run a
// second, returns the exit status.
int run_and_signal(const std::filesystem::path& out, int signal) {
  const std::string program = std::string(GAZELOD_BINARY_DIR) + "/apps/gazelod/gazelod";
  const std::string out_dir = out.string(), decisions = (out / "decisions.csv").string();
  std::vector<std::string> args = {program,   "run",   "--frames", "1000000",     "--no-render",
                                   "--quiet", "--out", out_dir,    "--decisions", decisions};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string log = (out.parent_path() / "run.log").string();
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  EXPECT_EQ(posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, signal);
  int status = 0;
  // Bounded: a run that ignored the signal is killed after 30 s and fails the test.
  for (int i = 0; i < 300 && waitpid(pid, &status, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (waitpid(pid, &status, WNOHANG) == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    ADD_FAILURE() << "gazelod run did not stop within 30 s of the signal";
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
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

}  // namespace
}  // namespace gazelod::test
