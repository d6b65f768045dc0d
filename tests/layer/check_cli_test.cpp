// SPDX-License-Identifier: Apache-2.0
// `gazelod layer check` (apps/gazelod/commands/layer.cpp): what the layer would do, through the
// loader, on the simulated runtime with and without eye gaze, with a good and a bad source.
#include "tests/cli_run.hpp"
#include "tests/layer/layer_test_util.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace gazelod::layer_test {
namespace {

TEST(LayerCheckCli, SaysWhatTheLayerWouldDo) {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 2.0);
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  apply(setup);
  auto r = test::run_cli({"layer", "check"});
  EXPECT_EQ(r.rc, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("XR_APILAYER_GAZELOD_eye_gaze: found by the loader, enabled (XR_ENABLE_API_LAYERS)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("runtime    gazelod simulated runtime"), std::string::npos) << r.out;
  // The layer's own advertisement does not hide that the runtime lacks the extension.
  EXPECT_NE(r.out.find("XR_EXT_eye_gaze_interaction: not offered by the runtime"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("source     trace " + dir + "/trace.csv (400 samples"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("decision   emulating XR_EXT_eye_gaze_interaction with gaze from trace"), std::string::npos)
      << r.out;

  setup.runtime_eye_gaze = true;
  apply(setup);
  r = test::run_cli({"layer", "check"});
  EXPECT_EQ(r.rc, 0);
  EXPECT_NE(r.out.find("decision   the runtime offers XR_EXT_eye_gaze_interaction: passing it through"),
            std::string::npos)
      << r.out;
  std::ofstream(dir + "/override.json") << R"({"override": true})";
  setup.config = dir + "/override.json";
  apply(setup);
  r = test::run_cli({"layer", "check"});
  EXPECT_NE(r.out.find("decision   overriding the runtime's XR_EXT_eye_gaze_interaction with gaze from trace"),
            std::string::npos)
      << r.out;
  // A configuration error is the user's to fix: exit 2, even though the layer would pass through.
  setup.config = dir + "/missing-config.json";
  apply(setup);
  r = test::run_cli({"layer", "check"});
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("config     error: "), std::string::npos) << r.out;

  setup.runtime_eye_gaze = false;
  setup.config.clear();
  setup.trace = dir + "/missing.csv";
  apply(setup);
  r = test::run_cli({"layer", "check"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.out.find("decision   gaze unavailable (GAZELOD_LAYER_TRACE: " + dir + "/missing.csv"), std::string::npos)
      << r.out;

  setup.layer = false;
  apply(setup);
  setenv("XR_RUNTIME_JSON", (dir + "/no-runtime.json").c_str(), 1);
  r = test::run_cli({"layer", "check"});
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.out.find("runtime    none found through the loader"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not found by the loader"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace gazelod::layer_test
