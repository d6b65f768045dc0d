// SPDX-License-Identifier: Apache-2.0
// The one error type of the bake pipeline: a message that already names the file and where in
// it (mesh / primitive / JSON path), ready for the user.
#pragma once

#include <stdexcept>
#include <string>

namespace gazelod::bake {

struct BakeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The output could not be written (the input was fine): a different exit status in the CLI.
struct OutputError : BakeError {
  using BakeError::BakeError;
};

}  // namespace gazelod::bake
