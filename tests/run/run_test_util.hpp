// SPDX-License-Identifier: Apache-2.0
// Shared by the end-to-end tests: a scratch folder, the simulated runtime's environment, and
// `gazelod` invoked in-process.
#pragma once

#include "tests/cli_run.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::test {

// A fresh folder under the build tree, named after the running test.
std::filesystem::path scratch_dir();

// Points the loader at the simulated runtime (unpaced) and at `scenario_file` ("" = default).
void use_simulated_runtime(const std::string& scenario_file);

std::string read_text(const std::filesystem::path& file);

}  // namespace gazelod::test
