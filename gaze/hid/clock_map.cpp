// SPDX-License-Identifier: Apache-2.0
#include "gaze/hid/clock_map.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::gaze::hid {

ClockMap::ClockMap(ClockMapConfig config) : config_(config) {
  config_.counter_bits = std::clamp(config_.counter_bits, 8, 64);
  mask_ = config_.counter_bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << config_.counter_bits) - 1;
  if (config_.window_ns < 1) config_.window_ns = 1;
  if (config_.max_windows < 2) config_.max_windows = 2;
}

void ClockMap::reset() {
  started_ = false;
  windows_.clear();
  device_ns_ = 0;
  slope_ = 0.0;
}

void ClockMap::restart(std::uint64_t raw, std::int64_t host_receive_ns) {
  started_ = true;
  last_raw_ = raw;
  device_ns_ = 0;
  window_start_ns_ = 0;
  windows_.clear();
  windows_.push_back({0, static_cast<double>(host_receive_ns)});
  refit();
  last_mapped_ns_ = host_receive_ns;
}

std::int64_t ClockMap::map(std::uint64_t device_us, std::int64_t host_receive_ns) {
  const std::uint64_t raw = device_us & mask_;
  if (!started_) {
    restart(raw, host_receive_ns);
    return host_receive_ns;
  }
  // Modular difference, read as signed: forward steps are small, a wrap looks like a small step.
  const std::uint64_t delta = (raw - last_raw_) & mask_;
  const std::uint64_t half = mask_ >> 1;
  const bool backwards = delta > half;
  const std::uint64_t max_gap_us = static_cast<std::uint64_t>(config_.max_forward_gap_ns / 1000);
  if (backwards || delta > max_gap_us) {
    ++clock_resets_;  // restarted device, or a long silence: the old fit no longer applies
    restart(raw, host_receive_ns);
    return host_receive_ns;
  }
  last_raw_ = raw;
  device_ns_ += static_cast<std::int64_t>(delta) * 1000;

  const double offset = static_cast<double>(host_receive_ns - device_ns_);
  if (device_ns_ - window_start_ns_ >= config_.window_ns) {
    // The window just completed. A minimum well under what the fit predicts proves the earlier
    // minima inflated (offsets only overestimate: a reader thread running behind for a while);
    // kept, they would tilt the line and extrapolate under the true offset.
    const Window& done = windows_.back();
    if (windows_.size() >= 2 && done.offset_ns < offset_at(done.device_ns) - static_cast<double>(config_.stale_drop_ns))
      windows_.erase(windows_.begin(), windows_.end() - 1);
    window_start_ns_ = device_ns_;
    windows_.push_back({device_ns_, offset});
    while (windows_.size() > config_.max_windows) windows_.pop_front();
  } else if (offset < windows_.back().offset_ns) {
    windows_.back() = {device_ns_, offset};
  }
  refit();
  // The newest windows' minima bound the offset from above as well (a transfer only adds
  // latency). After the latency drops (a host busy at start-up), the fit over up to
  // max_windows earlier windows stays high for as long; they correct it at once.
  double offset_used = std::min(offset_at(device_ns_), windows_.back().offset_ns);
  if (windows_.size() >= 2) offset_used = std::min(offset_used, windows_[windows_.size() - 2].offset_ns);
  const auto mapped = static_cast<std::int64_t>(std::llround(static_cast<double>(device_ns_) + offset_used));
  // The sample cannot have been taken after it arrived, nor before the previous sample (device
  // times only increase; an offset lowered since then would otherwise place it earlier, and a
  // recorded trace would go backwards in time).
  last_mapped_ns_ = std::min(std::max(mapped, last_mapped_ns_), host_receive_ns);
  return last_mapped_ns_;
}

void ClockMap::refit() {
  // Completed windows only (the last one is still collecting its minimum), once there are two.
  const std::size_t done = windows_.size() - 1;
  if (done < 2) {
    auto best = std::min_element(windows_.begin(), windows_.end(),
                                 [](const Window& a, const Window& b) { return a.offset_ns < b.offset_ns; });
    fit_x_ns_ = static_cast<double>(best->device_ns);
    fit_y_ns_ = best->offset_ns;
    slope_ = 0.0;
    return;
  }
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < done; ++i) {
    mx += static_cast<double>(windows_[i].device_ns);
    my += windows_[i].offset_ns;
  }
  mx /= static_cast<double>(done);
  my /= static_cast<double>(done);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < done; ++i) {
    const double dx = static_cast<double>(windows_[i].device_ns) - mx;
    sxx += dx * dx;
    sxy += dx * (windows_[i].offset_ns - my);
  }
  const double max_slope = config_.max_drift_ppm * 1e-6;
  slope_ = sxx > 0.0 ? std::clamp(sxy / sxx, -max_slope, max_slope) : 0.0;
  fit_x_ns_ = mx;
  fit_y_ns_ = my;
}

double ClockMap::offset_at(std::int64_t device_ns) const {
  return fit_y_ns_ + slope_ * (static_cast<double>(device_ns) - fit_x_ns_);
}

std::int64_t ClockMap::offset_ns() const {
  return static_cast<std::int64_t>(std::llround(offset_at(device_ns_)));
}

}  // namespace gazelod::gaze::hid
