// SPDX-License-Identifier: Apache-2.0
// Fuzzes the HID report decoders with every layout. Invariants: exactly one of value / error is
// set; an error's byte offset lies within the report (or just past its end for a short one).
#include "fuzz/fuzz_entry.hpp"

#include "gaze/hid/reports.hpp"

#include <span>

namespace gazelod::fuzz {
namespace {

template <class T>
void check_decoded(const gaze::hid::Decoded<T>& d, std::size_t size) {
  check(d.value.has_value() != d.error.has_value(), "Decoded: not exactly one of value/error");
  if (d.error) {
    check(d.error->byte_offset <= size, "DecodeError byte offset past the end of the report");
    check(!d.error->to_string().empty(), "DecodeError without a message");
  }
}

}  // namespace

int hid_reports(const std::uint8_t* data, std::size_t size) {
  namespace h = gaze::hid;
  const std::span<const std::uint8_t> report(data, size);
  for (const h::ReportLayout& layout : {h::kLayoutGazeHidPacked, h::kLayoutGazeHidDmf}) {
    const auto tracking = h::decode_tracking(report, layout);
    check_decoded(tracking, size);
    check_decoded(h::decode_configuration(report, layout), size);
    check_decoded(h::decode_status(report, layout), size);
  }
  check_decoded(h::decode_capabilities(report), size);
  const auto control = h::decode_control(report);
  check_decoded(control, size);
  if (control) {  // encode(decode(x)) reproduces x's mode byte
    const auto bytes = h::encode_control(*control.value);
    const auto again = h::decode_control(bytes);
    check(again && *again.value == *control.value, "control report does not round-trip");
  }
  return 0;
}

}  // namespace gazelod::fuzz

GAZELOD_FUZZ_TARGET(hid_reports)
