// SPDX-License-Identifier: Apache-2.0
// gazelod hid list / record, run through the command registry against the fake hidapi.
#include "apps/gazelod/commands/command.hpp"
#include "tests/hid/fake_hidapi.hpp"
#include "tests/hid/report_bytes.hpp"
#include "tests/interrupt_when_handled.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace gazelod::gaze::hid {
namespace {

using testing::Bytes;
using testing::tracking_report;

struct Result {
  int code;
  std::string out, err;
};
Result run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = cli::run(args, out, err);
  return {code, out.str(), err.str()};
}

const std::string kPath = "/dev/hidraw-fake-cli";

class HidCliTest : public ::testing::Test {
 protected:
  void SetUp() override { fake_hid::reset(); }
  void TearDown() override { fake_hid::reset(); }
};

TEST_F(HidCliTest, ListShowsOnlyUsagePage0x12) {
  fake_hid::plug({"/dev/hidraw-fake-mouse", 0x01, 0x02});
  fake_hid::plug({kPath});
  const Result r = run({"hid", "list", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["path"], kPath);
  EXPECT_EQ(j[0]["usage_page"], 0x12);
  EXPECT_EQ(j[0]["kind"], "eye tracker");
  fake_hid::reset();
  const Result none = run({"hid", "list"});
  EXPECT_EQ(none.code, 0);
  EXPECT_NE(none.out.find("no HID eye tracker"), std::string::npos);
}

// A configured, calibrated tracker with three tracking reports queued.
void plug_tracker_with_three_samples() {
  fake_hid::plug({kPath});
  fake_hid::set_feature(kPath, Bytes{}.u8(kReportConfiguration).u16(1).u16(2).u32(3).u16(4).i32(527040).i32(296460).b);
  fake_hid::set_feature(kPath, Bytes{}.u8(kReportStatus).u8(1).u16(250).b);
  for (int i = 0; i < 3; ++i)
    fake_hid::push_input(kPath,
                         tracking_report(1000 + 4000u * i, 263520, 148230, {-32000, 0, 600000}, {32000, 0, 600000}));
}

TEST_F(HidCliTest, RecordWritesEverySampleToATrace) {
  plug_tracker_with_three_samples();
  fake_hid::push_input(kPath, Bytes{}.u8(0x10).pad(5).b);  // short: skipped, not written
  const auto out = std::filesystem::temp_directory_path() / "gazelod_hid_cli_test.csv";
  const Result r = run({"hid", "record", "--out", out.string(), "--seconds", "0.3"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("3 samples (0 invalid)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("skipped 1 malformed"), std::string::npos) << r.err;
  std::ifstream in(out);
  std::string line;
  int rows = -1;  // the column header
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') ++rows;
  EXPECT_EQ(rows, 3);
  std::filesystem::remove(out);
}

TEST_F(HidCliTest, BadOptionsAndNoDeviceFailWithAMessage) {
  const Result neg = run({"hid", "record", "--out", "/tmp/x.csv", "--seconds", "-1"});
  EXPECT_EQ(neg.code, 2);
  EXPECT_NE(neg.err.find("--seconds"), std::string::npos) << neg.err;
  const Result layout = run({"hid", "record", "--out", "/tmp/x.csv", "--seconds", "1", "--layout", "zz"});
  EXPECT_EQ(layout.code, 2);
  EXPECT_NE(layout.err.find("--layout"), std::string::npos) << layout.err;
  const auto out = std::filesystem::temp_directory_path() / "gazelod_hid_cli_none.csv";
  const Result none = run({"hid", "record", "--out", out.string(), "--seconds", "0.02"});
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.err.find("no HID eye tracker could be opened"), std::string::npos) << none.err;
  EXPECT_FALSE(std::filesystem::exists(out)) << "no header-only file left behind";
  std::filesystem::remove(out);
}

// hidapi crashed on a path that is not a hidraw device (/dev/null, /dev/zero): refused before
// it is opened, with the reason, and no output file.
TEST_F(HidCliTest, DeviceThatIsNotHidrawIsRefused) {
  const auto out = std::filesystem::temp_directory_path() / "gazelod_hid_cli_notraw.csv";
  for (const char* device : {"/dev/null", "/dev/zero", "/tmp", "/no/such/device"}) {
    const Result r = run({"hid", "record", "--device", device, "--out", out.string(), "--seconds", "1"});
    EXPECT_EQ(r.code, 2) << device;
    EXPECT_NE(r.err.find("--device: "), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << device;
  }
}

// Ctrl-C is how a recording is usually stopped: it ends the recording, keeps the samples and
// exits 0. Before, it killed the process and left the temporary file beside --out.
TEST_F(HidCliTest, CtrlCEndsTheRecordingAndKeepsTheSamples) {
  plug_tracker_with_three_samples();
  const auto dir = std::filesystem::temp_directory_path() / "gazelod_hid_cli_ctrl_c";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto out = dir / "rec.csv";
  Result r;
  std::thread recorder([&] { r = run({"hid", "record", "--out", out.string(), "--seconds", "60"}); });
  EXPECT_TRUE(test::interrupt_when_handled(SIGINT, std::chrono::milliseconds(100)));
  const auto sent = std::chrono::steady_clock::now();
  recorder.join();
  EXPECT_LT(std::chrono::steady_clock::now() - sent, std::chrono::seconds(5));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("stopped by SIGINT"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("3 samples"), std::string::npos) << r.err;
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.path() == out ? 1 : 100;
  EXPECT_EQ(files, 1u) << "a temporary was left, or no recording";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace gazelod::gaze::hid
