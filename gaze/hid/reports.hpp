// SPDX-License-Identifier: Apache-2.0
// Pure decoders for the HID "Eye and Head Trackers" usage page (0x12, HUTRR74) reports, as
// Windows eye trackers implement it. Plain bytes in, plain structs out; every error names the
// report and the byte offset where decoding failed. No hidapi here.
//
// Sources for the layouts (all little-endian, as HID reports are):
//  - HUTRR74 "Usage Page for Head and Eye Trackers" (usb.org), usage IDs: report IDs are the
//    collection usages 0x10 Tracking Data, 0x11 Capabilities, 0x12 Configuration, 0x13 Status,
//    0x14 Control.
//  - MSREnable/GazeHid inc/Tracker.h (Microsoft's reference driver, packed structs, pshpack1):
//    GAZE_REPORT, CAPABILITIES_REPORT, CONFIGURATION_REPORT, TRACKER_STATUS_REPORT,
//    TRACKER_CONTROL_REPORT; enum values TRACKER_STATUS_*, MODE_REQUEST_ENABLE_*.
//  - MSREnable/GazeHid's DMF VirtualEyeGaze module: the same fields, but its report descriptor
//    puts 7 constant bytes after the Tracking Data report ID and 1 after the Configuration and
//    Status report IDs; it also gives the units: timestamp unit SI linear exp -6 (microseconds),
//    positions and distances "Centimeter, exponent -4" (micrometres), sampling frequency in Hz.
// hidapi 0.13 cannot return the report descriptor on every backend, so the padding is a choice
// (ReportLayout) rather than parsed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace gazelod::gaze::hid {

inline constexpr std::uint16_t kUsagePageEyeHeadTrackers = 0x0012;
inline constexpr std::uint16_t kUsageEyeTracker = 0x0001;
inline constexpr std::uint16_t kUsageHeadTracker = 0x0002;

// Report IDs (= the HUTRR74 collection usage of each report).
inline constexpr std::uint8_t kReportTrackingData = 0x10;
inline constexpr std::uint8_t kReportCapabilities = 0x11;
inline constexpr std::uint8_t kReportConfiguration = 0x12;
inline constexpr std::uint8_t kReportStatus = 0x13;
inline constexpr std::uint8_t kReportControl = 0x14;

// Where the decoders expect constant padding bytes right after the report ID.
struct ReportLayout {
  std::size_t tracking_pad = 0;       // bytes between report ID and timestamp
  std::size_t configuration_pad = 0;  // bytes between report ID and display manufacturer ID
  std::size_t status_pad = 0;         // bytes between report ID and configuration status
};
// MSREnable/GazeHid vhidmini drivers (Tracker.h, packed): no padding.
inline constexpr ReportLayout kLayoutGazeHidPacked{0, 0, 0};
// MSREnable/GazeHid DMF VirtualEyeGaze (EyeGazeIoctl) descriptor: 7 / 1 / 1 padding bytes.
inline constexpr ReportLayout kLayoutGazeHidDmf{7, 1, 1};

// A decoding failure: what and where (byte offset in the report, report ID included).
struct DecodeError {
  std::string report;       // "tracking data", "capabilities", ...
  std::size_t byte_offset;  // first byte that could not be decoded
  std::string message;
  std::string to_string() const;  // "tracking data report, byte 9: ..."
};

template <class T>
struct Decoded {
  std::optional<T> value;
  std::optional<DecodeError> error;  // set exactly when value is not
  explicit operator bool() const { return value.has_value(); }
};

// Capabilities feature report (0x11). Distances and sizes in micrometres.
struct Capabilities {
  std::uint8_t tracker_quality = 0;  // 1 = fine gaze (TRACKER_QUALITY_FINE_GAZE)
  std::uint32_t min_tracking_distance_um = 0;
  std::uint32_t optimum_tracking_distance_um = 0;
  std::uint32_t max_tracking_distance_um = 0;
  std::uint32_t max_screen_plane_width_um = 0;
  std::uint32_t max_screen_plane_height_um = 0;
};
inline constexpr std::size_t kCapabilitiesSize = 22;
Decoded<Capabilities> decode_capabilities(std::span<const std::uint8_t> report);

// Configuration feature report (0x12): the display the tracker was calibrated on.
struct Configuration {
  std::uint16_t display_manufacturer_id = 0;
  std::uint16_t display_product_id = 0;
  std::uint32_t display_serial_number = 0;
  std::uint16_t display_manufacturer_date = 0;
  std::int32_t calibrated_screen_width_um = 0;
  std::int32_t calibrated_screen_height_um = 0;
};
inline constexpr std::size_t kConfigurationSize = 19;  // without padding
Decoded<Configuration> decode_configuration(std::span<const std::uint8_t> report, const ReportLayout& layout = {});

// Configuration status values (Tracker.h TRACKER_STATUS_*; HUTRR74 usage 0x301).
enum class ConfigurationStatus : std::uint8_t {
  kReserved = 0,
  kReady = 1,
  kConfiguring = 2,
  kScreenSetupNeeded = 3,
  kUserCalibrationNeeded = 4,
};
const char* to_string(ConfigurationStatus s);

// Status feature (or input) report (0x13).
struct Status {
  ConfigurationStatus configuration_status = ConfigurationStatus::kReserved;
  std::uint16_t sampling_frequency_hz = 0;
};
inline constexpr std::size_t kStatusSize = 4;  // without padding
Decoded<Status> decode_status(std::span<const std::uint8_t> report, const ReportLayout& layout = {});

// Control feature report (0x14): the mode request bits (Tracker.h MODE_REQUEST_ENABLE_*).
inline constexpr std::uint8_t kModeGazePoint = 1;
inline constexpr std::uint8_t kModeEyePosition = 2;
inline constexpr std::uint8_t kModeHeadPosition = 4;
inline constexpr std::size_t kControlSize = 2;
std::array<std::uint8_t, kControlSize> encode_control(std::uint8_t mode_request);
Decoded<std::uint8_t> decode_control(std::span<const std::uint8_t> report);

// Tracking Data input report (0x10). Positions in micrometres (int32).
//  gaze point: on the calibrated screen plane, origin at its upper-left corner, +x right,
//    +y down (the convention Windows' GazeInputSourcePreview exposes);
//  eye / head position: 3-D, see ScreenGeometry (screen_geometry.hpp) for the frame;
//  head direction: the three "rotation about X/Y/Z axis" values, passed through raw (their unit
//    is not fixed by the sources above, so gazelod does not interpret them).
struct Point3Um {
  std::int32_t x = 0, y = 0, z = 0;
};
struct TrackingData {
  std::uint64_t timestamp_us = 0;  // device clock, microseconds
  std::int32_t gaze_x_um = 0, gaze_y_um = 0;
  Point3Um left_eye_um, right_eye_um;
  bool has_head = false;  // the report carried the two head fields (65-byte form)
  Point3Um head_position_um;
  Point3Um head_direction_raw;
};
// Without head fields: ID + 8 + 2*4 + 2*3*4 = 41 bytes; with them 65 (plus layout padding).
inline constexpr std::size_t kTrackingSizeNoHead = 41;
inline constexpr std::size_t kTrackingSizeWithHead = 65;
Decoded<TrackingData> decode_tracking(std::span<const std::uint8_t> report, const ReportLayout& layout = {});

}  // namespace gazelod::gaze::hid
