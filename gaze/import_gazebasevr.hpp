// SPDX-License-Identifier: Apache-2.0
// Importer for GazeBaseVR recordings (Lohr et al. 2023, Sci Data 10:177; 250 Hz, SRanipal on
// an HTC Vive Pro Eye). Columns used: n (ms since recording start), x, y (cyclopean gaze, deg
// of visual angle: x horizontal positive right, y vertical positive up). lx, ly, rx, ry (per-eye
// angles), xT, yT, zT (target) and the eye-centre columns are read past but not used. NaN in x
// or y is the data set's mark for lost tracking (blinks): such a sample becomes invalid, it is
// not an error. The angles are taken as longitude/latitude (Fick): direction =
// (cos y sin x, sin y, -cos y cos x) in OpenXR head axes, the same as gaze_yaw_deg/pitch_deg.
#pragma once

#include "gaze/record_stream.hpp"

namespace gazelod::gaze {

class GazeBaseVrReader : public CsvRecordStream {
 public:
  GazeBaseVrReader(std::istream& in, std::string file, ReadOptions options = {});
  bool has_head() const override { return false; }

 protected:
  void parse_row(TraceRecord& out) override;

 private:
  std::size_t n_ = 0, x_ = 0, y_ = 0, fields_ = 0;
};

}  // namespace gazelod::gaze
