// SPDX-License-Identifier: Apache-2.0
// Importer for HTC Vive Pro Eye recordings logged from Unity through HTC's SRanipal SDK: one
// semicolon-separated row per eye-tracker sample (about 120 Hz), per-eye validity, gaze
// direction and origin, and the headset's pose.
//
// Columns used (names as the logger writes them):
//   time(100ns)                       .NET DateTime ticks (100 ns since 0001-01-01), taken as
//                                     UTC: t_ns = (ticks - Unix epoch's ticks) * 100
//   eye_valid_L, eye_valid_R          SRanipal's SingleEyeDataValidity bits (0..31): bit 0 gaze
//                                     origin, bit 1 gaze direction, 2 pupil diameter, 3 openness,
//                                     4 pupil position in the sensor area
//   gaze_direct_{L,R}.{x,y,z}         unit gaze direction per eye, SRanipal's right-handed eye
//                                     frame: +x to the user's left, +y up, +z forward
//   gaze_origin_{L,R}.{x,y,z}(mm)     optional: each eye's position, same frame, millimetres
//   helmet_pos_{x,y,z}, helmet_rot_{x,y,z}
//                                     optional: the headset in Unity's world (metres; Euler angles
//                                     in degrees as Transform.eulerAngles: z, then x, then y)
// Everything else (openness, pupil sizes, frown / squeeze / wide, the convergence distance) is
// read past.
//
// Conversions to OpenXR's right-handed head space (+x right, +y up, -z forward):
//   - SRanipal's eye frame is OpenXR's turned 180 deg about +y: (x, y, z) -> (-x, y, -z). (A near
//     target makes the eyes converge: the left eye turns right, the right eye left.)
//   - Unity's world is left-handed (+z forward): positions (x, y, z) -> (x, y, -z); a rotation
//     mirrored through z keeps its z component and negates x and y: q (w, x, y, z) ->
//     (w, -x, -y, z).
// A sample is valid when at least one eye's gaze direction is valid (bit 1) and non-zero; the
// gaze is the normalised mean of the valid eyes' directions (a cyclopean gaze), its origin the
// mean of those eyes' origins flagged valid (bit 0); an eye's columns are read only when its
// direction bit is set. Invalid samples (blinks, lost tracking) are kept as invalid, not
// dropped. Confidence: 1 with both eyes, 0.5 with one, 0 for an invalid sample. Where one eye
// drops out the cyclopean gaze moves by half the eyes' vergence (a degree or two at arm's
// length), as SRanipal's own combined gaze does.
#pragma once

#include "gaze/record_stream.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>

namespace gazelod::gaze {

class SranipalReader : public CsvRecordStream {
 public:
  SranipalReader(std::istream& in, std::string file, ReadOptions options = {});
  bool has_head() const override { return head_.has_value(); }

 protected:
  void parse_row(TraceRecord& out) override;

 private:
  double number(std::size_t index, const char* name) const;
  using Cols3 = std::array<std::size_t, 3>;
  std::size_t t_ = 0, fields_ = 0;
  std::array<std::size_t, 2> valid_{};
  std::array<Cols3, 2> direction_{};
  std::optional<std::array<Cols3, 2>> origin_;
  struct HeadCols {
    Cols3 position, rotation;
  };
  std::optional<HeadCols> head_;
};

// .NET DateTime ticks (100 ns since 0001-01-01) to Unix nanoseconds, or nullopt when the result
// is outside int64.
std::optional<std::int64_t> dotnet_ticks_to_unix_ns(std::int64_t ticks);

// SRanipal's eye frame (+x left, +y up, +z forward) to OpenXR head axes.
inline glm::dvec3 sranipal_to_openxr(const glm::dvec3& v) {
  return {-v.x, v.y, -v.z};
}

// Unity's Transform.eulerAngles (degrees; applied z, then x, then y) to the same rotation in
// OpenXR's axes.
glm::dquat unity_euler_deg_to_openxr(const glm::dvec3& euler_deg);

}  // namespace gazelod::gaze
