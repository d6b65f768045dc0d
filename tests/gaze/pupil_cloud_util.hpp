// SPDX-License-Identifier: Apache-2.0
// Test helpers: Pupil Cloud gaze.csv / blinks.csv text in the export's exact layout, from
// synthetic gaze (tests/gaze/synth.hpp) with Pupil's own fixation and blink ids per sample.
#pragma once

#include "auxiliary/angles.hpp"
#include "tests/gaze/synth.hpp"

#include <glm/geometric.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::gaze::testing {

inline constexpr const char* kPupilCloudGazeHeader =
    "section id,recording id,timestamp [ns],gaze x [px],gaze y [px],worn,fixation id,blink id,"
    "azimuth [deg],elevation [deg]\n";
inline constexpr const char* kPupilCloudBlinksHeader =
    "section id,recording id,blink id,start timestamp [ns],end timestamp [ns],duration [ms]\n";
// Made-up ids in the export's UUID form.
inline constexpr const char* kSection = "3c7e2a51-9d0b-4f6e-8a21-5b9c0d4e7f12";
inline constexpr const char* kRecording = "a4d19f30-62c8-4b7a-9e55-1f0c3b8d2e64";
inline constexpr std::int64_t kUnixStartNs = 1'650'316'509'598'345'895;

struct PupilCloudRow {
  std::int64_t t_unix_ns = 0;
  double azimuth_deg = 0.0, elevation_deg = 0.0;
  int worn = 1;
  std::uint32_t fixation_id = 0, blink_id = 0;  // 0 = empty cell
};

inline std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

inline std::string id_cell(std::uint32_t id) {
  return id == 0 ? "" : std::to_string(id);
}

inline std::string pupil_cloud_gaze_csv(const std::vector<PupilCloudRow>& rows) {
  std::string s = kPupilCloudGazeHeader;
  for (const auto& r : rows) {
    // Scene pixels as an Invisible's 1088 x 1080 camera would roughly give (not read).
    const double px = 544.0 + 15.0 * r.azimuth_deg, py = 540.0 - 15.0 * r.elevation_deg;
    s += std::string(kSection) + "," + kRecording + "," + std::to_string(r.t_unix_ns) + "," + shortest(px) + "," +
         shortest(py) + "," + std::to_string(r.worn) + "," + id_cell(r.fixation_id) + "," + id_cell(r.blink_id) + "," +
         shortest(r.azimuth_deg) + "," + shortest(r.elevation_deg) + "\n";
  }
  return s;
}

// One line per blink: start = its first sample, end = the first sample after it (as in real
// exports).
inline std::string pupil_cloud_blinks_csv(const std::vector<PupilCloudRow>& rows) {
  std::string s = kPupilCloudBlinksHeader;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].blink_id == 0 || (i > 0 && rows[i - 1].blink_id == rows[i].blink_id)) continue;
    std::size_t j = i;
    while (j < rows.size() && rows[j].blink_id == rows[i].blink_id) ++j;
    const std::int64_t end = j < rows.size() ? rows[j].t_unix_ns : rows[j - 1].t_unix_ns + 1;
    s += std::string(kSection) + "," + kRecording + "," + std::to_string(rows[i].blink_id) + "," +
         std::to_string(rows[i].t_unix_ns) + "," + std::to_string(end) + "," +
         std::to_string((end - rows[i].t_unix_ns) / 1'000'000) + "\n";
  }
  return s;
}

// 200 Hz (Pupil Invisible's rate): fixation (Pupil id 1), 10 deg saccade, fixation (2), blink
// (Pupil blink id 1; the eye keeps still, so only the blink marks can tell), fixation (3).
// Pupil's fixation ids cover the fixation samples, never the saccade.
inline std::vector<PupilCloudRow> three_fixations_and_a_blink() {
  Synth s;
  s.rate_hz = 200.0;
  std::vector<std::uint32_t> fix, blink;
  auto mark = [&](std::uint32_t f, std::uint32_t b) {
    while (fix.size() < s.out.size()) {
      fix.push_back(f);
      blink.push_back(b);
    }
  };
  s.fixate(0.4);
  mark(1, 0);
  s.saccade(10.0, 0.0);
  mark(0, 0);
  s.fixate(0.4);
  mark(2, 0);
  s.fixate(0.15);  // the blink: Pupil Invisible keeps estimating gaze through it
  mark(0, 1);
  s.fixate(0.4);
  mark(3, 0);
  std::vector<PupilCloudRow> rows;
  for (std::size_t i = 0; i < s.out.size(); ++i) {
    const glm::dvec3 d = s.out[i].direction;
    PupilCloudRow r;
    r.t_unix_ns = kUnixStartNs + (s.out[i].t_ns - s.out[0].t_ns);
    r.azimuth_deg = std::atan2(d.x, -d.z) * aux::kDegPerRad;
    r.elevation_deg = std::atan2(d.y, std::hypot(d.x, d.z)) * aux::kDegPerRad;
    r.fixation_id = fix[i];
    r.blink_id = blink[i];
    rows.push_back(r);
  }
  return rows;
}

}  // namespace gazelod::gaze::testing
