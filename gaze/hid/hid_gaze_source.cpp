// SPDX-License-Identifier: Apache-2.0
#include "gaze/hid/hid_gaze_source.hpp"

namespace gazelod::gaze::hid {
namespace {
constexpr std::size_t kHistory = 64;  // > one frame's worth of samples at 1 kHz and 15 Hz
}

HidGazeSource::HidGazeSource(HidTrackerConfig config, std::int64_t max_hold_ns)
    : tracker_(std::move(config)), max_hold_ns_(max_hold_ns < 0 ? 0 : max_hold_ns) {
  incoming_.reserve(256);
  tracker_.start();
}

std::optional<GazeSample> HidGazeSource::sample_at(std::int64_t t_ns) {
  incoming_.clear();
  tracker_.drain(incoming_);
  for (const GazeSample& s : incoming_) {
    if (!s.valid) continue;
    // Mapped times are monotonic except across a device clock reset; keep the history sorted.
    while (!history_.empty() && history_.back().t_ns > s.t_ns) history_.pop_back();
    history_.push_back(s);
    if (history_.size() > kHistory) history_.pop_front();
  }
  if (!tracker_.connected()) return std::nullopt;
  for (auto it = history_.rbegin(); it != history_.rend(); ++it) {
    if (it->t_ns > t_ns) continue;
    if (t_ns - it->t_ns > max_hold_ns_) return std::nullopt;
    return *it;
  }
  return std::nullopt;
}

std::string HidGazeSource::status() const {
  const std::string s = tracker_.status();
  return s == "ok" ? s : "hid: " + s;
}

}  // namespace gazelod::gaze::hid
