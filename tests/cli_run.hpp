// SPDX-License-Identifier: Apache-2.0
// Runs the gazelod program in-process (gazelod::cli::run) for the command-line tests.
#pragma once

#include "apps/gazelod/commands/command.hpp"

#include <sstream>
#include <string>
#include <vector>

namespace gazelod::test {

struct CliResult {
  int rc = 0;
  std::string out, err;
};

inline CliResult run_cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int rc = cli::run(args, out, err);
  return {rc, out.str(), err.str()};
}

}  // namespace gazelod::test
