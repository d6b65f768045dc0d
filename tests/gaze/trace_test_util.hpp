// SPDX-License-Identifier: Apache-2.0
// Test helpers: deterministic synthetic traces, and reading a CSV text whole with any reader.
#pragma once

#include "gaze/gaze_sample.hpp"
#include "gaze/record_stream.hpp"
#include "gaze/trace_error.hpp"

#include <glm/geometric.hpp>

#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace gazelod::gaze::testing {

// Every record of `text` read by a Reader (a CsvRecordStream) named "in.csv"; throws TraceError.
template <typename Reader>
std::vector<TraceRecord> read_all(const std::string& text, ReadOptions o = {}) {
  std::istringstream in(text);
  Reader r(in, "in.csv", o);
  std::vector<TraceRecord> out;
  TraceRecord rec;
  while (r.next(rec)) out.push_back(rec);
  return out;
}

// The TraceError message reading `text` gives, or "" when it reads fine.
template <typename Reader>
std::string error_of(const std::string& text) {
  try {
    read_all<Reader>(text);
  } catch (const TraceError& e) {
    return e.what();
  }
  return "";
}

// `seconds` at `rate_hz` of random unit gaze vectors and head poses (full-precision doubles),
// with a few invalid samples and a few rows without head pose.
inline std::vector<TraceRecord> random_trace(double seconds, double rate_hz, unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto n = static_cast<std::size_t>(seconds * rate_hz);
  const auto dt_ns = static_cast<std::int64_t>(1e9 / rate_hz);
  std::vector<TraceRecord> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    TraceRecord& r = out[i];
    r.gaze.t_ns = 1'234'567'890'123LL + static_cast<std::int64_t>(i) * dt_ns;
    r.gaze.direction = glm::normalize(glm::dvec3(u(rng) * 0.5, u(rng) * 0.5, -1.0));
    r.gaze.origin_m = {u(rng) * 0.01, u(rng) * 0.01, u(rng) * 0.01};
    r.gaze.valid = i % 97 != 5;
    r.gaze.confidence = static_cast<float>(0.5 + 0.5 * std::abs(u(rng)));
    r.has_head = i % 113 != 3;
    if (r.has_head) {
      r.head.t_ns = r.gaze.t_ns;
      r.head.orientation = glm::normalize(glm::dquat(u(rng), u(rng), u(rng), u(rng)));
      r.head.position_m = {u(rng), 1.6 + u(rng) * 0.1, u(rng)};
      r.head.valid = i % 211 != 9;
    }
  }
  return out;
}

}  // namespace gazelod::gaze::testing
