// SPDX-License-Identifier: Apache-2.0
// Importer for Pupil Labs (Pupil Core / Pupil Player) gaze_positions.csv exports.
// Columns used: gaze_timestamp (s, Pupil time), confidence (0..1), gaze_point_3d_x/y/z (mm,
// 3D world-camera space) and, when present, eye_center0_3d_* / eye_center1_3d_* (mm).
// norm_pos_x/y are 2D image coordinates: they need the world camera's intrinsics to become a
// direction, so a 2D-only export is rejected with a message naming gaze_point_3d_*.
//
// Coordinate conversion: Pupil's 3D camera space is OpenCV's (origin at the world camera,
// +x right, +y down, +z forward into the scene). gazelod's head space is OpenXR's (+x right,
// +y up, -z forward). So p_xr = (x, -y, -z) and mm -> m. The world camera is taken as the
// head frame (its few-cm offset from the eyes and small tilt are not known from the export).
// The gaze direction is from the cyclopean eye centre (mean of the eye centres present) to
// the 3D gaze point, else from the camera origin. A sample is valid when confidence >=
// min_confidence (Pupil's documentation recommends discarding data below 0.6) and the 3D gaze
// point is present (empty/NaN cells mark missing data in these exports).
#pragma once

#include "gaze/record_stream.hpp"

#include <array>
#include <optional>

namespace gazelod::gaze {

struct PupilImportOptions {
  double min_confidence = 0.6;
};

class PupilReader : public CsvRecordStream {
 public:
  PupilReader(std::istream& in, std::string file, ReadOptions options = {}, PupilImportOptions pupil = {});
  bool has_head() const override { return false; }

 protected:
  void parse_row(TraceRecord& out) override;

 private:
  using Cols3 = std::array<std::size_t, 3>;
  std::optional<glm::dvec3> point_mm(const Cols3& cols, const char* const names[3]) const;
  PupilImportOptions pupil_;
  std::size_t t_ = 0, conf_ = 0, fields_ = 0;
  Cols3 gaze_{};
  std::optional<Cols3> eye0_, eye1_;
};

// Pupil 3D camera space (mm, OpenCV axes) -> OpenXR head space (m).
glm::dvec3 pupil_camera_to_openxr_m(const glm::dvec3& p_mm);

}  // namespace gazelod::gaze
