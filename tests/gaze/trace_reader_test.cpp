// SPDX-License-Identifier: Apache-2.0
// Trace writer/reader: exact round trip, header rules, and every error naming file:line:column.
#include "gaze/trace_reader.hpp"
#include "gaze/trace_writer.hpp"
#include "tests/gaze/trace_test_util.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <sstream>

namespace gazelod::gaze {
namespace {

std::vector<TraceRecord> read_all(const std::string& text, ReadOptions o = {}, SkipReport* skipped = nullptr) {
  std::istringstream in(text);
  TraceReader r(in, "t.csv", o);
  std::vector<TraceRecord> out;
  TraceRecord rec;
  while (r.next(rec)) out.push_back(rec);
  if (skipped) *skipped = r.skipped();
  return out;
}

// The TraceError message for `text`, or "" when it reads fine.
std::string error_of(const std::string& text) {
  try {
    read_all(text);
  } catch (const TraceError& e) {
    return e.what();
  }
  return "";
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expect_identical(const TraceRecord& a, const TraceRecord& b, std::size_t i) {
  SCOPED_TRACE(i);
  EXPECT_EQ(a.gaze.t_ns, b.gaze.t_ns);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(same_bits(a.gaze.direction[k], b.gaze.direction[k]));
    EXPECT_TRUE(same_bits(a.gaze.origin_m[k], b.gaze.origin_m[k]));
  }
  EXPECT_EQ(a.gaze.valid, b.gaze.valid);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(a.gaze.confidence), std::bit_cast<std::uint32_t>(b.gaze.confidence));
  ASSERT_EQ(a.has_head, b.has_head);
  if (a.has_head) {
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(same_bits(a.head.orientation[k], b.head.orientation[k]));
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(a.head.position_m[k], b.head.position_m[k]));
    EXPECT_EQ(a.head.valid, b.head.valid);
    EXPECT_EQ(a.head.t_ns, b.head.t_ns);
  }
}

TEST(TraceRoundTrip, TenSecondsAt250HzIsBitIdentical) {
  const auto trace = testing::random_trace(10.0, 250.0);
  ASSERT_EQ(trace.size(), 2500u);
  std::ostringstream out;
  TraceWriter w(out);
  for (const auto& r : trace) w.write(r);
  const auto back = read_all(out.str());
  ASSERT_EQ(back.size(), trace.size());
  for (std::size_t i = 0; i < trace.size(); ++i) expect_identical(trace[i], back[i], i);
}

TEST(TraceRoundTrip, SecondsColumnRecoversNanoseconds) {
  const auto trace = testing::random_trace(2.0, 250.0, 11);
  std::ostringstream out;
  TraceWriter w(out, {.time_in_ns = false, .write_head = false});
  for (const auto& r : trace) w.write(r);
  EXPECT_NE(out.str().find("t_s,"), std::string::npos);
  const auto back = read_all(out.str());
  ASSERT_EQ(back.size(), trace.size());
  for (std::size_t i = 0; i < trace.size(); ++i) {
    EXPECT_EQ(back[i].gaze.t_ns, trace[i].gaze.t_ns);
    EXPECT_FALSE(back[i].has_head);
  }
}

TEST(TraceReader, WriterHeaderCarriesVersion) {
  std::ostringstream out;
  TraceWriter w(out);
  std::istringstream in(out.str());
  TraceReader r(in, "v.csv");
  EXPECT_EQ(r.version(), 1);
  EXPECT_TRUE(r.has_head());
}

TEST(TraceReader, RejectsNewerVersion) {
  EXPECT_NE(error_of("# gazelod-trace 99\nt_ns,gaze_x,gaze_y,gaze_z\n").find("newer"), std::string::npos);
}

TEST(TraceReader, UnknownColumnsIgnoredAndDefaults) {
  const auto recs = read_all("t_ns,extra,gaze_x,gaze_y,gaze_z,note\n10,abc,0,0,-1,hi\n");
  ASSERT_EQ(recs.size(), 1u);
  EXPECT_EQ(recs[0].gaze.t_ns, 10);
  EXPECT_TRUE(recs[0].gaze.valid);
  EXPECT_EQ(recs[0].gaze.confidence, 1.0f);
  EXPECT_FALSE(recs[0].has_head);
}

TEST(TraceReader, MissingColumnsAreNamed) {
  const std::string e = error_of("time,gaze_x,gaze_y\n");
  EXPECT_NE(e.find("t.csv:1: missing required column(s)"), std::string::npos) << e;
  EXPECT_NE(e.find("t_ns or t_s"), std::string::npos) << e;
  EXPECT_NE(e.find("gaze_z"), std::string::npos) << e;
  EXPECT_NE(error_of("t_s,gaze_x,gaze_y,gaze_z,head_qw\n").find("head_qx"), std::string::npos);
  EXPECT_NE(error_of("t_s,valid\n").find("gaze_yaw_deg,gaze_pitch_deg"), std::string::npos);
  EXPECT_NE(error_of("").find("empty file"), std::string::npos);
}

TEST(TraceReader, YawPitchAlternative) {
  // yaw +90 (right) = +X; pitch +90 (up) = +Y; 0,0 = -Z (forward).
  const auto r = read_all("t_s,gaze_yaw_deg,gaze_pitch_deg\n0,0,0\n1,90,0\n2,0,90\n3,-30,10\n");
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(r[0].gaze.direction.z, -1.0, 1e-15);
  EXPECT_NEAR(r[1].gaze.direction.x, 1.0, 1e-15);
  EXPECT_NEAR(r[2].gaze.direction.y, 1.0, 1e-15);
  // Independent: horizontal angle atan2(x, -z) = yaw, elevation asin(y) = pitch.
  const auto d = r[3].gaze.direction;
  EXPECT_NEAR(std::atan2(d.x, -d.z) * 180.0 / M_PI, -30.0, 1e-12);
  EXPECT_NEAR(std::atan2(d.y, std::hypot(d.x, d.z)) * 180.0 / M_PI, 10.0, 1e-12);
  EXPECT_EQ(r[3].gaze.t_ns, 3'000'000'000);
  EXPECT_NE(error_of("t_s,gaze_yaw_deg,gaze_pitch_deg\n0,0,95\n").find("t.csv:2:5: gaze_pitch_deg"), std::string::npos);
}

TEST(TraceReader, ErrorsNameLineAndColumn) {
  const std::string h = "t_ns,gaze_x,gaze_y,gaze_z,valid\n";
  // Line 3 is bad; the column points at the field.
  EXPECT_NE(error_of(h + "1,0,0,-1,1\n2,0,abc,-1,1\n").find("t.csv:3:5: gaze_y: 'abc' is not a number"),
            std::string::npos)
      << error_of(h + "1,0,0,-1,1\n2,0,abc,-1,1\n");
  EXPECT_NE(error_of(h + "1,0,nan,-1,1\n").find("t.csv:2:5: gaze_y: NaN"), std::string::npos);
  EXPECT_NE(error_of(h + "5,0,0,-1,1\n4,0,0,-1,1\n").find("t.csv:3:1: time goes backwards"), std::string::npos);
  // Times whose difference would overflow 64 bits (every consumer subtracts two of them).
  EXPECT_NE(error_of(h + "-9223372036854775808,0,0,-1,1\n9223372036854775807,0,0,-1,1\n")
                .find("t.csv:2:1: time -9223372036854775808 ns is not within +-2^62 ns"),
            std::string::npos);
  EXPECT_EQ(error_of(h + "-4611686018427387903,0,0,-1,1\n4611686018427387903,0,0,-1,1\n"), "");
  EXPECT_NE(error_of(h + "1,0,0,0,1\n").find("t.csv:2:3: zero gaze vector"), std::string::npos);
  EXPECT_NE(error_of(h + "1,0,0,-2,1\n").find("t.csv:2:3: gaze vector is not unit"), std::string::npos);
  EXPECT_NE(error_of(h + "1,0,0,-1,2\n").find("t.csv:2:10: valid"), std::string::npos);
  EXPECT_NE(error_of(h + "1,0,0,-1\n").find("t.csv:2: row has 4 fields"), std::string::npos);
  EXPECT_NE(error_of(h + "1.5,0,0,-1,1\n").find("not an integer"), std::string::npos);
  EXPECT_NE(error_of(h + "1,0,0,inf,1\n").find("infinite"), std::string::npos);
  // Invalid samples may carry a zero vector (blinks); equal timestamps are not backwards.
  EXPECT_EQ(error_of(h + "1,0,0,0,0\n1,0,0,-1,1\n"), "");
  // Physical ranges: an eye within 1 m of the head, a head within 1000 km (1e308 passed).
  const std::string eh =
      "t_ns,gaze_x,gaze_y,gaze_z,eye_px,eye_py,eye_pz,head_qw,head_qx,head_qy,head_qz,"
      "head_px,head_py,head_pz\n";
  EXPECT_NE(error_of(eh + "1,0,0,-1,1e300,0,0,1,0,0,0,0,0,0\n").find("t.csv:2:10: eye_px: beyond 1 m of the head's"),
            std::string::npos)
      << error_of(eh + "1,0,0,-1,1e300,0,0,1,0,0,0,0,0,0\n");
  EXPECT_NE(error_of(eh + "1,0,0,-1,0.03,0,0,1,0,0,0,0,1e308,0\n").find("head_py: beyond 1000 km of the origin"),
            std::string::npos);
  EXPECT_EQ(error_of(eh + "1,0,0,-1,0.03,0,0,1,0,0,0,0,1.6,999999\n"), "");
}

TEST(TraceReader, LenientSkipsAndReportsEveryBadLine) {
  const std::string text =
      "t_ns,gaze_x,gaze_y,gaze_z\n1,0,0,-1\n2,x,0,-1\n3,0,0,-1\n# comment\n\n2,0,0,-1\n"
      "4,0,0,-1\n";
  SkipReport skipped;
  const auto recs = read_all(text, {.lenient = true}, &skipped);
  ASSERT_EQ(recs.size(), 3u);
  EXPECT_EQ(recs[2].gaze.t_ns, 4);
  ASSERT_EQ(skipped.skipped, 2u);
  EXPECT_EQ(skipped.first[0].line, 3u);
  EXPECT_EQ(skipped.first[1].line, 7u);
  EXPECT_NE(skipped.first[1].message.find("backwards"), std::string::npos);
}

TEST(TraceReader, WindowsLineEndingsBomAndQuotes) {
  const auto r = read_all("\xEF\xBB\xBFt_ns,\"gaze_x\",gaze_y,gaze_z\r\n7,\"0\",0,-1\r\n");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].gaze.t_ns, 7);
  EXPECT_EQ(r[0].gaze.direction.z, -1.0);
  // Duplicate column names are ambiguous: an error naming the column.
  EXPECT_NE(error_of("t_ns,gaze_x,gaze_y,gaze_z,gaze_x\n").find("t.csv:1:27: duplicate column 'gaze_x'"),
            std::string::npos);
}

TEST(TraceReader, HeadQuaternionChecked) {
  const std::string h = "t_ns,gaze_x,gaze_y,gaze_z,head_qw,head_qx,head_qy,head_qz\n";
  EXPECT_NE(error_of(h + "1,0,0,-1,0,0,0,0\n").find("t.csv:2:10: head quaternion"), std::string::npos);
  const auto r = read_all(h + "1,0,0,-1,0,0,1,0\n2,0,0,-1,,,,\n");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(r[0].has_head);
  EXPECT_EQ(r[0].head.orientation.y, 1.0);
  EXPECT_FALSE(r[1].has_head);
}

}  // namespace
}  // namespace gazelod::gaze
