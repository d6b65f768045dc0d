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
      // Before the range check: it read these as numbers and said "Value 1e3 not in range".
      {{"run", "--frames", "1e3", "--no-render"}, "--frames: '1e3' is not a decimal integer"},
      {{"run", "--frames", "5 ", "--no-render"}, "--frames: '5 ' is not a decimal integer"},
      {{"scene", "generate", "terrain", "/tmp/gazelod-never.glb", "--seed", "-1"}, "--seed: '-1' is negative"},
      // Past 64 bits: CLI11 saturated to 2^64 - 1 and ran.
      {{"scenario", "family", "--seed", "18446744073709551616"},
       "--seed: '18446744073709551616' is out of range (64 bits: at most 18446744073709551615)"},
      {{"scenario", "record", "--rate", "nan", "--out", "/tmp/gazelod-never.csv"},
       "--rate: 'nan' is not a finite number"},
      {{"scenario", "record", "--duration", "inf", "--out", "/tmp/gazelod-never.csv"},
       "--duration: 'inf' is not a finite number"},
      {{"eval", "--radius-scale", "nan"}, "--radius-scale: 'nan' is not a finite number"},
      {{"run", "--criteria", "size,", "--no-render"}, "--criteria: an empty item in 'size,'"},
      {{"run", "--criteria", "velocity,size,velocity", "--no-render"}, "--criteria: 'velocity' twice"},
      {{"run", "--trace", "a.csv", "--gaze", "trace:b.csv", "--no-render"}, "two traces; give one"},
      {{"run", "--trace", "a.csv", "--gaze", "runtime", "--no-render"}, "--gaze runtime and --trace: choose one"},
      {{"compare", "--hmd", "questpro", "--hmd", "questpro"}, "--hmd: 'questpro' twice"},
      {{"bake", "in.glb", "-o", "out.glb", "--levels", "0"}, "--levels: must be in [2, 16], got 0"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_cli(c.args);
    EXPECT_EQ(r.rc, 2) << c.args[0] << " " << c.message << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

// --capture-frame -7 meant the middle frame (-1 was "not given"); it is refused, naming the
// option, like a negative value of an unsigned option. 0 is the first frame.
TEST(StrictOptions, NegativeCaptureFrameIsRefused) {
  for (const char* frame : {"-7", "-1"}) {
    const CliResult r = run_cli({"run", "--frames", "2", "--no-render", "--quiet", "--capture-frame", frame, "--out",
                                 "/tmp/gazelod-never-capture"});
    EXPECT_EQ(r.rc, 2) << frame << "\n" << r.err;
    EXPECT_NE(r.err.find(std::string("--capture-frame: '") + frame + "' is negative"), std::string::npos) << r.err;
  }
}

// Integers past their option's own type: an int given 2^31 or more gave CLI11's raw "Could not
// convert: --levels = 99999999999"; past 64 bits a 32-bit option said "(64 bits)"; a signed
// 64-bit option took 2^63 as 2^63 - 1. Each names the option, the value and the type's range.
TEST(StrictOptions, IntegersPastTheirTypeAreRefusedWithItsRange) {
  const std::string int32 = "(32 bits: -2147483648 to 2147483647)";
  const std::vector<Case> cases = {
      {{"bake", "in.glb", "-o", "out.glb", "--levels", "99999999999"},
       "--levels: '99999999999' is out of range " + int32},
      {{"bake", "in.glb", "-o", "out.glb", "--levels", "2147483648"},
       "--levels: '2147483648' is out of range " + int32},
      {{"bake", "in.glb", "-o", "out.glb", "--profile", "-2147483649"},
       "--profile: '-2147483649' is out of range " + int32},
      {{"bake", "in.glb", "-o", "out.glb", "--levels", "99999999999999999999999"},
       "--levels: '99999999999999999999999' is out of range " + int32},
      {{"run", "--frames", "2", "--no-render", "--capture-frame", "9223372036854775808", "--out",
        "/tmp/gazelod-never-capture"},
       "--capture-frame: '9223372036854775808' is out of range (64 bits: -9223372036854775808 to "
       "9223372036854775807)"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_cli(c.args);
    EXPECT_EQ(r.rc, 2) << c.args[0] << " " << c.message << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace gazelod::test
