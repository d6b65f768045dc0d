// SPDX-License-Identifier: Apache-2.0
// The layer's gaze feed: one gaze::GazeSource (a trace replayed on the session's clock, or the
// HID eye tracker on the runtime's clock) with what the OpenXR side asks of it: a sample for a
// requested XrTime, and whether gaze is fresh now (an action is active only then). Not
// thread-safe by itself: the layer calls it under its state mutex (the HID source has its own
// reader thread behind a queue).
#pragma once

#include "layer/layer_config.hpp"

#include "gaze/gaze_source.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace gazelod::layer {

class GazeFeed {
 public:
  virtual ~GazeFeed() = default;
  // "trace FILE (N samples, S s)" or "HID eye tracker ...", for logs and `gazelod layer check`.
  virtual std::string describe() const = 0;
  // Every xrWaitFrame's predicted display time; `first_of_session` for a session's first.
  virtual void on_frame(std::int64_t predicted_display_time_ns, bool first_of_session) = 0;
  // The gaze for XrTime t (runtime clock), nullopt when none is fresh at t.
  virtual std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) = 0;
  // Whether gaze is fresh now (checked at each xrSyncActions).
  virtual bool fresh() = 0;
  virtual std::string status() const = 0;
};

// A trace replayed as gazelod replays traces (gaze/replay_source.hpp: interpolated between
// samples, the last valid one held for the freshness time), its first sample mapped to the
// predicted display time of each session's first xrWaitFrame (as `gazelod run --trace` maps it
// to the run's first frame). `now` is the newest predicted display time.
class TraceFeed final : public GazeFeed {
 public:
  TraceFeed(std::string path, std::vector<gaze::TraceRecord> records, std::int64_t freshness_ns);
  std::string describe() const override;
  void on_frame(std::int64_t predicted_display_time_ns, bool first_of_session) override;
  std::optional<gaze::GazeSample> sample_at(std::int64_t t_ns) override;
  bool fresh() override;
  std::string status() const override;

 private:
  std::string path_;
  std::int64_t first_sample_ns_ = 0, span_ns_ = 0;
  std::size_t samples_ = 0;
  std::unique_ptr<gaze::GazeSource> replay_;
  bool mapped_ = false;
  std::int64_t offset_ns_ = 0;  // session XrTime = trace time + offset
  std::int64_t now_ns_ = 0;
};

// Reads the whole trace (gaze/trace_open.hpp, any format it knows). Throws gaze::TraceError
// (file:line:column) or std::runtime_error ("has no samples").
std::unique_ptr<TraceFeed> open_trace_feed(const LayerConfig& config);

struct HidFeedOptions {
  std::function<std::int64_t()> now_ns;         // the runtime's clock now (XrTime)
  std::function<void(const std::string&)> log;  // one line, no prefix
};

// The first HID eye tracker (or config.hid_path), hot-plugged: its reader thread starts here and
// keeps looking for / reopening the device. `note` gets one line when no tracker is present now.
std::unique_ptr<GazeFeed> open_hid_feed(const LayerConfig& config, HidFeedOptions options, std::string& note);

// The trackers hidapi lists now ("" = none), for the note and `gazelod layer check`.
std::string describe_hid_trackers(const LayerConfig& config);

}  // namespace gazelod::layer
