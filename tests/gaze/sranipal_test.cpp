// SPDX-License-Identifier: Apache-2.0
// HTC Vive Pro Eye (SRanipal, logged from Unity) importer: the semicolon layout and its
// detection, .NET ticks, the axis conversions checked against geometry worked out by hand
// (converging eyes, a head turned left, a head pitched down), the validity bits, and errors
// that name file:line:column.
#include "gaze/import_sranipal.hpp"
#include "gaze/trace_open.hpp"
#include "tests/gaze/trace_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace gazelod::gaze {
namespace {

// The logger's own header (a subset of its 42 columns, in its order).
const std::string kHeader =
    "time(100ns);time_stamp(ms);frame;eye_valid_L;eye_valid_R;openness_L;openness_R;"
    "gaze_origin_L.x(mm);gaze_origin_L.y(mm);gaze_origin_L.z(mm);gaze_origin_R.x(mm);gaze_origin_R.y(mm);"
    "gaze_origin_R.z(mm);gaze_direct_L.x;gaze_direct_L.y;gaze_direct_L.z;gaze_direct_R.x;gaze_direct_R.y;"
    "gaze_direct_R.z;distance_valid_C;helmet_pos_x;helmet_pos_y;helmet_pos_z;helmet_rot_x;helmet_rot_y;helmet_rot_z\n";

// 2023-10-30 16:31:28.2596202 UTC in .NET ticks (the recording's first sample).
constexpr std::int64_t kTicks = 638342802882596202;
constexpr std::int64_t kTicksUnixNs = 1698683488259620200;

std::string row(std::int64_t ticks, int valid_l, int valid_r, const std::string& dirs,
                const std::string& head = "0;1.6;0;0;0;0") {
  return std::to_string(ticks) + ";-1511527596;1;" + std::to_string(valid_l) + ";" + std::to_string(valid_r) +
         ";1;1;32;0;-40;-32;0;-40;" + dirs + ";False;" + head + "\n";
}

std::vector<TraceRecord> read_all(const std::string& text) {
  return testing::read_all<SranipalReader>(text);
}
std::string error_of(const std::string& text) {
  return testing::error_of<SranipalReader>(text);
}

constexpr double kDeg = M_PI / 180.0;

TEST(Sranipal, TicksAreUnixNanoseconds) {
  EXPECT_EQ(dotnet_ticks_to_unix_ns(621355968000000000), 0);
  EXPECT_EQ(dotnet_ticks_to_unix_ns(kTicks), kTicksUnixNs);
  EXPECT_EQ(dotnet_ticks_to_unix_ns(-1), std::nullopt);
  EXPECT_EQ(dotnet_ticks_to_unix_ns(std::numeric_limits<std::int64_t>::max()), std::nullopt);
}

TEST(Sranipal, ConvergingEyesLookAheadAndOriginsSitLeftAndRight) {
  // A target 1 m straight ahead seen from eyes 32 mm either side of the middle: SRanipal's +x is
  // the user's left, so the left eye (at +32 mm) turns toward -x and the right eye toward +x.
  const double a = std::atan2(0.032, 1.0);
  char dirs[160];
  std::snprintf(dirs, sizeof dirs, "%.9f;0;%.9f;%.9f;0;%.9f", -std::sin(a), std::cos(a), std::sin(a), std::cos(a));
  const auto r = read_all(kHeader + row(kTicks, 31, 31, dirs));
  ASSERT_EQ(r.size(), 1u);
  const GazeSample& g = r[0].gaze;
  EXPECT_EQ(g.t_ns, kTicksUnixNs);
  EXPECT_TRUE(g.valid);
  EXPECT_FLOAT_EQ(g.confidence, 1.0f);
  EXPECT_NEAR(g.direction.x, 0.0, 1e-9);
  EXPECT_NEAR(g.direction.y, 0.0, 1e-9);
  EXPECT_NEAR(g.direction.z, -1.0, 1e-9);  // OpenXR's forward
  // Origins at (+-32, 0, -40) mm in SRanipal's axes (+z forward): both 40 mm behind the tracker's
  // origin, which is +z in OpenXR's; the mean centred.
  EXPECT_NEAR(g.origin_m.x, 0.0, 1e-12);
  EXPECT_NEAR(g.origin_m.z, 0.040, 1e-12);
}

TEST(Sranipal, OneEyeLeftOfTheUserTurnsToMinusX) {
  // Only the left eye valid (bits 0..4 set), looking 10 deg to the user's left.
  char dirs[160];
  std::snprintf(dirs, sizeof dirs, "%.9f;0;%.9f;0;0;0", std::sin(10 * kDeg), std::cos(10 * kDeg));
  const auto r = read_all(kHeader + row(kTicks, 31, 0, dirs));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(r[0].gaze.valid);
  EXPECT_FLOAT_EQ(r[0].gaze.confidence, 0.5f);
  EXPECT_NEAR(std::atan2(r[0].gaze.direction.x, -r[0].gaze.direction.z) / kDeg, -10.0, 1e-6);  // 9 decimals written
  EXPECT_NEAR(r[0].gaze.origin_m.x, -0.032, 1e-12);  // the left eye's origin only
}

TEST(Sranipal, ValidityBitsDecide) {
  const std::string ahead = "0;0;1;0;0;1";
  const auto r = read_all(kHeader + row(kTicks, 0, 0, ahead) +      // both lost (a blink)
                          row(kTicks + 1, 29, 29, ahead) +          // bit 1 (direction) clear
                          row(kTicks + 2, 2, 0, ahead) +            // direction without origin
                          row(kTicks + 3, 31, 31, "0;0;0;0;0;0"));  // flagged, but no vector
  ASSERT_EQ(r.size(), 4u);
  EXPECT_FALSE(r[0].gaze.valid);
  EXPECT_FALSE(r[1].gaze.valid);
  EXPECT_TRUE(r[2].gaze.valid);
  EXPECT_EQ(r[2].gaze.origin_m, glm::dvec3(0.0));
  EXPECT_FALSE(r[3].gaze.valid);
  EXPECT_EQ(r[3].gaze.t_ns, kTicksUnixNs + 300);  // one tick is 100 ns
  for (const TraceRecord& x : r) {
    if (!x.gaze.valid) {
      EXPECT_EQ(x.gaze.confidence, 0.0f);
    }
  }
  // A lost eye's columns are not read (SRanipal may leave them empty or NaN); the origin is
  // that of the eyes whose direction is used: here the left eye's, not the right's (bit 0 only).
  std::string lost = row(kTicks, 31, 1, "0;0;1;nan;;");
  lost.replace(lost.find(";-32;0;-40;"), 11, ";-320;0;-40;");
  const auto one = read_all(kHeader + lost);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_TRUE(one[0].gaze.valid);
  EXPECT_FLOAT_EQ(one[0].gaze.confidence, 0.5f);
  EXPECT_NEAR(one[0].gaze.origin_m.x, -0.032, 1e-12);
}

TEST(Sranipal, UnityHeadPoseBecomesOpenXrs) {
  const glm::dvec3 forward(0, 0, -1);
  // eulerAngles.y = 270: turned 90 deg to the left, so OpenXR's forward points to -x.
  const glm::dvec3 left = unity_euler_deg_to_openxr({0, 270, 0}) * forward;
  EXPECT_NEAR(left.x, -1.0, 1e-12);
  EXPECT_NEAR(left.z, 0.0, 1e-12);
  // eulerAngles.x = 30: pitched 30 deg down.
  const glm::dvec3 down = unity_euler_deg_to_openxr({30, 0, 0}) * forward;
  EXPECT_NEAR(down.y, -0.5, 1e-12);
  // eulerAngles.z = 20: rolled 20 deg, the top of the head toward the left shoulder (-x).
  const glm::dvec3 up = unity_euler_deg_to_openxr({0, 0, 20}) * glm::dvec3(0, 1, 0);
  EXPECT_NEAR(up.x, -std::sin(20 * kDeg), 1e-12);
  // The order: z, then x, then y. Yaw 90 left after pitch 30 down: forward goes left and down.
  const glm::dvec3 both = unity_euler_deg_to_openxr({30, 270, 0}) * forward;
  EXPECT_NEAR(both.x, -std::cos(30 * kDeg), 1e-12);
  EXPECT_NEAR(both.y, -0.5, 1e-12);
  // In a row: Unity's +z forward becomes -z; the position's z is negated.
  const auto r = read_all(kHeader + row(kTicks, 31, 31, "0;0;1;0;0;1", "0.5;1.6;2;0;270;0"));
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].has_head);
  EXPECT_TRUE(r[0].head.valid);
  EXPECT_EQ(r[0].head.t_ns, kTicksUnixNs);
  EXPECT_EQ(r[0].head.position_m, glm::dvec3(0.5, 1.6, -2.0));
  EXPECT_NEAR((r[0].head.orientation * forward).x, -1.0, 1e-9);
}

TEST(Sranipal, WithoutHelmetColumnsThereIsNoHead) {
  std::istringstream in(
      "time(100ns);eye_valid_L;eye_valid_R;gaze_direct_L.x;gaze_direct_L.y;gaze_direct_L.z;"
      "gaze_direct_R.x;gaze_direct_R.y;gaze_direct_R.z\n" +
      std::to_string(kTicks) + ";31;31;0;0;1;0;0;1\n");
  SranipalReader r(in, "vive.csv");
  EXPECT_FALSE(r.has_head());
  TraceRecord rec;
  ASSERT_TRUE(r.next(rec));
  EXPECT_FALSE(rec.has_head);
  EXPECT_TRUE(rec.gaze.valid);
}

TEST(Sranipal, ErrorsNameFileLineAndColumn) {
  const auto has = [](const std::string& text, const std::string& what) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(what), std::string::npos) << "got: " << e;
  };
  has("time(100ns);eye_valid_L;gaze_direct_L.x\n",
      "in.csv:1: missing required SRanipal (HTC Vive Pro Eye) column(s): gaze_direct_L.y,gaze_direct_L.z,"
      "eye_valid_R,gaze_direct_R.x");
  has(kHeader + row(kTicks, 32, 31, "0;0;1;0;0;1"), "in.csv:2:");
  has(kHeader + row(kTicks, 32, 31, "0;0;1;0;0;1"), "eye_valid_L: must be in [0, 31] (validity bits)");
  has(kHeader + row(kTicks, 31, 31, "0;0;2;0;0;1"), "gaze_direct_L: not a unit vector (length 2.0");
  has(kHeader + row(kTicks, 31, 31, "0;0;1;0;0;x"), "gaze_direct_R.z: 'x' is not a number");
  has(kHeader + row(-5, 31, 31, "0;0;1;0;0;1"), "time(100ns): not a .NET tick count");
  {
    std::string far = row(kTicks, 31, 31, "0;0;1;0;0;1");
    far.replace(far.find(";32;0;-40;"), 10, ";3200;0;-40;");
    has(kHeader + far, "gaze_origin_L.x(mm): beyond 1000 mm of the eye tracker");
  }
  has(kHeader + row(kTicks + 10, 31, 31, "0;0;1;0;0;1") + row(kTicks, 31, 31, "0;0;1;0;0;1"),
      "in.csv:3:1: time goes backwards");
  has(kHeader + "1;2;3\n", "in.csv:2: row has 3 fields, header has 26");
  has(kHeader + row(kTicks, 31, 31, "0;0;1;0,06;0;0,998"),
      "gaze_direct_R.x: '0,06' has a decimal comma (the logger wrote its locale's numbers)");
  has(kHeader + row(kTicks, 31, 31, "0;0;1;0;0;1", "0;1.6;2e7;0;0;0"), "helmet_pos_z: beyond 1000 km of the origin");
  has(kHeader + row(kTicks, 31, 31, "0;0;1;0;0;1", "0;1.6;0;0;1e308;0"), "helmet_rot_y: beyond +-720 deg");
  has("time(100ns),eye_valid_L,eye_valid_R\n", "in.csv:1: an SRanipal (HTC Vive Pro Eye) header separated by commas");
  // Lenient: the bad row is skipped and listed, the rest read.
  std::istringstream in(kHeader + row(kTicks, 32, 31, "0;0;1;0;0;1") + row(kTicks + 1, 31, 31, "0;0;1;0;0;1"));
  SranipalReader lenient(in, "vive.csv", {.lenient = true});
  TraceRecord rec;
  ASSERT_TRUE(lenient.next(rec));
  EXPECT_FALSE(lenient.next(rec));
  EXPECT_EQ(lenient.skipped().skipped, 1u);
}

TEST(Sranipal, DetectedFromItsSemicolonHeader) {
  using V = std::vector<std::string>;
  EXPECT_EQ(detect_trace_format(V{"time(100ns)", "eye_valid_L", "gaze_direct_L.x"}, false), TraceFormat::sranipal);
  EXPECT_EQ(parse_trace_format("sranipal"), TraceFormat::sranipal);
  EXPECT_EQ(trace_format_name(TraceFormat::sranipal), "sranipal");
  const auto path =
      std::filesystem::temp_directory_path() / ("gazelod-sranipal-" + std::to_string(::getpid()) + ".csv");
  std::ofstream(path) << kHeader << row(kTicks, 31, 31, "0;0;1;0;0;1");
  const auto s = open_trace(path.string(), TraceFormat::automatic);
  EXPECT_EQ(opened_trace_format(*s), TraceFormat::sranipal);
  EXPECT_TRUE(s->has_head());
  TraceRecord rec;
  EXPECT_TRUE(s->next(rec));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace gazelod::gaze
