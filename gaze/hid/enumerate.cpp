// SPDX-License-Identifier: Apache-2.0
#include "gaze/hid/enumerate.hpp"

#include "gaze/hid/reports.hpp"

#include <hidapi.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace gazelod::gaze::hid {

std::string to_utf8(const wchar_t* s) {
  std::string out;
  if (!s) return out;
  for (; *s; ++s) {
    const auto c = static_cast<std::uint32_t>(*s);
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x110000) {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += '?';
    }
  }
  return out;
}

std::vector<TrackerInfo> list_trackers() {
  std::vector<TrackerInfo> out;
  hid_device_info* all = hid_enumerate(0, 0);
  for (const hid_device_info* d = all; d; d = d->next) {
    if (d->usage_page != kUsagePageEyeHeadTrackers || !d->path) continue;
    TrackerInfo t;
    t.path = d->path;
    t.vendor_id = d->vendor_id;
    t.product_id = d->product_id;
    t.usage_page = d->usage_page;
    t.usage = d->usage;
    t.interface_number = d->interface_number;
    t.manufacturer = to_utf8(d->manufacturer_string);
    t.product = to_utf8(d->product_string);
    t.serial = to_utf8(d->serial_number);
    out.push_back(std::move(t));
  }
  hid_free_enumeration(all);
  return out;
}

std::string check_hidraw_path(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return path + ": " + std::strerror(errno);
  if (!S_ISCHR(st.st_mode)) return path + ": not a character device (an eye tracker is a /dev/hidrawN)";
  const std::string sys =
      "/sys/dev/char/" + std::to_string(major(st.st_rdev)) + ":" + std::to_string(minor(st.st_rdev));
  std::error_code ec;
  const std::filesystem::path subsystem = std::filesystem::read_symlink(sys + "/subsystem", ec);
  if (ec || subsystem.filename() != "hidraw")
    return path + ": character device " + std::to_string(major(st.st_rdev)) + ":" + std::to_string(minor(st.st_rdev)) +
           " is not a hidraw device (an eye tracker is a /dev/hidrawN; `gazelod hid list` shows them)";
  return "";
}

}  // namespace gazelod::gaze::hid
