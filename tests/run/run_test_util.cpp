// SPDX-License-Identifier: Apache-2.0
#include "run_test_util.hpp"

#include "apps/gazelod/commands/command.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace gazelod::test {

std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::path(GAZELOD_BINARY_DIR) / "test-scratch" /
             (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void use_simulated_runtime(const std::string& scenario_file) {
  ::setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
  ::setenv("GAZELOD_SIM_PACED", "0", 1);
  if (scenario_file.empty())
    ::unsetenv("GAZELOD_SIM_SCENARIO");
  else
    ::setenv("GAZELOD_SIM_SCENARIO", scenario_file.c_str(), 1);
  ::unsetenv("GAZELOD_SIM_DURATION_S");
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace gazelod::test
