// SPDX-License-Identifier: Apache-2.0
// Builders for HID report bytes in the tests: little-endian fields appended one by one, so a
// test states each field's value and the expected decode independently of the decoder.
#pragma once

#include "gaze/hid/reports.hpp"

#include <cstdint>
#include <vector>

namespace gazelod::gaze::hid::testing {

struct Bytes {
  std::vector<std::uint8_t> b;
  Bytes& u8(std::uint8_t v) {
    b.push_back(v);
    return *this;
  }
  Bytes& le(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    return *this;
  }
  Bytes& u16(std::uint16_t v) { return le(v, 2); }
  Bytes& u32(std::uint32_t v) { return le(v, 4); }
  Bytes& i32(std::int32_t v) { return le(static_cast<std::uint32_t>(v), 4); }
  Bytes& u64(std::uint64_t v) { return le(v, 8); }
  Bytes& pad(std::size_t n) {
    b.insert(b.end(), n, 0xEE);
    return *this;
  }
};

// A Tracking Data report (packed layout) with the given values in micrometres.
inline std::vector<std::uint8_t> tracking_report(std::uint64_t t_us, std::int32_t gx, std::int32_t gy, Point3Um left,
                                                 Point3Um right, bool head = false, Point3Um head_pos = {},
                                                 Point3Um head_dir = {}) {
  Bytes r;
  r.u8(kReportTrackingData).u64(t_us).i32(gx).i32(gy);
  r.i32(left.x).i32(left.y).i32(left.z).i32(right.x).i32(right.y).i32(right.z);
  if (head) {
    r.i32(head_pos.x).i32(head_pos.y).i32(head_pos.z);
    r.i32(head_dir.x).i32(head_dir.y).i32(head_dir.z);
  }
  return r.b;
}

}  // namespace gazelod::gaze::hid::testing
