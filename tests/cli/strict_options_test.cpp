// SPDX-License-Identifier: Apache-2.0
// Options are read as a user means them, for every command: decimal integers only ("0x10" is
// not 16), no negative into an unsigned option (CLI11 wrapped "-1"), finite numbers only (NaN
// passed range checks); lists without empty or repeated items; no silently dropped input.
// Each refusal names the option and exits 2 before any work.
#include "tests/cli_run.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gazelod::test {
namespace {

struct Case {
  std::vector<std::string> args;
  std::string message;
};

TEST(StrictOptions, NumbersListsAndSourcesAreRefusedWithTheOption) {
  const std::vector<Case> cases = {
      {{"run", "--frames", "0x10", "--no-render"}, "--frames: '0x10' is not a decimal integer"},
      {{"run", "--frames", "1e3", "--no-render"}, "--frames: "},  // the range check refuses it first
      {{"scene", "generate", "terrain", "/tmp/gazelod-never.glb", "--seed", "-1"}, "--seed: '-1' is negative"},
      // Past 64 bits: CLI11 saturated to 2^64 - 1 and ran.
      {{"scenario", "family", "--seed", "18446744073709551616"},
       "--seed: '18446744073709551616' is out of range (64 bits)"},
      {{"scenario", "record", "--rate", "nan", "--out", "/tmp/gazelod-never.csv"},
       "--rate: 'nan' is not a finite number"},
      {{"scenario", "record", "--duration", "inf", "--out", "/tmp/gazelod-never.csv"}, "--duration: "},
      {{"eval", "--radius-scale", "nan"}, "--radius-scale: 'nan' is not a finite number"},
      {{"run", "--criteria", "size,", "--no-render"}, "--criteria: an empty item in 'size,'"},
      {{"run", "--criteria", "velocity,size,velocity", "--no-render"}, "--criteria: 'velocity' twice"},
      {{"run", "--trace", "a.csv", "--gaze", "trace:b.csv", "--no-render"}, "two traces; give one"},
      {{"compare", "--hmd", "questpro", "--hmd", "questpro"}, "--hmd: 'questpro' twice"},
      {{"bake", "in.glb", "-o", "out.glb", "--levels", "0"}, "--levels: must be in [2, 16], got 0"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_cli(c.args);
    EXPECT_EQ(r.rc, 2) << c.args[0] << " " << c.message << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace gazelod::test
