// SPDX-License-Identifier: Apache-2.0
// GazeBaseVR and Pupil Labs importers: column mapping, axis conversion, missing-data marks.
#include "gaze/import_gazebasevr.hpp"
#include "gaze/import_pupil.hpp"
#include "gaze/trace_open.hpp"
#include "tests/gaze/trace_test_util.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace gazelod::gaze {
namespace {

using testing::error_of;
using testing::read_all;

constexpr double kDeg = M_PI / 180.0;

const char* kGbvrHeader = "n,x,y,lx,ly,rx,ry,xT,yT,zT\n";

TEST(GazeBaseVr, MapsDegreesAndMilliseconds) {
  const auto r = read_all<GazeBaseVrReader>(std::string(kGbvrHeader) +
                                            "0,0,0,0,0,0,0,0,0,1\n"
                                            "4,10,-5,10,-5,10,-5,0,0,1\n"
                                            "8,NaN,NaN,NaN,NaN,NaN,NaN,0,0,1\n");
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[1].gaze.t_ns, 4'000'000);
  EXPECT_TRUE(r[1].gaze.valid);
  const auto d = r[1].gaze.direction;
  // Independent check: longitude atan2(x, -z) = 10 deg right, latitude = -5 deg (down).
  EXPECT_NEAR(std::atan2(d.x, -d.z) / kDeg, 10.0, 1e-12);
  EXPECT_NEAR(std::atan2(d.y, std::hypot(d.x, d.z)) / kDeg, -5.0, 1e-12);
  EXPECT_GT(d.x, 0.0);
  EXPECT_FALSE(r[2].gaze.valid);  // NaN marks lost tracking: invalid, not an error
  EXPECT_EQ(r[2].gaze.t_ns, 8'000'000);
}

TEST(GazeBaseVr, ErrorsNameLine) {
  EXPECT_NE(error_of<GazeBaseVrReader>("n,lx,ly\n").find("in.csv:1: missing required GazeBaseVR column(s): x,y"),
            std::string::npos);
  EXPECT_NE(error_of<GazeBaseVrReader>(std::string(kGbvrHeader) + "4,0,0,0,0,0,0,0,0,1\n"
                                                                  "2,0,0,0,0,0,0,0,0,1\n")
                .find("in.csv:3:1: time goes backwards"),
            std::string::npos);
  EXPECT_NE(error_of<GazeBaseVrReader>(std::string(kGbvrHeader) + "4,1,x,0,0,0,0,0,0,1\n").find("in.csv:2:5: y:"),
            std::string::npos);
}

const char* kPupilHeader =
    "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data,gaze_point_3d_x,"
    "gaze_point_3d_y,gaze_point_3d_z,eye_center0_3d_x,eye_center0_3d_y,eye_center0_3d_z,"
    "eye_center1_3d_x,eye_center1_3d_y,eye_center1_3d_z\n";

TEST(Pupil, ConvertsOpenCvCameraAxesToOpenXr) {
  // Eyes at (+-30, 0, -20) mm: cyclopean (0, 0, -20). Gaze point straight ahead and a little
  // down in camera space (+y is down): (0, 100, 480) -> relative (0, 100, 500).
  const auto r = read_all<PupilReader>(std::string(kPupilHeader) +
                                       "100.5,3,0.95,0.5,0.4,\"1 2\",0,100,480,-30,0,-20,30,0,-20\n"
                                       "100.504,3,0.3,0.5,0.4,x,0,0,500,-30,0,-20,30,0,-20\n"
                                       "100.508,3,0.99,0.5,0.4,x,,,,-30,0,-20,30,0,-20\n");
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].gaze.t_ns, 100'500'000'000);
  EXPECT_TRUE(r[0].gaze.valid);
  const auto d = r[0].gaze.direction;
  EXPECT_NEAR(d.x, 0.0, 1e-15);
  EXPECT_LT(d.y, 0.0);  // camera +y (down) becomes OpenXR -y
  EXPECT_LT(d.z, 0.0);  // camera +z (forward) becomes OpenXR -z
  EXPECT_NEAR(std::atan2(-d.y, -d.z), std::atan2(100.0, 500.0), 1e-12);
  EXPECT_NEAR(r[0].gaze.origin_m.z, 0.020, 1e-15);  // -(-20 mm)
  EXPECT_FLOAT_EQ(r[0].gaze.confidence, 0.95f);
  EXPECT_FALSE(r[1].gaze.valid);  // confidence 0.3 < 0.6
  EXPECT_FALSE(r[2].gaze.valid);  // no 3D gaze point
}

TEST(Pupil, TwoDimensionalExportRejectedByName) {
  const std::string e = error_of<PupilReader>("gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y\n");
  EXPECT_NE(e.find("gaze_point_3d_x"), std::string::npos) << e;
  EXPECT_NE(e.find("intrinsics"), std::string::npos) << e;
}

TEST(Pupil, LenientCountsBadLines) {
  std::istringstream in(std::string(kPupilHeader) +
                        "1,0,0.9,0,0,x,0,0,500,,,,,,\n"
                        "1.1,0,bad,0,0,x,0,0,500,,,,,,\n"
                        "1.2,0,0.9,0,0,x,0,0,500,,,,,,\n");
  PupilReader r(in, "p.csv", {.lenient = true});
  TraceRecord rec;
  int n = 0;
  while (r.next(rec)) ++n;
  EXPECT_EQ(n, 2);
  ASSERT_EQ(r.skipped().skipped, 1u);
  EXPECT_EQ(r.skipped().first[0].line, 3u);
  EXPECT_EQ(r.skipped().first[0].column, 7u);
}

// Numbers near the double range are numbers: they must give a unit direction or a located
// error, never a NaN or zero direction marked valid (squaring 1e200 overflows).
TEST(Pupil, HugeCoordinatesGiveUnitDirectionsOrErrors) {
  const auto r = read_all<PupilReader>(std::string(kPupilHeader) + "1,0,0.9,0,0,x,1e200,0,0,,,,,,\n" +
                                       "1.1,0,0.9,0,0,x,0,1.7e308,1e300,-30,0,-20,30,0,-20\n");
  ASSERT_EQ(r.size(), 2u);
  for (const auto& rec : r) {
    ASSERT_TRUE(rec.gaze.valid);
    EXPECT_NEAR(glm::length(rec.gaze.direction), 1.0, 1e-12);
  }
  EXPECT_NEAR(r[0].gaze.direction.x, 1.0, 1e-12);
  EXPECT_NEAR(r[1].gaze.direction.y, -1.0, 1e-12);  // camera +y (down) -> OpenXR -y
  const std::string e = error_of<PupilReader>(std::string(kPupilHeader) + "1,0,0.9,0,0,x,1e308,0,500,-1e308,0,0,,,\n");
  EXPECT_NE(e.find("in.csv:2:27: eye_center0_3d_x: outside +-1000 mm"), std::string::npos) << e;
}

TEST(TraceOpen, FormatsAndMissingFile) {
  EXPECT_EQ(parse_trace_format("pupil"), TraceFormat::pupil);
  EXPECT_FALSE(parse_trace_format("csv").has_value());
  for (auto f : {TraceFormat::gazelod, TraceFormat::gazebasevr, TraceFormat::pupil})
    EXPECT_EQ(parse_trace_format(trace_format_name(f)), f);
  try {
    open_trace("/nonexistent/trace.csv", TraceFormat::gazelod);
    FAIL() << "no error";
  } catch (const TraceError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/trace.csv"), std::string::npos);
  }
}

}  // namespace
}  // namespace gazelod::gaze
