// SPDX-License-Identifier: Apache-2.0
// Misconfiguration never breaks the application: a missing trace, a config that is not JSON, a
// bad value, a directory given as the config. Each is ONE line on stderr ("gazelod layer: ..."
// saying what and where), the instance is created with XR_EXT_eye_gaze_interaction enabled,
// the system reports no eye-gaze support, the eye-gaze bindings are accepted, the action stays
// inactive, and the frame loop runs.
#include "tests/layer/layer_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace gazelod::layer_test {
namespace {

// Runs a client for a few frames under `setup`; returns stderr. `supported` / `ever_active` report.
std::string run_misconfigured(const LayerSetup& setup, XrBool32& supported, bool& ever_active) {
  apply(setup);
  ever_active = false;
  return capture_stderr([&] {
    GazeRig rig;
    rig.create();
    if (::testing::Test::HasFatalFailure()) return;
    supported = rig.supported;
    for (int f = 0; f < 30; ++f) {
      const XrTime t = rig.frame();
      EXPECT_EQ(rig.sync(), XR_SUCCESS);
      ever_active = ever_active || rig.active();
      EXPECT_EQ(rig.locate(rig.gaze_space, rig.local, t).flags, 0u);
    }
    EXPECT_EQ(rig.current_profile(), XR_NULL_PATH);  // no gaze: no eye-gaze profile either
    rig.destroy();
  });
}

void expect_one_line(const std::string& err, const std::string& what) {
  EXPECT_EQ(count_lines_with(err, "gazelod layer:"), 1) << err;
  EXPECT_EQ(count_lines_with(err, what), 1) << "expected a line with '" << what << "' in:\n" << err;
}

TEST(LayerBadConfig, MissingTrace) {
  const std::string dir = scratch_dir();
  LayerSetup setup;
  setup.trace = dir + "/no-such-trace.csv";
  XrBool32 supported = XR_TRUE;
  bool active = true;
  const std::string err = run_misconfigured(setup, supported, active);
  expect_one_line(err, "GAZELOD_LAYER_TRACE: " + dir + "/no-such-trace.csv");
  EXPECT_EQ(supported, XR_FALSE);
  EXPECT_FALSE(active);
}

TEST(LayerBadConfig, ConfigThatIsNotJson) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 1.0);
  std::ofstream(dir + "/config.json") << "{ \"override\": tru }";
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  setup.config = dir + "/config.json";
  XrBool32 supported = XR_TRUE;
  bool active = true;
  const std::string err = run_misconfigured(setup, supported, active);
  expect_one_line(err, dir + "/config.json:1:");
  EXPECT_EQ(supported, XR_FALSE);
  EXPECT_FALSE(active);
}

TEST(LayerBadConfig, ValueOutOfRangeNamesItsJsonPath) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 1.0);
  std::ofstream(dir + "/config.json") << R"({"head_offset": {"position_m": [0, 0, "x"]}})";
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  setup.config = dir + "/config.json";
  XrBool32 supported = XR_TRUE;
  bool active = true;
  const std::string err = run_misconfigured(setup, supported, active);
  expect_one_line(err, "head_offset.position_m[2]: must be a number");
  EXPECT_FALSE(active);
}

TEST(LayerBadConfig, UnreadableConfig) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 1.0);
  std::filesystem::create_directories(dir + "/config.json");  // a directory, not a file
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  setup.config = dir + "/config.json";
  XrBool32 supported = XR_TRUE;
  bool active = true;
  const std::string err = run_misconfigured(setup, supported, active);
  expect_one_line(err, "GAZELOD_LAYER_CONFIG=" + dir + "/config.json: not a regular file");
  EXPECT_FALSE(active);
}

TEST(LayerBadConfig, MalformedTraceSaysFileLineColumn) {
  const std::string dir = scratch_dir();
  std::ofstream(dir + "/trace.csv") << "# gazelod-trace 1\nt_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n1000,zero,0,-1\n";
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  XrBool32 supported = XR_TRUE;
  bool active = true;
  const std::string err = run_misconfigured(setup, supported, active);
  expect_one_line(err, dir + "/trace.csv:4:");
  EXPECT_FALSE(active);
}

}  // namespace
}  // namespace gazelod::layer_test
