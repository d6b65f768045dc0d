// SPDX-License-Identifier: Apache-2.0
// The SRanipal importer on a real HTC Vive Pro Eye recording (../shared/data/gaze, not part of
// the project): read whole and detected from its header, and its axes checked by physiology.
// While the head turns, the vestibulo-ocular reflex turns the eyes the other way, so a gaze that
// holds a point in the world moves much less in the world than in the head. That holds only
// when the eye directions and the head pose are converted with the right handedness: with
// Unity's rotation taken as it is, or SRanipal's x not mirrored, the world gaze moves about 6x
// faster than with the conversions the importer uses (measured on this file: 60 against 10 deg/s).
#include "auxiliary/angles.hpp"
#include "gaze/trace_open.hpp"
#include "tests/skip_or_fail.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

namespace gazelod::gaze {
namespace {

namespace fs = std::filesystem;

fs::path recording() {
  return fs::path(GAZELOD_SOURCE_DIR) / ".." / "shared" / "data" / "gaze" / "htc_vive_pro_eye_unity_log.csv";
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

TEST(SranipalSample, ReadsWholeAndTheWorldGazeHoldsWhileTheHeadTurns) {
  const fs::path file = recording();
  if (!fs::is_regular_file(file)) GAZELOD_SKIP_OR_FAIL("no " << file << " (../shared/data/gaze, evaluation data)");
  const auto stream = open_trace(file.string(), TraceFormat::automatic);
  ASSERT_EQ(opened_trace_format(*stream), TraceFormat::sranipal);
  ASSERT_TRUE(stream->has_head());
  std::vector<TraceRecord> records;
  TraceRecord r;
  while (stream->next(r)) records.push_back(r);
  ASSERT_GT(records.size(), 1000u);
  const double seconds = double(records.back().gaze.t_ns - records.front().gaze.t_ns) * 1e-9;
  const double rate_hz = double(records.size() - 1) / seconds;
  EXPECT_GT(rate_hz, 100.0);
  EXPECT_LT(rate_hz, 140.0);  // the Vive Pro Eye's 120 Hz
  const auto invalid =
      std::count_if(records.begin(), records.end(), [](const TraceRecord& x) { return !x.gaze.valid; });
  EXPECT_GT(invalid, 0) << "the recording has blinks";
  EXPECT_LT(double(invalid), 0.1 * double(records.size()));

  // Over 100 ms baselines (12 samples: single-sample velocities are mostly the tracker's noise),
  // wherever the head turns faster than 15 deg/s.
  constexpr std::size_t kBaseline = 12;
  const glm::dvec3 forward(0, 0, -1);
  std::vector<double> world_deg_s, in_head_deg_s, head_deg_s;
  for (std::size_t i = 0; i + kBaseline < records.size(); ++i) {
    const TraceRecord &a = records[i], &b = records[i + kBaseline];
    if (!a.gaze.valid || !b.gaze.valid || !a.head.valid || !b.head.valid) continue;
    const double dt_s = double(b.gaze.t_ns - a.gaze.t_ns) * 1e-9;
    if (!(dt_s > 0.0)) continue;
    const double head =
        aux::angle_between_rad(a.head.orientation * forward, b.head.orientation * forward) * aux::kDegPerRad / dt_s;
    if (head < 15.0) continue;
    head_deg_s.push_back(head);
    in_head_deg_s.push_back(aux::angle_between_rad(a.gaze.direction, b.gaze.direction) * aux::kDegPerRad / dt_s);
    world_deg_s.push_back(
        aux::angle_between_rad(a.head.orientation * a.gaze.direction, b.head.orientation * b.gaze.direction) *
        aux::kDegPerRad / dt_s);
  }
  ASSERT_GT(world_deg_s.size(), 200u) << "too few head turns to check the axes";
  const double world = median(world_deg_s), in_head = median(in_head_deg_s);
  std::printf(
      "%zu samples at %.1f Hz, %.1f %% invalid; %zu baselines with the head turning (median %.1f deg/s): "
      "gaze %.1f deg/s in the head, %.1f in the world\n",
      records.size(), rate_hz, 100.0 * double(invalid) / double(records.size()), world_deg_s.size(), median(head_deg_s),
      in_head, world);
  EXPECT_LT(world, 0.5 * in_head);
  EXPECT_LT(world, 15.0);
}

}  // namespace
}  // namespace gazelod::gaze
