// SPDX-License-Identifier: Apache-2.0
// The `gazelod trace` command-line contract, through gazelod::cli::run.
#include "gaze/trace_writer.hpp"
#include "tests/cli_run.hpp"
#include "tests/gaze/synth.hpp"
#include "tests/interrupt_when_handled.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/gtc/quaternion.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <thread>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;

using Result = test::CliResult;
Result run(const std::vector<std::string>& args) {
  return test::run_cli(args);
}

fs::path temp_file(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / ("gazelod_trace_cli_" + std::string(info->name()));
  fs::create_directories(dir);
  return dir / name;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST(TraceCli, StatsJsonMatchesTheGeneratedTrace) {
  testing::Synth s;
  s.fixate(0.5);
  for (int i = 0; i < 5; ++i) {
    s.saccade(8.0, i % 2 ? 180.0 : 0.0);
    s.fixate(0.4);
  }
  s.blink(0.1);
  s.fixate(0.4);
  const fs::path p = temp_file("synth.csv");
  {
    std::ofstream f(p, std::ios::binary);
    TraceWriter w(f);
    for (const auto& g : s.out) w.write(TraceRecord{g, false, {}});
  }
  const Result r = run({"trace", "stats", p.string(), "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double n = static_cast<double>(s.out.size());
  EXPECT_EQ(j["samples"].get<std::size_t>(), s.out.size());
  EXPECT_NEAR(j["duration_s"].get<double>(), (n - 1) * 0.004, 1e-9);
  EXPECT_NEAR(j["rate_hz"].get<double>(), 250.0, 1e-6);
  EXPECT_NEAR(j["invalid_fraction"].get<double>(), 25.0 / n, 1e-12);  // 0.1 s blink
  EXPECT_EQ(j["saccades"].get<int>(), 5);
  // Six fixations between/around the saccades; the blink splits the last one into two.
  EXPECT_EQ(j["fixations"].get<int>(), 7);
  EXPECT_EQ(j["skipped_lines"].get<int>(), 0);
}

// The eyes holding a point while the head turns at 60 deg/s (the vestibulo-ocular reflex): no
// saccade in the world, which the stats see when the trace has head poses; the same eye-in-head
// gaze without them reads as one long eye movement above I-VT's 30 deg/s.
TEST(TraceCli, StatsClassifyInTheWorldWhenTheTraceHasHeadPoses) {
  const double deg = std::acos(-1.0) / 180.0;
  std::vector<TraceRecord> rows;
  for (int i = 0; i < 250; ++i) {  // 1 s at 250 Hz
    const double yaw_rad = 60.0 * deg * i / 250.0;
    TraceRecord r;
    r.gaze.t_ns = std::int64_t{4'000'000} * i;
    r.gaze.valid = true;
    r.gaze.confidence = 1.0f;
    r.gaze.direction = glm::angleAxis(-yaw_rad, glm::dvec3(0, 1, 0)) * glm::dvec3(0, 0, -1);  // eye in head
    r.has_head = true;
    r.head.t_ns = r.gaze.t_ns;
    r.head.valid = true;
    r.head.orientation = glm::angleAxis(yaw_rad, glm::dvec3(0, 1, 0));
    rows.push_back(r);
  }
  const auto stats = [&](bool with_head) {
    const fs::path p = temp_file(with_head ? "vor_head.csv" : "vor_gaze_only.csv");
    {
      std::ofstream f(p, std::ios::binary);
      TraceWriter w(f, {.write_head = with_head});
      for (TraceRecord r : rows) {
        r.has_head = with_head;
        w.write(r);
      }
    }
    const Result res = run({"trace", "stats", p.string(), "--json"});
    EXPECT_EQ(res.rc, 0) << res.err;
    return nlohmann::json::parse(res.out);
  };
  const auto world = stats(true), head = stats(false);
  EXPECT_EQ(world["classified_in"], "world");
  EXPECT_EQ(world["saccades"].get<int>(), 0);
  EXPECT_EQ(world["fixations"].get<int>(), 1);
  EXPECT_EQ(head["classified_in"], "head");
  EXPECT_GE(head["saccades"].get<int>(), 1);
  EXPECT_EQ(head["fixations"].get<int>(), 0);
}

// Head poses that begin mid-trace: classified in the head, then in the world, with no velocity
// taken across the switch (the first pose turns the gaze by 30 deg at once: no saccade).
TEST(TraceCli, StatsSwitchToTheWorldAtTheFirstHeadPoseWithoutAFalseSaccade) {
  const fs::path p = temp_file("late_head.csv");
  {
    std::ofstream f(p, std::ios::binary);
    TraceWriter w(f);
    for (int i = 0; i < 200; ++i) {  // 0.8 s at 250 Hz, eyes and head still; poses from row 100
      TraceRecord r;
      r.gaze.t_ns = std::int64_t{4'000'000} * i;
      r.gaze.valid = true;
      r.gaze.confidence = 1.0f;
      r.has_head = true;
      r.head.t_ns = r.gaze.t_ns;
      r.head.valid = i >= 100;
      r.head.orientation = glm::angleAxis(std::acos(-1.0) / 6.0, glm::dvec3(0, 1, 0));
      w.write(r);
    }
  }
  const Result res = run({"trace", "stats", p.string(), "--json"});
  ASSERT_EQ(res.rc, 0) << res.err;
  const auto j = nlohmann::json::parse(res.out);
  EXPECT_EQ(j["classified_in"], "head_then_world");
  EXPECT_EQ(j["saccades"].get<int>(), 0);
}

// Head cells marked head_valid = 0 are no pose: counted as one, they printed "with head pose 3"
// beside "in the head: no head poses".
TEST(TraceCli, StatsCountOnlyValidHeadPoses) {
  const fs::path p = temp_file("headless.csv");
  write_text(p,
             "t_ns,gaze_x,gaze_y,gaze_z,head_qw,head_qx,head_qy,head_qz,head_valid\n"
             "0,0,0,-1,1,0,0,0,0\n4000000,0,0,-1,1,0,0,0,0\n8000000,0,0,-1,1,0,0,0,0\n");
  Result r = run({"trace", "stats", p.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("with head pose    0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("in the head: no head poses"), std::string::npos) << r.out;
  r = run({"trace", "stats", p.string(), "--json"});
  EXPECT_EQ(nlohmann::json::parse(r.out).at("samples_with_head"), 0);
}

TEST(TraceCli, MalformedFileExitsNonZeroNamingTheLine) {
  const fs::path p = temp_file("bad.csv");
  write_text(p, "t_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n4000000,0,0,x\n");
  Result r = run({"trace", "stats", p.string()});
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find(p.string() + ":3:"), std::string::npos) << r.err;
  // Lenient: succeeds, and the skipped line is reported (stderr and JSON).
  r = run({"trace", "stats", p.string(), "--json", "--lenient"});
  EXPECT_EQ(r.rc, 0);
  EXPECT_NE(r.err.find(":3:"), std::string::npos);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["samples"].get<int>(), 1);
  EXPECT_EQ(j["skipped_lines"].get<int>(), 1);
  EXPECT_EQ(j["skipped"][0]["line"].get<int>(), 3);
  // Missing file, unknown format.
  r = run({"trace", "stats", (p.parent_path() / "nope.csv").string()});
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find("nope.csv"), std::string::npos);
  EXPECT_EQ(run({"trace", "stats", p.string(), "--format", "tobii"}).rc, 2);
}

TEST(TraceCli, ConvertGazeBaseVrThenStats) {
  const fs::path in = temp_file("gbvr.csv"), out = temp_file("gbvr_gazelod.csv");
  std::string text = "n,x,y,lx,ly,rx,ry,xT,yT,zT\n";
  for (int i = 0; i < 100; ++i)
    text += std::to_string(i * 4) + (i >= 40 && i < 50 ? ",NaN,NaN" : ",1.5,-2") + ",0,0,0,0,0,0,1\n";
  write_text(in, text);
  Result r = run({"trace", "convert", in.string(), out.string(), "--format", "gazebasevr"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_FALSE(fs::exists(out.string() + ".part"));
  r = run({"trace", "stats", out.string(), "--json"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["samples"].get<int>(), 100);
  EXPECT_NEAR(j["duration_s"].get<double>(), 0.396, 1e-12);
  EXPECT_NEAR(j["invalid_fraction"].get<double>(), 0.1, 1e-12);
  EXPECT_EQ(j["saccades"].get<int>(), 0);
  // A failing conversion leaves no output behind.
  const fs::path bad_out = temp_file("never.csv");
  write_text(in, "n,x\n");
  EXPECT_NE(run({"trace", "convert", in.string(), bad_out.string(), "--format", "gazebasevr"}).rc, 0);
  EXPECT_FALSE(fs::exists(bad_out));
  EXPECT_FALSE(fs::exists(bad_out.string() + ".part"));
}

// What is not a trace, said precisely, without reading it all (/dev/zero used to be read for
// 2.1 GB before "empty file: no header row").
TEST(TraceCli, StatsSaysWhatIsNotATrace) {
  if (fs::exists("/dev/zero")) {
    const Result r = run({"trace", "stats", "/dev/zero"});
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("/dev/zero: is a device, not a trace file"), std::string::npos) << r.err;
  }
  const fs::path dir = temp_file("adir");
  fs::create_directories(dir);
  Result r = run({"trace", "stats", dir.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find(dir.string() + ": is a directory, not a trace file"), std::string::npos) << r.err;
  const fs::path cr = temp_file("cr.csv");
  write_text(cr, "t_ns,gaze_x,gaze_y,gaze_z\r0,0,0,-1\r");
  r = run({"trace", "stats", cr.string(), "--lenient"});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find(cr.string() + ":1:26: carriage return (CR) inside a line"), std::string::npos) << r.err;
  const fs::path one_line = temp_file("one_line.csv");
  write_text(one_line, std::string(1 << 20, '7'));
  r = run({"trace", "stats", one_line.string()});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find(one_line.string() + ":1:65537: line longer than 65536 bytes"), std::string::npos) << r.err;
}

// convert writes OUT atomically: on failure neither OUT nor a temporary is left, and the
// message has the system's reason.
TEST(TraceCli, ConvertFailuresLeaveNothingAndSayWhy) {
  fs::remove_all(temp_file("good.csv").parent_path());  // from an earlier run
  const fs::path in = temp_file("good.csv");
  write_text(in, "t_ns,gaze_x,gaze_y,gaze_z\n0,0,0,-1\n1000,0,0,-1\n");
  const fs::path dir = in.parent_path();
  const fs::path adir = dir / "adir.csv";
  fs::create_directories(adir);
  Result r = run({"trace", "convert", in.string(), adir.string()});
  EXPECT_EQ(r.rc, 2);  // a folder named for the file: bad input, refused before reading
  EXPECT_NE(r.err.find("cannot write '" + adir.string() + "': is a directory"), std::string::npos) << r.err;
  r = run({"trace", "convert", in.string(), (dir / "none" / "out.csv").string()});
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("No such file or directory (creating a temporary file in '"), std::string::npos) << r.err;
  if (fs::exists("/dev/full")) {
    r = run({"trace", "convert", in.string(), "/dev/full"});
    EXPECT_EQ(r.rc, 1);
    EXPECT_NE(r.err.find("cannot write '/dev/full': No space left on device"), std::string::npos) << r.err;
  }
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"adir.csv", "good.csv"})) << "no .part, no temporary";
  r = run({"trace", "convert", in.string(), (dir / "out.csv").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out.csv"));
}

// Ctrl-C while converting a pipe that has not ended (a recorder still writing): the conversion
// stops with 128 + SIGINT and leaves neither OUT nor its temporary; without a handler the
// default action ended the process with the temporary left beside OUT.
TEST(TraceCli, ConvertStoppedBySignalWritesNothing) {
  const fs::path dir = temp_file("in.csv").parent_path();
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path fifo = dir / "in.csv", out = dir / "out.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  Result r;
  std::thread converter([&] { r = run({"trace", "convert", fifo.string(), out.string()}); });
  std::FILE* w = std::fopen(fifo.c_str(), "w");  // returns once the converter has opened it
  if (w != nullptr) {
    std::fputs("t_ns,gaze_x,gaze_y,gaze_z\n", w);
    for (int i = 0; i < 100; ++i) std::fprintf(w, "%d,0,0,-1\n", i * 4'000'000);
    std::fflush(w);
  }
  EXPECT_TRUE(test::interrupt_when_handled(SIGINT, std::chrono::milliseconds(100)));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (w != nullptr) {
    // More samples, then the end of the input: what came after the signal must not complete it.
    for (int i = 100; i < 200; ++i) std::fprintf(w, "%d,0,0,-1\n", i * 4'000'000);
    std::fclose(w);
  }
  converter.join();
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(r.rc, 128 + SIGINT) << r.err;
  EXPECT_NE(r.err.find("stopped by SIGINT after "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(out.string() + " not written"), std::string::npos) << r.err;
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"in.csv"}) << "OUT or a temporary was left";
  // The handler was the command's: the default is back.
  struct sigaction after {};
  ::sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, SIG_DFL);
}

}  // namespace
}  // namespace gazelod::gaze
