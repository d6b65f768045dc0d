// SPDX-License-Identifier: Apache-2.0
// `gazelod run` against the simulated runtime with injected faults (docs/hardening.md): the
// session lost (with XR_SESSION_STATE_LOSS_PENDING, and silently with only
// XR_ERROR_SESSION_LOST), a bad fault variable, a gaze trace that freezes or jumps back, a
// tracker with dropouts and blinks. The frame loop ends cleanly with a message, or continues;
// no NaN reaches a frame's decisions.
#include "tests/run/run_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace gazelod::test {
namespace {

class RuntimeFaults : public ::testing::Test {
 protected:
  void SetUp() override { use_simulated_runtime(""); }
  void TearDown() override {
    ::unsetenv("GAZELOD_SIM_LOSE_SESSION_AT_FRAME");
    ::unsetenv("GAZELOD_SIM_LOSE_SESSION_SILENTLY");
  }
};

std::size_t data_rows(const std::string& csv) {
  const auto lines = static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n'));
  return lines == 0 ? 0 : lines - 1;  // minus the header
}

bool has_nan(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text.find("nan") != std::string::npos || text.find("inf,") != std::string::npos;
}

TEST_F(RuntimeFaults, SessionLossPendingEndsTheRunWithAMessageAndTheFramesSoFar) {
  ::setenv("GAZELOD_SIM_LOSE_SESSION_AT_FRAME", "30", 1);
  const auto dir = scratch_dir();
  const CliResult r = run_cli({"run", "--frames", "120", "--no-render", "--quiet", "--out", dir.string()});
  EXPECT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.err.find("XR_SESSION_STATE_LOSS_PENDING"), std::string::npos) << r.err;
  // Frame 30 was submitted, then the session was lost: 30 frames in the report.
  EXPECT_EQ(data_rows(read_text(dir / "frames.csv")), 30u);
  EXPECT_TRUE(std::filesystem::exists(dir / "summary.json"));
}

TEST_F(RuntimeFaults, SilentSessionLossIsAnErrorNamingXrErrorSessionLost) {
  ::setenv("GAZELOD_SIM_LOSE_SESSION_AT_FRAME", "10", 1);
  ::setenv("GAZELOD_SIM_LOSE_SESSION_SILENTLY", "1", 1);
  const auto dir = scratch_dir();
  const CliResult r = run_cli({"run", "--frames", "120", "--no-render", "--quiet", "--out", dir.string()});
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("XR_ERROR_SESSION_LOST"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("xrWaitFrame"), std::string::npos) << r.err;  // the call that failed
}

TEST_F(RuntimeFaults, ABadFaultVariableIsNamed) {
  ::setenv("GAZELOD_SIM_LOSE_SESSION_AT_FRAME", "-3", 1);
  const auto dir = scratch_dir();
  testing::internal::CaptureStderr();  // the runtime writes its reason to the process's stderr
  const CliResult r = run_cli({"run", "--frames", "5", "--no-render", "--quiet", "--out", dir.string()});
  const std::string runtime_err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("xrCreateInstance"), std::string::npos) << r.err;
  EXPECT_NE(runtime_err.find("GAZELOD_SIM_LOSE_SESSION_AT_FRAME=\"-3\""), std::string::npos) << runtime_err;
}

TEST_F(RuntimeFaults, AFrozenGazeTraceKeepsTheLoopGoingWithoutNan) {
  // A tracker stuck on one sample: every row has the same time and direction.
  const auto dir = scratch_dir();
  {
    std::ofstream t(dir / "frozen.csv");
    t << "t_ns,gaze_x,gaze_y,gaze_z\n";
    for (int i = 0; i < 50; ++i) t << "0,0.6,0,-0.8\n";
  }
  const CliResult r = run_cli({"run", "--frames", "90", "--no-render", "--quiet", "--no-eye-gaze", "--trace",
                               (dir / "frozen.csv").string(), "--out", (dir / "out").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  const std::string csv = read_text(dir / "out" / "frames.csv");
  EXPECT_EQ(data_rows(csv), 90u);
  EXPECT_FALSE(has_nan(csv));
}

TEST_F(RuntimeFaults, AGazeTraceJumpingBackIsRejectedWithItsLine) {
  const auto dir = scratch_dir();
  {
    std::ofstream t(dir / "back.csv");
    t << "t_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n5000000,0,0,-1\n1000000,0,0,-1\n";
  }
  const CliResult r = run_cli({"run", "--frames", "10", "--no-render", "--quiet", "--trace",
                               (dir / "back.csv").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("back.csv:4:1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("backwards"), std::string::npos) << r.err;
}

TEST_F(RuntimeFaults, TrackerDropoutsAndBlinksNeverPutNanInTheReport) {
  // sim/scenarios/all_effects.json: blinks, dropouts, noise, latency, a tracker rate change.
  use_simulated_runtime("");
  const auto dir = scratch_dir();
  const CliResult r = run_cli({"run", "--scenario", std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/all_effects.json",
                               "--frames", "900", "--no-render", "--quiet", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  const std::string csv = read_text(dir / "frames.csv");
  EXPECT_EQ(data_rows(csv), 900u);
  EXPECT_FALSE(has_nan(csv));
}

}  // namespace
}  // namespace gazelod::test
