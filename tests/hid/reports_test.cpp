// SPDX-License-Identifier: Apache-2.0
// Decoding HUTRR74 reports: hand-written byte strings (values worked out by hand, in the
// comments) decode to those values; short, long, wrong-ID and out-of-range reports are errors
// that name the byte; arbitrary bytes never crash the decoders.
#include "gaze/hid/reports.hpp"
#include "tests/hid/report_bytes.hpp"

#include <gtest/gtest.h>

#include <random>

namespace gazelod::gaze::hid {
namespace {

using testing::Bytes;
using testing::tracking_report;

// Capabilities as MSREnable/GazeHid's driver fills them: quality 1, distances 50/65/90 mm, and
// a 527.04 x 296.46 mm (24", 16:9) screen plane. Little-endian by hand:
// 50000 = 0x0000C350, 65000 = 0x0000FDE8, 90000 = 0x00015F90, 527040 = 0x00080AC0,
// 296460 = 0x0004860C.
const std::vector<std::uint8_t> kCapabilities = {0x11, 0x01, 0x50, 0xc3, 0x00, 0x00, 0xe8, 0xfd, 0x00, 0x00, 0x90,
                                                 0x5f, 0x01, 0x00, 0xc0, 0x0a, 0x08, 0x00, 0x0c, 0x86, 0x04, 0x00};

TEST(HidReports, CapabilitiesDecodeToKnownValues) {
  ASSERT_EQ(kCapabilities.size(), kCapabilitiesSize);
  const auto d = decode_capabilities(kCapabilities);
  ASSERT_TRUE(d) << d.error->to_string();
  EXPECT_EQ(d.value->tracker_quality, 1);
  EXPECT_EQ(d.value->min_tracking_distance_um, 50000u);
  EXPECT_EQ(d.value->optimum_tracking_distance_um, 65000u);
  EXPECT_EQ(d.value->max_tracking_distance_um, 90000u);
  EXPECT_EQ(d.value->max_screen_plane_width_um, 527040u);
  EXPECT_EQ(d.value->max_screen_plane_height_um, 296460u);
}

TEST(HidReports, CapabilitiesWithUnorderedDistancesAreRejected) {
  auto r = kCapabilities;
  r[2] = 0xff;  // min = 0x0000C3FF = 50175 ... still < optimum; make it bigger than optimum:
  r[4] = 0x01;  // min = 0x0001C3FF = 115711 > 65000
  const auto d = decode_capabilities(r);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error->byte_offset, 2u);
  EXPECT_NE(d.error->to_string().find("capabilities report, byte 2"), std::string::npos);
}

TEST(HidReports, EveryTruncationOfEveryReportIsAnErrorAtItsEnd) {
  const std::vector<std::vector<std::uint8_t>> reports = {
      kCapabilities, Bytes{}.u8(kReportConfiguration).u16(1).u16(2).u32(3).u16(4).i32(5).i32(6).b,
      Bytes{}.u8(kReportStatus).u8(1).u16(90).b, Bytes{}.u8(kReportControl).u8(1).b,
      tracking_report(1, 2, 3, {4, 5, 6}, {7, 8, 9})};
  for (const auto& full : reports) {
    for (std::size_t n = 0; n < full.size(); ++n) {
      const std::span<const std::uint8_t> cut(full.data(), n);
      std::optional<DecodeError> e;
      switch (full[0]) {
        case kReportCapabilities:
          e = decode_capabilities(cut).error;
          break;
        case kReportConfiguration:
          e = decode_configuration(cut).error;
          break;
        case kReportStatus:
          e = decode_status(cut).error;
          break;
        case kReportControl:
          e = decode_control(cut).error;
          break;
        default:
          e = decode_tracking(cut).error;
          break;
      }
      ASSERT_TRUE(e.has_value()) << "report 0x" << std::hex << int{full[0]} << " cut to " << std::dec << n;
      EXPECT_EQ(e->byte_offset, n) << e->to_string();  // the first missing byte
    }
  }
}

TEST(HidReports, WrongReportIdIsAnErrorAtByteZero) {
  auto r = kCapabilities;
  r[0] = kReportStatus;
  const auto d = decode_capabilities(r);
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error->byte_offset, 0u);
  EXPECT_NE(d.error->message.find("0x13"), std::string::npos) << d.error->message;
  EXPECT_FALSE(decode_tracking(Bytes{}.u8(0x7f).pad(40).b));
}

TEST(HidReports, ConfigurationPackedAndDmfLayouts) {
  // Packed (vhidmini Tracker.h): ID, mfr 0x4c2d, product 0x0a7e, serial 12345678, date 0x1f20,
  // calibrated 527040 x 296460 um.
  const auto packed =
      Bytes{}.u8(kReportConfiguration).u16(0x4c2d).u16(0x0a7e).u32(12345678).u16(0x1f20).i32(527040).i32(296460).b;
  const auto a = decode_configuration(packed, kLayoutGazeHidPacked);
  ASSERT_TRUE(a) << a.error->to_string();
  EXPECT_EQ(a.value->display_manufacturer_id, 0x4c2d);
  EXPECT_EQ(a.value->display_product_id, 0x0a7e);
  EXPECT_EQ(a.value->display_serial_number, 12345678u);
  EXPECT_EQ(a.value->display_manufacturer_date, 0x1f20);
  EXPECT_EQ(a.value->calibrated_screen_width_um, 527040);
  EXPECT_EQ(a.value->calibrated_screen_height_um, 296460);
  // DMF VirtualEyeGaze: one reserved byte after the ID; the same values must come out.
  auto dmf = Bytes{}
                 .u8(kReportConfiguration)
                 .pad(1)
                 .u16(0x4c2d)
                 .u16(0x0a7e)
                 .u32(12345678)
                 .u16(0x1f20)
                 .i32(527040)
                 .i32(296460)
                 .b;
  const auto b = decode_configuration(dmf, kLayoutGazeHidDmf);
  ASSERT_TRUE(b) << b.error->to_string();
  EXPECT_EQ(b.value->calibrated_screen_width_um, 527040);
  EXPECT_EQ(b.value->display_serial_number, 12345678u);
  // Negative height: error at its byte (1 + 2 + 2 + 4 + 2 + 4 = 15 packed).
  const auto neg = Bytes{}.u8(kReportConfiguration).u16(0).u16(0).u32(0).u16(0).i32(1).i32(-5).b;
  const auto c = decode_configuration(neg);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error->byte_offset, 15u);
}

TEST(HidReports, StatusValuesAndRange) {
  const auto d = decode_status(Bytes{}.u8(kReportStatus).u8(1).u16(250).b);
  ASSERT_TRUE(d);
  EXPECT_EQ(d.value->configuration_status, ConfigurationStatus::kReady);
  EXPECT_EQ(d.value->sampling_frequency_hz, 250);
  const auto cal = decode_status(Bytes{}.u8(kReportStatus).u8(4).u16(90).b);
  ASSERT_TRUE(cal);
  EXPECT_EQ(cal.value->configuration_status, ConfigurationStatus::kUserCalibrationNeeded);
  EXPECT_STREQ(to_string(cal.value->configuration_status), "user calibration needed");
  // 5 is outside the enum: error at the status byte (1 packed, 2 with the DMF reserved byte).
  const auto bad = decode_status(Bytes{}.u8(kReportStatus).u8(5).u16(90).b);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error->byte_offset, 1u);
  const auto bad_dmf = decode_status(Bytes{}.u8(kReportStatus).pad(1).u8(9).u16(90).b, kLayoutGazeHidDmf);
  ASSERT_FALSE(bad_dmf);
  EXPECT_EQ(bad_dmf.error->byte_offset, 2u);
}

TEST(HidReports, ControlRoundTripAndUnknownBits) {
  for (std::uint8_t mode = 0; mode <= 7; ++mode) {
    const auto bytes = encode_control(mode);
    EXPECT_EQ(bytes[0], 0x14);
    const auto d = decode_control(bytes);
    ASSERT_TRUE(d);
    EXPECT_EQ(*d.value, mode);
  }
  const auto bad = decode_control(std::vector<std::uint8_t>{0x14, 0x08});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error->byte_offset, 1u);
}

// A recorded-style tracking report, hex by hand: timestamp 0x0102030405060708 us, gaze point
// (263520, 148230) um, left eye (-32000, 0, 600000), right eye (32000, 0, 600000).
const std::vector<std::uint8_t> kTracking = {
    0x10,                                                                    // report ID
    0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01,                          // timestamp
    0x60, 0x05, 0x04, 0x00, 0x06, 0x43, 0x02, 0x00,                          // gaze x, y
    0x00, 0x83, 0xff, 0xff, 0x00, 0x00, 0x00, 0x00, 0xc0, 0x27, 0x09, 0x00,  // left eye
    0x00, 0x7d, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xc0, 0x27, 0x09, 0x00,  // right eye
};

TEST(HidReports, TrackingDataDecodesToKnownValues) {
  ASSERT_EQ(kTracking.size(), kTrackingSizeNoHead);
  const auto d = decode_tracking(kTracking);
  ASSERT_TRUE(d) << d.error->to_string();
  EXPECT_EQ(d.value->timestamp_us, 0x0102030405060708ull);
  EXPECT_EQ(d.value->gaze_x_um, 263520);
  EXPECT_EQ(d.value->gaze_y_um, 148230);
  EXPECT_EQ(d.value->left_eye_um.x, -32000);
  EXPECT_EQ(d.value->left_eye_um.z, 600000);
  EXPECT_EQ(d.value->right_eye_um.x, 32000);
  EXPECT_FALSE(d.value->has_head);
}

TEST(HidReports, TrackingDataWithHeadAndWithDmfPadding) {
  const auto r = tracking_report(42, -1, -2, {1, 2, 3}, {4, 5, 6}, true, {7, 8, 9}, {-10, 11, -12});
  ASSERT_EQ(r.size(), kTrackingSizeWithHead);
  const auto d = decode_tracking(r);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d.value->has_head);
  EXPECT_EQ(d.value->gaze_x_um, -1);
  EXPECT_EQ(d.value->head_position_um.z, 9);
  EXPECT_EQ(d.value->head_direction_raw.x, -10);
  EXPECT_EQ(d.value->head_direction_raw.z, -12);
  // The same report with the DMF layout's 7 reserved bytes after the ID.
  std::vector<std::uint8_t> dmf = {r[0]};
  dmf.insert(dmf.end(), 7, 0);
  dmf.insert(dmf.end(), r.begin() + 1, r.end());
  const auto e = decode_tracking(dmf, kLayoutGazeHidDmf);
  ASSERT_TRUE(e) << e.error->to_string();
  EXPECT_EQ(e.value->timestamp_us, 42u);
  EXPECT_EQ(e.value->head_direction_raw.y, 11);
  // Lengths between the short (41) and long (65) forms are a cut-off head block: errors.
  for (std::size_t n = kTrackingSizeNoHead + 1; n < kTrackingSizeWithHead; ++n) {
    const auto cut = decode_tracking(std::span<const std::uint8_t>(r.data(), n));
    ASSERT_FALSE(cut) << n;
    EXPECT_EQ(cut.error->byte_offset, n);
  }
}

TEST(HidReports, ArbitraryBytesNeverCrashAndErrorsStayInRange) {
  std::mt19937 rng(7);
  std::vector<std::uint8_t> buf;
  for (int i = 0; i < 20000; ++i) {
    buf.resize(rng() % 80);
    for (auto& b : buf) b = static_cast<std::uint8_t>(rng());
    if (!buf.empty() && i % 2) buf[0] = static_cast<std::uint8_t>(0x10 + rng() % 5);
    for (const auto& e : {decode_tracking(buf).error, decode_status(buf).error, decode_configuration(buf).error,
                          decode_capabilities(buf).error, decode_control(buf).error}) {
      if (e) {
        EXPECT_LE(e->byte_offset, buf.size());
      }
    }
  }
}

}  // namespace
}  // namespace gazelod::gaze::hid
