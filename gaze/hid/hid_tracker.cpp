// SPDX-License-Identifier: Apache-2.0
#include "gaze/hid/hid_tracker.hpp"

#include "gaze/hid/enumerate.hpp"

#include <hidapi.h>

#include <array>
#include <chrono>
#include <iostream>
#include <span>

namespace gazelod::gaze::hid {
namespace {

std::int64_t steady_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Logs the first few of a kind of bad report, then every 1000th, so a babbling device cannot
// flood the log but every kind of problem is seen.
bool worth_logging(std::uint64_t count) {
  return count <= 10 || count % 1000 == 0;
}

std::string hex_id(std::uint8_t id) {
  static const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[id >> 4] + digits[id & 15];
}

}  // namespace

HidTracker::HidTracker(HidTrackerConfig config)
    : config_(std::move(config)), queue_(config_.queue_capacity), clock_(config_.clock) {
  if (!config_.host_now_ns) config_.host_now_ns = steady_now_ns;
  if (!config_.log) config_.log = [](const std::string& line) { std::cerr << line << "\n"; };
  if (config_.read_timeout_ms < 1) config_.read_timeout_ms = 1;
  if (config_.reopen_interval_ms < 1) config_.reopen_interval_ms = 1;
}

HidTracker::~HidTracker() {
  stop();
}

void HidTracker::start() {
  if (thread_.joinable()) return;
  stop_ = false;
  set_status("searching for a usage page 0x12 device");
  thread_ = std::thread([this] { run(); });
}

void HidTracker::stop() {
  {
    std::lock_guard lock(wake_mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void HidTracker::log(const std::string& line) {
  config_.log("gazelod hid: " + line);
}

void HidTracker::set_status(std::string s) {
  std::lock_guard lock(state_mutex_);
  status_ = std::move(s);
}

std::string HidTracker::status() const {
  std::lock_guard lock(state_mutex_);
  return status_;
}

HidCounters HidTracker::counters() const {
  std::lock_guard lock(state_mutex_);
  HidCounters c = counters_;
  c.dropped = queue_.dropped();
  return c;
}

DeviceState HidTracker::device_state() const {
  std::lock_guard lock(state_mutex_);
  return state_;
}

bool HidTracker::wait_for_stop(int ms) {
  std::unique_lock lock(wake_mutex_);
  return wake_.wait_for(lock, std::chrono::milliseconds(ms), [this] { return stop_.load(); });
}

void HidTracker::run() {
  hid_init();
  std::array<std::uint8_t, 256> buf{};
  while (!stop_) {
    if (!dev_ && !try_open()) {
      wait_for_stop(config_.reopen_interval_ms);
      continue;
    }
    const int n = hid_read_timeout(dev_, buf.data(), buf.size(), config_.read_timeout_ms);
    const std::int64_t now = config_.host_now_ns();
    if (n < 0) {
      close_device(true);
      continue;
    }
    if (n > 0) handle_report(buf.data(), static_cast<std::size_t>(n), now);
    check_silence(now);  // Status, malformed or unknown reports carry no gaze either
  }
  if (dev_) close_device(false);
}

bool HidTracker::try_open() {
  std::string path = config_.path;
  if (path.empty()) {
    // The first eye tracker: a head tracker (usage 2) on the same page gives no gaze.
    for (const TrackerInfo& t : list_trackers())
      if (t.usage == kUsageEyeTracker) {
        path = t.path;
        break;
      }
  }
  // Only a hidraw device reaches hidapi: it crashes reading the udev parent of anything else.
  // (A path hidapi enumerated is one; a configured path is the user's word.)
  const std::string not_hidraw = config_.path.empty() ? std::string() : check_hidraw_path(path);
  hid_device* dev = path.empty() || !not_hidraw.empty() ? nullptr : hid_open_path(path.c_str());
  if (!dev) {
    if (!not_hidraw.empty() && !said_no_device_) {
      set_status(not_hidraw);  // before the log line: whoever reads the line sees this status
      log(not_hidraw);
      said_no_device_ = true;
      return false;
    }
    if (!said_no_device_) {  // once per absence, not once per retry (an unplug said it already)
      // The status first: a reader woken by the log line must see the state it announces
      // (HidTrackerTest.NoDeviceAtStartIsLoggedOnceThenFound read it in between under ASan).
      set_status(path.empty() ? "no device" : "cannot open " + path);
      log(path.empty() ? "no eye tracker (HID usage page 0x12) found; will keep looking"
                       : "cannot open " + path + "; will keep trying");
      said_no_device_ = true;
    }
    return false;
  }
  dev_ = dev;
  said_no_device_ = false;
  clock_.reset();  // a reconnected device may have restarted its clock
  {
    std::lock_guard lock(state_mutex_);
    ++counters_.opens;
    state_ = DeviceState{};
    state_.path = path;
  }
  read_features();
  const auto control = encode_control(config_.mode_request);
  if (hid_send_feature_report(dev_, control.data(), control.size()) < 0)
    log("could not send the Control report (mode request): " + to_utf8(hid_error(dev_)));
  const DeviceState st = device_state();
  last_tracking_ns_ = config_.host_now_ns();
  said_silent_ = false;
  set_status(open_status());
  std::string why;
  if (!st.screen)
    why = "; no screen size known, samples are invalid";
  else if (st.status && st.status->configuration_status != ConfigurationStatus::kReady)
    why = std::string("; tracker not ready (") + to_string(st.status->configuration_status) +
          "), samples are invalid until it is";
  log("opened " + path + why);
  // Published last: whoever sees connected() then sees this connection's status and log line.
  connected_ = true;
  return true;
}

std::string HidTracker::open_status() const {
  const DeviceState st = device_state();
  if (!st.screen) return "connected, but no screen size (configure one)";
  if (st.status && st.status->configuration_status != ConfigurationStatus::kReady)
    return std::string("connected, tracker not ready (") + to_string(st.status->configuration_status) + ")";
  return "ok";
}

void HidTracker::check_silence(std::int64_t now_ns) {
  if (said_silent_ || !dev_) return;
  const std::int64_t silent_ns = now_ns - last_tracking_ns_;
  if (silent_ns < std::int64_t{config_.silence_ms} * 1'000'000) return;
  said_silent_ = true;
  const std::string line = "connected, but no gaze reports for " + std::to_string(config_.silence_ms) + " ms";
  set_status(line);  // before the log line, as elsewhere
  log(line + " (device still open); gaze unavailable until they resume");
}

void HidTracker::read_features() {
  std::array<std::uint8_t, 64> buf{};
  auto get = [&](std::uint8_t id, const char* name) -> std::span<const std::uint8_t> {
    buf.fill(0);
    buf[0] = id;
    const int n = hid_get_feature_report(dev_, buf.data(), buf.size());
    if (n <= 0) {
      log(std::string("could not read the ") + name + " feature report: " + to_utf8(hid_error(dev_)));
      return {};
    }
    return {buf.data(), static_cast<std::size_t>(n)};
  };
  DeviceState st;
  st.path = device_state().path;
  if (auto r = get(kReportCapabilities, "Capabilities"); !r.empty()) {
    auto d = decode_capabilities(r);
    if (d)
      st.capabilities = *d.value;
    else
      log(d.error->to_string());
  }
  if (auto r = get(kReportConfiguration, "Configuration"); !r.empty()) {
    auto d = decode_configuration(r, config_.layout);
    if (d)
      st.configuration = *d.value;
    else
      log(d.error->to_string());
  }
  if (auto r = get(kReportStatus, "Status"); !r.empty()) {
    auto d = decode_status(r, config_.layout);
    if (d)
      st.status = *d.value;
    else
      log(d.error->to_string());
  }
  // Screen size: configured, else calibrated (Configuration), else maximum (Capabilities).
  ScreenGeometry g = config_.screen;
  if (!validate(g).empty() && st.configuration) {
    g.width_m = st.configuration->calibrated_screen_width_um * 1e-6;
    g.height_m = st.configuration->calibrated_screen_height_um * 1e-6;
  }
  if (!validate(g).empty() && st.capabilities) {
    g.width_m = st.capabilities->max_screen_plane_width_um * 1e-6;
    g.height_m = st.capabilities->max_screen_plane_height_um * 1e-6;
  }
  if (validate(g).empty()) st.screen = g;
  std::lock_guard lock(state_mutex_);
  state_ = st;
}

void HidTracker::close_device(bool unplugged) {
  const std::string err = unplugged ? to_utf8(hid_error(dev_)) : "";
  hid_close(dev_);
  dev_ = nullptr;
  if (unplugged) {
    std::string path;
    {
      std::lock_guard lock(state_mutex_);
      ++counters_.disconnects;
      path = state_.path;
    }
    said_no_device_ = true;   // the unplug line below is the one line for this absence
    set_status("unplugged");  // before its log line, as above
    log("lost " + path + " (hid_read returned -1" + (err.empty() ? "" : ": " + err) +
        "); gaze unavailable until it is back");
  }
  // Last: whoever sees connected() false also sees the counter, the status and the line above
  // (a test read the status between the two and found the old one).
  connected_ = false;
}

void HidTracker::bad_report(std::uint64_t& counter, const std::string& line) {
  std::uint64_t n;
  {
    std::lock_guard lock(state_mutex_);
    n = ++counter;
  }
  if (worth_logging(n)) log("skipped " + line + " (" + std::to_string(n) + " so far)");
}

void HidTracker::handle_report(const std::uint8_t* data, std::size_t size, std::int64_t host_ns) {
  const std::span<const std::uint8_t> r(data, size);
  {
    std::lock_guard lock(state_mutex_);
    ++counters_.reports;
  }
  switch (data[0]) {
    case kReportTrackingData: {
      const auto d = decode_tracking(r, config_.layout);
      if (!d) return bad_report(counters_.malformed, d.error->to_string());
      const std::size_t resets_before = clock_.clock_resets();
      const std::int64_t t_ns = clock_.map(d.value->timestamp_us, host_ns);
      last_tracking_ns_ = host_ns;
      if (said_silent_) {
        said_silent_ = false;
        set_status(open_status());
        log("gaze reports resumed");
      }
      const DeviceState st = device_state();
      GazeSample s = st.screen ? gaze_from_screen(*d.value, *st.screen) : GazeSample{};
      // A tracker that says it is not ready (calibrating, needs setup) is not trusted.
      if (st.status && st.status->configuration_status != ConfigurationStatus::kReady) s.valid = false;
      s.t_ns = t_ns;
      queue_.push(s);
      std::lock_guard lock(state_mutex_);
      ++counters_.samples;
      if (!s.valid) ++counters_.invalid_samples;
      counters_.clock_resets += clock_.clock_resets() - resets_before;
      return;
    }
    case kReportStatus: {  // some trackers also send Status as an input report
      const auto d = decode_status(r, config_.layout);
      if (!d) return bad_report(counters_.malformed, d.error->to_string());
      std::optional<Status> before;
      {
        std::lock_guard lock(state_mutex_);
        before = state_.status;
        state_.status = *d.value;
      }
      if (!before || before->configuration_status != d.value->configuration_status) {
        if (!said_silent_) set_status(open_status());  // before its log line
        log(std::string("tracker status: ") + to_string(d.value->configuration_status));
      }
      return;
    }
    default:
      return bad_report(counters_.unknown,
                        "input report with unknown ID " + hex_id(data[0]) + " (" + std::to_string(size) + " bytes)");
  }
}

}  // namespace gazelod::gaze::hid
