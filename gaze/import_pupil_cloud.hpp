// SPDX-License-Identifier: Apache-2.0
// Importer for Pupil Cloud's gaze.csv export (Pupil Invisible and Pupil Neon, "Timeseries
// Data"): `section id,recording id,timestamp [ns],gaze x [px],gaze y [px],worn,fixation id,
// blink id,azimuth [deg],elevation [deg]`. Columns are found by name; Neon exports may add
// columns or lack `fixation id` / `blink id`.
//
// Used: `timestamp [ns]` (Unix time, int64; rebased to the first sample, so t_ns = timestamp -
// first timestamp exactly, no float on the way), `azimuth [deg]`, `elevation [deg]` (required),
// `worn` (0 or 1; 0 = invalid sample; absent = worn), `fixation id` / `blink id` (Pupil Cloud's
// own event ids, empty = none: not used for the trace, kept for comparison, last_ids()),
// `recording id` (must not change within the file). `gaze x/y [px]` are scene-image pixels and
// would need the camera's intrinsics: not used.
//
// Axes: azimuth and elevation are the gaze ray's angles in the scene camera's frame: azimuth
// positive to the right (in the sample export `gaze x [px]` grows with it), elevation positive
// up (`gaze y [px]`, image rows counted downwards, shrinks as it grows). Pupil Labs' own
// conversion (documentation, "IMU Transformations") is, in OpenCV camera axes (+x right, +y down,
// +z forward), (cos el sin az, -sin el, cos el cos az); in gazelod's head space (OpenXR: +x
// right, +y up, -z forward) that is (cos el sin az, sin el, -cos el cos az), the same as
// gaze_yaw_deg = azimuth, gaze_pitch_deg = elevation. The scene camera is taken as the head
// frame (as for Pupil Core, import_pupil.hpp): its tilt on the face is not in the export.
//
// Time: timestamps must increase strictly; a repeated or earlier one is an error naming
// file:line:column (none in the sample export; --lenient skips such rows and lists them).
//
// Blinks: blinks.csv beside the gaze file (pupil_cloud_blinks_path) lists blink intervals;
// a sample with start <= t < end (end is the first sample after the blink: in the sample export
// exactly the samples carrying that `blink id`) is marked as gazelod traces mark blinks:
// valid = false, confidence 0 (trace_format.hpp `valid`). Without a blinks file, the samples
// that carry a `blink id` are marked so.
#pragma once

#include "gaze/record_stream.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace gazelod::gaze {

// One row of blinks.csv, Unix ns: the blink covers start_ns <= t < end_ns.
struct PupilCloudBlink {
  std::int64_t start_ns = 0, end_ns = 0;
};

struct PupilCloudBlinks {
  std::string file;                        // where they came from ("" = none)
  std::vector<PupilCloudBlink> intervals;  // sorted by start
};

// Reads blinks.csv (`start timestamp [ns]`, `end timestamp [ns]` by name; `blink id`,
// `duration [ms]` and the rest ignored). Throws TraceError with file:line:column.
PupilCloudBlinks read_pupil_cloud_blinks(std::istream& in, const std::string& file);

// The blinks file Pupil Cloud writes beside `gaze_path`: .../gaze.csv -> .../blinks.csv and
// .../X_gaze.csv -> .../X_blinks.csv; nullopt for any other name.
std::optional<std::string> pupil_cloud_blinks_path(const std::string& gaze_path);

// Pupil Cloud's own classification of one sample; 0 = not in such an event.
struct PupilCloudEventIds {
  std::uint32_t fixation_id = 0, blink_id = 0;
};

class PupilCloudReader : public CsvRecordStream {
 public:
  PupilCloudReader(std::istream& in, std::string file, ReadOptions options = {}, PupilCloudBlinks blinks = {});
  bool has_head() const override { return false; }

  // Pupil Cloud's ids of the record next() returned last.
  PupilCloudEventIds last_ids() const { return last_ids_; }
  bool has_fixation_ids() const { return fixation_id_.has_value(); }
  bool has_blink_ids() const { return blink_id_.has_value(); }
  const PupilCloudBlinks& blinks() const { return blinks_; }
  std::size_t samples_in_blinks() const { return samples_in_blinks_; }  // marked invalid so far (file or blink id)

 protected:
  void parse_row(TraceRecord& out) override;

 private:
  bool in_blink(std::int64_t unix_ns);
  std::uint32_t event_id(const std::optional<std::size_t>& col, const char* name) const;

  PupilCloudBlinks blinks_;
  std::size_t next_blink_ = 0;         // first interval not yet started
  std::int64_t blink_end_max_ns_ = 0;  // latest end among the started intervals
  bool any_blink_started_ = false;
  std::size_t samples_in_blinks_ = 0;

  std::size_t fields_ = 0, t_ = 0, azimuth_ = 0, elevation_ = 0;
  std::optional<std::size_t> worn_, fixation_id_, blink_id_, recording_id_;
  std::string recording_id_value_;
  bool have_first_ = false;
  std::int64_t first_unix_ns_ = 0, last_unix_ns_ = 0;
  PupilCloudEventIds last_ids_;
};

}  // namespace gazelod::gaze
