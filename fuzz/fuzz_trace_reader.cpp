// SPDX-License-Identifier: Apache-2.0
// Fuzzes the trace CSV readers (gazelod's own, GazeBase VR, Pupil Core, Pupil Cloud, SRanipal),
// strict and lenient. Invariants: time never goes backwards; a valid gaze is a finite unit vector.
#include "fuzz/fuzz_entry.hpp"

#include "gaze/import_gazebasevr.hpp"
#include "gaze/import_pupil.hpp"
#include "gaze/import_pupil_cloud.hpp"
#include "gaze/import_sranipal.hpp"
#include "gaze/trace_error.hpp"
#include "gaze/trace_reader.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

namespace gazelod::fuzz {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template <class Reader>
void read_all(const std::string& text, bool lenient) {
  std::istringstream in(text);
  try {
    Reader reader(in, "fuzz.csv", gaze::ReadOptions{lenient});
    gaze::TraceRecord rec;
    bool have_last = false;
    std::int64_t last_t_ns = 0;
    // Bounded: every record consumes at least one line of the input.
    for (std::size_t n = 0; n <= text.size() && reader.next(rec); ++n) {
      check(!have_last || rec.gaze.t_ns >= last_t_ns, "trace time went backwards");
      have_last = true;
      last_t_ns = rec.gaze.t_ns;
      if (rec.gaze.valid) {
        check(finite(rec.gaze.direction), "valid gaze with a non-finite direction");
        const double len = glm::length(rec.gaze.direction);
        check(std::abs(len - 1.0) < 1e-2, "valid gaze direction is not a unit vector");
        check(finite(rec.gaze.origin_m), "valid gaze with a non-finite origin");
        check(rec.gaze.confidence >= 0.0f && rec.gaze.confidence <= 1.0f, "confidence outside [0, 1]");
      }
      if (rec.has_head && rec.head.valid) {
        check(finite(rec.head.position_m), "valid head with a non-finite position");
        const glm::dquat& q = rec.head.orientation;
        check(std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z),
              "valid head with a non-finite orientation");
      }
    }
  } catch (const gaze::TraceError&) {
    // The documented rejection (names file:line:column).
  }
}

}  // namespace

int trace_reader(const std::uint8_t* data, std::size_t size) {
  const std::string text(as_text(data, size));
  for (bool lenient : {false, true}) {
    read_all<gaze::TraceReader>(text, lenient);
    read_all<gaze::GazeBaseVrReader>(text, lenient);
    read_all<gaze::PupilReader>(text, lenient);
    read_all<gaze::PupilCloudReader>(text, lenient);
    read_all<gaze::SranipalReader>(text, lenient);
  }
  return 0;
}

}  // namespace gazelod::fuzz

GAZELOD_FUZZ_TARGET(trace_reader)
