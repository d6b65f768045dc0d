// SPDX-License-Identifier: Apache-2.0
// gazelod: the command-line program. Every sub-command is a cmd_*.cpp in this folder.
#include "apps/gazelod/commands/command.hpp"

#include <iostream>

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return gazelod::cli::run(args, std::cout, std::cerr);
}
