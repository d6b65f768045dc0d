// SPDX-License-Identifier: Apache-2.0
// The gazelod command line: a registry of sub-commands.
// Each sub-command lives in one cmd_NAME.cpp that defines a static Registrar; run() builds a
// CLI11 app from every registered command, so tests can call it with their own streams.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gazelod::cli {

// Where a command writes. Commands never touch std::cout / std::cerr directly.
struct Io {
  std::ostream& out;
  std::ostream& err;
};

// A command's failure with a message for the user ("--pixels: width must be > 0, got 0").
// run() prints "gazelod <command>: <message>" and returns `exit_code`.
struct UsageError : std::runtime_error {
  explicit UsageError(const std::string& message, int exit_code_ = 2)
      : std::runtime_error(message), exit_code(exit_code_) {}
  int exit_code;
};

// An option's value as a finite number; throws UsageError("<option>: '<text>' is not a finite
// number") otherwise.
double parse_number(const std::string& option, const std::string& text);

// An output file named by `option` (its value `path`): a directory there is bad input, refused
// before any work with UsageError "<option>: cannot write '<path>': is a directory ..." (exit 2,
// as for an input file that is a directory).
void check_output_file(const std::string& option, const std::string& path);

// For a signed integer option whose negative values mean nothing: refuses "-7" with "'-7' is
// negative", as every unsigned option does. Other text is the decimal-integer check's.
CLI::Validator non_negative_integer();

// Adds one sub-command to `app`. The sub-command's callback must return its exit status
// through the returned function (called after a successful parse, only if it was selected).
using Action = std::function<int(Io)>;
using Setup = std::function<Action(CLI::App& sub)>;

struct Registrar {
  // `name` and `description` make the sub-command; `setup` adds its options and returns the
  // action to run. Options must bind to storage owned by the action (e.g. a shared_ptr).
  Registrar(std::string name, std::string description, Setup setup);
};

// Parses `args` (without the program name) and runs the selected command.
// Returns the process exit status: 0 success, 2 bad usage/input, 1 other failure.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace gazelod::cli
