// SPDX-License-Identifier: Apache-2.0
// A fake hidapi for the tests: fake_hidapi.cpp defines the hid_* functions gazelod calls, and
// this header is how a test plays the device: plug it in, give it feature reports, queue input
// reports (recorded bytes), unplug and replug it, and look at what the code sent to it.
// hid_read_timeout waits at most a few ms per call, so nothing here sleeps long.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fake_hid {

struct DeviceSpec {
  std::string path;
  std::uint16_t usage_page = 0x12;
  std::uint16_t usage = 0x01;
  std::uint16_t vendor_id = 0x2104, product_id = 0x0127;
  std::wstring product = L"Fake Eye Tracker";
};

void reset();                          // no devices, nothing queued, counters zero
void plug(const DeviceSpec& spec);     // adds (or re-adds after unplug) a device
void unplug(const std::string& path);  // open handles read -1 once their queue is empty
// Feature report served for hid_get_feature_report, for the request with report ID `for_id`
// (default: the report's own first byte; another ID plays a device that answers wrongly).
void set_feature(const std::string& path, std::vector<std::uint8_t> report, int for_id = -1);
// Makes hid_get_feature_report fail (-1) for this report ID.
void fail_feature(const std::string& path, std::uint8_t report_id);
void push_input(const std::string& path, std::vector<std::uint8_t> report);
std::size_t pending_input(const std::string& path);

std::vector<std::vector<std::uint8_t>> sent_features(const std::string& path);
int open_count(const std::string& path);
int open_handles();     // currently open (not yet closed) handles, all devices
int enumerate_calls();  // hid_enumerate calls since reset()

}  // namespace fake_hid
