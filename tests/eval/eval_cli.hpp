// SPDX-License-Identifier: Apache-2.0
// Running `gazelod` commands in the test process for the eval tests: the result, a scratch
// folder per test, and the simulated runtime unpaced.
#pragma once

#include "apps/gazelod/commands/command.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace gazelod::cli::testing {

struct Result {
  int rc = 0;
  std::string out, err;
};

inline Result cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  Result r;
  r.rc = run(args, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

// A fresh folder named after the running test, under the build tree.
inline std::filesystem::path scratch(const std::string& prefix = "eval.") {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::path(GAZELOD_BINARY_DIR) / "test-scratch" / (prefix + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void use_simulated_runtime() {
  ::setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 1);
  ::setenv("GAZELOD_SIM_PACED", "0", 1);
  ::unsetenv("GAZELOD_SIM_DURATION_S");
}

}  // namespace gazelod::cli::testing
