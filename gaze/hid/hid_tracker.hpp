// SPDX-License-Identifier: Apache-2.0
// The HID eye tracker device thread: finds a usage-page-0x12 device, opens it, reads its
// Capabilities / Configuration / Status feature reports, requests gaze mode through the Control
// report, then reads Tracking Data input reports into a bounded queue, mapping device time to
// host time. Unplug (hid_read returns -1) makes it unavailable, logged once; it keeps trying to
// reopen and logs when the device is back. Malformed, short or unknown reports are counted and
// skipped with a log line (rate-limited), never turned into samples.
//
// All hid_* calls happen on this thread (hidapi handles are not thread-safe). The program
// links the real hidapi; the tests link tests/hid/fake_hidapi.cpp instead.
#pragma once

#include "gaze/gaze_sample.hpp"
#include "gaze/hid/clock_map.hpp"
#include "gaze/hid/reports.hpp"
#include "gaze/hid/sample_queue.hpp"
#include "gaze/hid/screen_geometry.hpp"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

struct hid_device_;  // hidapi's opaque handle (hidapi.h stays out of this header)

namespace gazelod::gaze::hid {

struct HidTrackerConfig {
  std::string path;  // a hidapi device path; empty: the first usage-page-0x12 device
  ReportLayout layout = kLayoutGazeHidPacked;
  ClockMapConfig clock;
  // Screen (or image plane) size: width/height 0 (the default) take it from the device's
  // Configuration report (calibrated size), else its Capabilities (max screen plane size).
  // The eye frame is always this one.
  ScreenGeometry screen;
  std::uint8_t mode_request = kModeGazePoint | kModeEyePosition | kModeHeadPosition;
  std::size_t queue_capacity = 256;  // ~1 s at 250 Hz
  int read_timeout_ms = 20;          // how often the thread checks for stop()
  int reopen_interval_ms = 250;
  // No Tracking Data report for this long while the device stays open: the status says so and
  // one line is logged (a tracker can stop streaming without being unplugged).
  int silence_ms = 1000;
  // Where log lines go ("gazelod hid: " is prepended). Default: stderr. Called on the thread.
  std::function<void(const std::string&)> log;
  // Host clock in ns (the frame loop's clock). Default: std::chrono::steady_clock.
  std::function<std::int64_t()> host_now_ns;
};

struct HidCounters {
  std::uint64_t reports = 0;          // every input report read
  std::uint64_t samples = 0;          // tracking reports turned into samples (valid or not)
  std::uint64_t invalid_samples = 0;  // of those, without a usable gaze
  std::uint64_t malformed = 0;        // short, long or bad values
  std::uint64_t unknown = 0;          // report IDs this page does not define for input
  std::uint64_t dropped = 0;          // samples pushed out of the full queue
  std::uint64_t disconnects = 0;
  std::uint64_t opens = 0;
  std::uint64_t clock_resets = 0;
};

// What the device said about itself at the last open.
struct DeviceState {
  std::optional<Capabilities> capabilities;
  std::optional<Configuration> configuration;
  std::optional<Status> status;
  std::optional<ScreenGeometry> screen;  // the geometry in use
  std::string path;
};

class HidTracker {
 public:
  explicit HidTracker(HidTrackerConfig config);
  ~HidTracker();  // stops and joins the thread, closes the device
  HidTracker(const HidTracker&) = delete;
  HidTracker& operator=(const HidTracker&) = delete;

  void start();
  void stop();

  bool connected() const { return connected_.load(); }
  // Moves the queued samples into `out`. Never blocks.
  bool drain(std::vector<GazeSample>& out) { return queue_.drain(out); }
  HidCounters counters() const;
  DeviceState device_state() const;
  // One line: "ok", "no device", "unplugged", "connected, tracker not ready (...)",
  // "connected, but no gaze reports for 1 s", ...
  std::string status() const;

 private:
  void run();
  bool try_open();
  void close_device(bool unplugged);
  void read_features();
  void handle_report(const std::uint8_t* data, std::size_t size, std::int64_t host_ns);
  void bad_report(std::uint64_t& counter, const std::string& line);
  void log(const std::string& line);
  void set_status(std::string s);
  std::string open_status() const;  // the status of an open device, from what it said
  void check_silence(std::int64_t now_ns);
  bool wait_for_stop(int ms);

  HidTrackerConfig config_;
  SampleQueue queue_;
  ClockMap clock_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> connected_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;

  ::hid_device_* dev_ = nullptr;  // only touched on the thread
  bool said_no_device_ = false;
  std::int64_t last_tracking_ns_ = 0;  // host time of the last Tracking Data report (or the open)
  bool said_silent_ = false;

  mutable std::mutex state_mutex_;  // guards state_, status_, counters_
  DeviceState state_;
  std::string status_ = "not started";
  HidCounters counters_;
};

}  // namespace gazelod::gaze::hid
