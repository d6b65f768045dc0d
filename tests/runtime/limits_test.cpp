// SPDX-License-Identifier: Apache-2.0
// The runtime reads scenarios with the same parser as `gazelod scenario validate`: a scenario
// past the limits (sim/scene_json.hpp) fails xrCreateInstance with
// XR_ERROR_INITIALIZATION_FAILED and the parser's message on stderr, quickly and without
// allocating what it describes; and every boolean variable has one parser (GAZELOD_SIM_LOG
// too).
#include "sim/simulator.hpp"
#include "tests/runtime/xr_client.hpp"

#include <nlohmann/json.hpp>

#include <gmock/gmock.h>

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace gazelod::xrrt_test {
namespace {

using ::testing::HasSubstr;

// xrCreateInstance's result and what the runtime wrote on stderr meanwhile.
struct Created {
  XrResult result = XR_SUCCESS;
  std::string err;
};

Created create_capturing_stderr() {
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/runtime/limits_stderr.txt";
  std::fflush(stderr);
  const int saved = ::dup(2);
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(fd, 2);
  ::close(fd);
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "limits");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  XrInstance instance = XR_NULL_HANDLE;
  Created c;
  c.result = xrCreateInstance(&info, &instance);
  std::fflush(stderr);
  ::dup2(saved, 2);
  ::close(saved);
  if (c.result == XR_SUCCESS) xrDestroyInstance(instance);
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  c.err = s.str();
  return c;
}

TEST(RuntimeLimits, ScenarioPastTheLimitsFailsInstanceCreationWithTheMessage) {
  // The report's memory bomb: 50 generators of 1e6 objects and 16 levels each.
  nlohmann::json j = nlohmann::json::parse(sim::default_scenario_json());
  nlohmann::json gens = nlohmann::json::array();
  for (int i = 0; i < 50; ++i)
    gens.push_back({{"type", "random_field"},
                    {"count", 1'000'000},
                    {"lod_count", 16},
                    {"name_prefix", std::string("g").append(std::to_string(i))}});
  j["scene"] = {{"generators", gens}};
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/runtime/limits_bomb.json";
  std::ofstream(path) << j.dump();
  use_runtime(2.0, false, path);
  const auto t0 = std::chrono::steady_clock::now();
  const Created c = create_capturing_stderr();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
  EXPECT_EQ(c.result, XR_ERROR_INITIALIZATION_FAILED);
  EXPECT_THAT(c.err, HasSubstr("gazelod_xr_runtime: cannot load the scenario: " + path +
                               ": scene.generators[0].count: must keep the LOD levels in all <= 4000000"));
  // And a check `gazelod run` used to be the first to make: a one-view display.
  j = nlohmann::json::parse(sim::default_scenario_json());
  j["display"] = "desktop";
  std::ofstream(path) << j.dump();
  const Created mono = create_capturing_stderr();
  EXPECT_EQ(mono.result, XR_ERROR_INITIALIZATION_FAILED);
  EXPECT_THAT(mono.err, HasSubstr(path + ": display: the preset \"desktop\" has 1 view"));
}

TEST(RuntimeLimits, BooleanVariablesShareOneParser) {
  use_runtime(2.0);
  for (const char* name : {"GAZELOD_SIM_LOG", "GAZELOD_SIM_PACED", "GAZELOD_SIM_LOSE_SESSION_SILENTLY",
                           "GAZELOD_SIM_EYE_GAZE_EXTENSION"}) {
    SCOPED_TRACE(name);
    setenv(name, "abc", 1);
    const Created bad = create_capturing_stderr();
    EXPECT_EQ(bad.result, XR_ERROR_INITIALIZATION_FAILED);
    EXPECT_THAT(bad.err, HasSubstr(std::string(name) + "=\"abc\": expected 0 or 1"));
    setenv(name, "0", 1);
    EXPECT_EQ(create_capturing_stderr().result, XR_SUCCESS);
    unsetenv(name);
  }
  use_runtime(2.0);
}

}  // namespace
}  // namespace gazelod::xrrt_test
