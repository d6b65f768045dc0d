// SPDX-License-Identifier: Apache-2.0
// The one small interface every gaze source implements (trace replay, HID tracker,
// simulator, OpenXR eye-gaze action). Sources never block the caller's frame loop.
#pragma once

#include "gaze/gaze_sample.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace gazelod::gaze {

class GazeSource {
 public:
  virtual ~GazeSource() = default;

  // Short name for logs and reports: "trace", "hid", "sim", "openxr".
  virtual std::string name() const = 0;

  // The sample for time t_ns (the source may interpolate, hold or predict), or nullopt when
  // gaze is unavailable at t_ns. Must return quickly: never waits on a device or a file.
  virtual std::optional<GazeSample> sample_at(std::int64_t t_ns) = 0;

  // One line saying why the source is unavailable (or "ok"), for the fallback report.
  virtual std::string status() const { return "ok"; }
};

}  // namespace gazelod::gaze
