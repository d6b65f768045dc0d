// SPDX-License-Identifier: Apache-2.0
// The second Ctrl-C or SIGTERM during `gazelod run` ends the process at once (run/signals.hpp).
// It left the temporary of each file being written; the handler now removes those held by an
// AtomicRunFile (the report's files, frame.png, the decisions files) before the process ends,
// and only those: a file already committed stays.
#include "apps/gazelod/run/decisions_file.hpp"
#include "apps/gazelod/run/signals.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::cli {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(GAZELOD_BINARY_DIR) / "test-scratch" / ("RunSignalFiles." + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

// In the child: a stopper as the run holds one, a committed file, two files being written, the
// first signal (a stop request) and the second (the end).
void second_signal_while_writing(const fs::path& dir, int first, int second) {
  StopOnSignal stop;
  write_run_file((dir / "frames.svg").string(), "<svg/>\n");  // committed before the signals
  const std::vector<std::string> objects = {"a", "b"};
  DecisionsFile decisions(dir / "decisions.csv", objects);
  const std::uint8_t levels[] = {0, 1};
  decisions.write(0, 0, levels);
  AtomicRunFile summary((dir / "summary.json").string());
  summary.stream() << "{\"frames\": " << std::flush;
  std::raise(first);
  std::raise(second);
  std::_Exit(0);  // not reached
}

TEST(RunSignalFiles, SecondSignalRemovesTheTemporariesBeingWritten) {
  for (const auto& [first, second] : {std::pair{SIGINT, SIGINT}, std::pair{SIGTERM, SIGINT}}) {
    const fs::path dir = fresh_dir(std::to_string(first) + "-" + std::to_string(second));
    EXPECT_EXIT(second_signal_while_writing(dir, first, second), ::testing::KilledBySignal(second), "");
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"frames.svg"}) << "a temporary or a partial file was left";
  }
}

// Held temporaries are released with their file: one committed or abandoned is no longer the
// handler's, and a slot is free again for the next.
TEST(RunSignalFiles, HeldOnlyWhileTheFileIsOpen) {
  const fs::path dir = fresh_dir("held");
  for (int i = 0; i < 3 * TemporaryOnSignal::kHeldTemporaries; ++i) {
    AtomicRunFile f((dir / (std::to_string(i) + ".txt")).string());
    f.stream() << i;
    if (i % 2 == 0) f.commit();
  }
  std::vector<TemporaryOnSignal> held(TemporaryOnSignal::kHeldTemporaries);
  for (TemporaryOnSignal& t : held) {
    t.hold((dir / "x").string());
    EXPECT_TRUE(t.held()) << "a slot was not freed";
  }
  TemporaryOnSignal one_more;
  one_more.hold((dir / "y").string());
  EXPECT_FALSE(one_more.held());
  held.front().release();
  one_more.hold((dir / "y").string());
  EXPECT_TRUE(one_more.held());
}

}  // namespace
}  // namespace gazelod::cli
