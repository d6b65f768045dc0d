// SPDX-License-Identifier: Apache-2.0
// Streaming reader of gazelod's own gaze-trace CSV (spec: docs/gaze.md). Reads one line at a
// time; reads back exactly what TraceWriter writes. Errors name file:line:column.
#pragma once

#include "gaze/record_stream.hpp"

#include <optional>

namespace gazelod::gaze {

class TraceReader : public CsvRecordStream {
 public:
  // Reads and checks the header; throws TraceError naming missing required columns.
  TraceReader(std::istream& in, std::string file, ReadOptions options = {});
  bool has_head() const override { return head_q_.has_value(); }
  int version() const { return version_; }

  // Tolerance on |gaze| and |q| (trackers write ~6 significant digits).
  static constexpr double kUnitTolerance = 1e-3;

 protected:
  void parse_row(TraceRecord& out) override;

 private:
  struct Cols3 {
    std::size_t x, y, z;
  };
  struct Cols4 {
    std::size_t w, x, y, z;
  };
  bool time_ns_ = true;
  std::optional<Cols3> gaze_vec_, eye_, head_p_;
  std::optional<std::pair<std::size_t, std::size_t>> yaw_pitch_;
  std::optional<Cols4> head_q_;
  std::optional<std::size_t> valid_, confidence_, head_valid_;
  std::size_t header_fields_ = 0;
  int version_ = 0;  // 0 = no version line (hand-written file)
};

// Direction in head space (OpenXR axes) from the trace format's gaze_yaw_deg (positive = right,
// the opposite of auxiliary/yaw_pitch.hpp's convention) and gaze_pitch_deg (positive = up); also
// the GazeBaseVR and Pupil Cloud importers' angles, which the format shares.
glm::dvec3 direction_from_yaw_pitch_deg(double yaw_right_deg, double pitch_up_deg);

}  // namespace gazelod::gaze
