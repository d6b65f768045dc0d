// SPDX-License-Identifier: Apache-2.0
// Finding eye trackers: HID devices whose top-level collection is on the "Eye and Head
// Trackers" usage page (0x12). hidapi reports usage_page/usage per collection on the hidraw,
// Windows and macOS backends (not libusb), which is the backend gazelod links.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::gaze::hid {

struct TrackerInfo {
  std::string path;  // what hid_open_path() takes
  std::uint16_t vendor_id = 0, product_id = 0;
  std::uint16_t usage_page = 0, usage = 0;  // 0x12, and 1 eye tracker / 2 head tracker
  int interface_number = -1;
  std::string manufacturer, product, serial;  // UTF-8
};

// Every device with usage page 0x12 (calls hid_enumerate(0, 0)). Empty when hidapi fails.
std::vector<TrackerInfo> list_trackers();

// "" when `path` is a hidraw character device (what hidapi's hidraw backend opens), else why
// not: hidapi reads the device's udev parent and crashed on /dev/null or /dev/zero.
[[nodiscard]] std::string check_hidraw_path(const std::string& path);

// hidapi's wide strings to UTF-8 (nullptr -> "").
std::string to_utf8(const wchar_t* s);

}  // namespace gazelod::gaze::hid
