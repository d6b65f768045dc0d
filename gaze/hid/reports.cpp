// SPDX-License-Identifier: Apache-2.0
#include "gaze/hid/reports.hpp"

#include <sstream>

namespace gazelod::gaze::hid {
namespace {

// Little-endian field reader that remembers where it is, so errors can name the byte.
class Reader {
 public:
  Reader(std::span<const std::uint8_t> bytes, const char* report) : b_(bytes), report_(report) {}

  std::size_t offset() const { return at_; }
  bool has(std::size_t n) const { return at_ + n <= b_.size(); }
  void skip(std::size_t n) { at_ += n; }

  std::uint64_t unsigned_le(std::size_t n) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i) v |= std::uint64_t{b_[at_ + i]} << (8 * i);
    at_ += n;
    return v;
  }
  std::uint8_t u8() { return static_cast<std::uint8_t>(unsigned_le(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsigned_le(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_le(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }  // two's complement
  std::uint64_t u64() { return unsigned_le(8); }
  Point3Um point3() {
    Point3Um p;
    p.x = i32();
    p.y = i32();
    p.z = i32();
    return p;
  }

  DecodeError error(std::size_t at, std::string message) const { return DecodeError{report_, at, std::move(message)}; }
  // Common checks: a report ID byte that matches, and `need` bytes in total.
  std::optional<DecodeError> check_header(std::uint8_t id, std::size_t need) {
    if (b_.empty()) return error(0, "empty report");
    if (b_[0] != id) {
      std::ostringstream m;
      m << "report ID 0x" << std::hex << int{b_[0]} << ", expected 0x" << int{id};
      return error(0, m.str());
    }
    if (b_.size() < need) {
      std::ostringstream m;
      m << "report is " << b_.size() << " bytes, need at least " << need;
      return error(b_.size(), m.str());
    }
    at_ = 1;
    return std::nullopt;
  }

 private:
  std::span<const std::uint8_t> b_;
  const char* report_;
  std::size_t at_ = 0;
};

template <class T>
Decoded<T> fail(DecodeError e) {
  Decoded<T> d;
  d.error = std::move(e);
  return d;
}
template <class T>
Decoded<T> ok(T v) {
  Decoded<T> d;
  d.value = std::move(v);
  return d;
}

}  // namespace

std::string DecodeError::to_string() const {
  std::ostringstream s;
  s << report << " report, byte " << byte_offset << ": " << message;
  return s.str();
}

const char* to_string(ConfigurationStatus s) {
  switch (s) {
    case ConfigurationStatus::kReserved:
      return "reserved";
    case ConfigurationStatus::kReady:
      return "ready";
    case ConfigurationStatus::kConfiguring:
      return "configuring";
    case ConfigurationStatus::kScreenSetupNeeded:
      return "screen setup needed";
    case ConfigurationStatus::kUserCalibrationNeeded:
      return "user calibration needed";
  }
  return "unknown";
}

Decoded<Capabilities> decode_capabilities(std::span<const std::uint8_t> report) {
  Reader r(report, "capabilities");
  if (auto e = r.check_header(kReportCapabilities, kCapabilitiesSize)) return fail<Capabilities>(*e);
  Capabilities c;
  c.tracker_quality = r.u8();
  c.min_tracking_distance_um = r.u32();
  c.optimum_tracking_distance_um = r.u32();
  c.max_tracking_distance_um = r.u32();
  c.max_screen_plane_width_um = r.u32();
  c.max_screen_plane_height_um = r.u32();
  // Tracking distances must be ordered; a device that says otherwise is not trusted.
  if (c.min_tracking_distance_um > c.optimum_tracking_distance_um ||
      c.optimum_tracking_distance_um > c.max_tracking_distance_um)
    return fail<Capabilities>(r.error(2, "tracking distances not ordered min <= optimum <= max"));
  return ok(c);
}

Decoded<Configuration> decode_configuration(std::span<const std::uint8_t> report, const ReportLayout& layout) {
  Reader r(report, "configuration");
  if (auto e = r.check_header(kReportConfiguration, kConfigurationSize + layout.configuration_pad))
    return fail<Configuration>(*e);
  r.skip(layout.configuration_pad);
  Configuration c;
  c.display_manufacturer_id = r.u16();
  c.display_product_id = r.u16();
  c.display_serial_number = r.u32();
  c.display_manufacturer_date = r.u16();
  const std::size_t width_at = r.offset();
  c.calibrated_screen_width_um = r.i32();
  c.calibrated_screen_height_um = r.i32();
  if (c.calibrated_screen_width_um < 0)
    return fail<Configuration>(r.error(width_at, "negative calibrated screen width"));
  if (c.calibrated_screen_height_um < 0)
    return fail<Configuration>(r.error(width_at + 4, "negative calibrated screen height"));
  return ok(c);
}

Decoded<Status> decode_status(std::span<const std::uint8_t> report, const ReportLayout& layout) {
  Reader r(report, "status");
  if (auto e = r.check_header(kReportStatus, kStatusSize + layout.status_pad)) return fail<Status>(*e);
  r.skip(layout.status_pad);
  const std::size_t status_at = r.offset();
  const std::uint8_t raw = r.u8();
  if (raw > static_cast<std::uint8_t>(ConfigurationStatus::kUserCalibrationNeeded))
    return fail<Status>(r.error(status_at, "configuration status " + std::to_string(raw) + " outside 0..4"));
  Status s;
  s.configuration_status = static_cast<ConfigurationStatus>(raw);
  s.sampling_frequency_hz = r.u16();
  return ok(s);
}

std::array<std::uint8_t, kControlSize> encode_control(std::uint8_t mode_request) {
  return {kReportControl, mode_request};
}

Decoded<std::uint8_t> decode_control(std::span<const std::uint8_t> report) {
  Reader r(report, "control");
  if (auto e = r.check_header(kReportControl, kControlSize)) return fail<std::uint8_t>(*e);
  const std::uint8_t mode = r.u8();
  if (mode & ~(kModeGazePoint | kModeEyePosition | kModeHeadPosition))
    return fail<std::uint8_t>(r.error(1, "mode request has unknown bits"));
  return ok(mode);
}

Decoded<TrackingData> decode_tracking(std::span<const std::uint8_t> report, const ReportLayout& layout) {
  Reader r(report, "tracking data");
  const std::size_t pad = layout.tracking_pad;
  if (auto e = r.check_header(kReportTrackingData, kTrackingSizeNoHead + pad)) return fail<TrackingData>(*e);
  // Exactly the short form, or at least the long form: anything between is a cut-off head block.
  const std::size_t n = report.size();
  if (n > kTrackingSizeNoHead + pad && n < kTrackingSizeWithHead + pad)
    return fail<TrackingData>(r.error(n, "report is " + std::to_string(n) + " bytes: head fields cut off (expected " +
                                             std::to_string(kTrackingSizeNoHead + pad) + " or " +
                                             std::to_string(kTrackingSizeWithHead + pad) + ")"));
  r.skip(pad);
  TrackingData t;
  t.timestamp_us = r.u64();
  t.gaze_x_um = r.i32();
  t.gaze_y_um = r.i32();
  t.left_eye_um = r.point3();
  t.right_eye_um = r.point3();
  if (r.has(24)) {
    t.has_head = true;
    t.head_position_um = r.point3();
    t.head_direction_raw = r.point3();
  }
  return ok(t);
}

}  // namespace gazelod::gaze::hid
