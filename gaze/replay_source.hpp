// SPDX-License-Identifier: Apache-2.0
// Trace replay as a GazeSource. The trace is loaded once (one copy in memory; reading it is
// streaming) so that sample_at() never touches a file: it only searches and interpolates.
//  - Between two valid samples less than max_interp_gap apart and neither labelled saccade
//    (I-VT, ivt_classifier.hpp), gaze is interpolated by angle (slerp of directions) and head
//    orientation by quaternion slerp (shortest path, robust to q/-q).
//  - Otherwise the last valid sample is held (sample-and-hold, its t_ns says how old it is)
//    for at most hold_max (blinks last ~100-150 ms), after which gaze is unavailable.
#pragma once

#include "gaze/gaze_source.hpp"
#include "gaze/ivt_classifier.hpp"
#include "gaze/record_stream.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::gaze {

struct ReplayOptions {
  std::int64_t time_offset_ns = 0;              // host time = trace time + offset
  std::int64_t max_interp_gap_ns = 25'000'000;  // no interpolation across dropped samples
  std::int64_t hold_max_ns = 150'000'000;       // hold-last-good bound
  IvtOptions ivt;                               // saccade labels: no interpolation across
};

class ReplaySource : public GazeSource {
 public:
  // `records` in non-decreasing time (as every RecordStream yields); throws
  // std::invalid_argument otherwise.
  explicit ReplaySource(std::vector<TraceRecord> records, ReplayOptions options = {});
  // Reads the whole stream (throws TraceError as the stream does).
  static std::vector<TraceRecord> load(RecordStream& stream);

  std::string name() const override { return "trace"; }
  std::optional<GazeSample> sample_at(std::int64_t t_ns) override;
  std::string status() const override { return status_; }
  // Head pose at host time t_ns (slerp / hold like gaze), nullopt when unavailable.
  std::optional<HeadSample> head_at(std::int64_t t_ns);

  std::size_t size() const { return records_.size(); }
  GazeLabel label(std::size_t i) const { return labels_[i]; }

 private:
  // Index of the last record with t <= trace_t_ns, or nullopt when before the first.
  std::optional<std::size_t> locate(std::int64_t trace_t_ns);
  std::vector<TraceRecord> records_;
  std::vector<GazeLabel> labels_;
  ReplayOptions options_;
  std::size_t cursor_ = 0;
  std::string status_ = "ok";
};

}  // namespace gazelod::gaze
