// Test helpers: deterministic synthetic traces.
#pragma once

#include "gaze/gaze_sample.hpp"

#include <glm/geometric.hpp>

#include <cstdint>
#include <random>
#include <vector>

namespace gazelod::gaze::testing {

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
