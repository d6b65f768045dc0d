// SPDX-License-Identifier: Apache-2.0
// The fake hidapi: the hid_* symbols gazelod_hid_core calls, served from fake_hid's state.
#include "tests/hid/fake_hidapi.hpp"

#include <hidapi.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>

// hidapi's opaque handle: which device, and which plug-in of it it was opened on.
struct hid_device_ {
  std::string path;
  int generation;
};

namespace fake_hid {
namespace {

struct Device {
  DeviceSpec spec;
  bool plugged = false;
  int generation = 0;  // bumped at each plug, so handles from before an unplug stay dead
  std::map<std::uint8_t, std::vector<std::uint8_t>> features;
  std::map<std::uint8_t, bool> failing;
  std::deque<std::vector<std::uint8_t>> input;
  std::vector<std::vector<std::uint8_t>> sent;
  int opens = 0;
};

std::mutex m;
std::condition_variable cv;
std::map<std::string, Device> devices;
int handles = 0;
int enumerations = 0;

Device* find(const std::string& path) {
  auto it = devices.find(path);
  return it == devices.end() ? nullptr : &it->second;
}

wchar_t* wcopy(const std::wstring& s) {
  auto* w = static_cast<wchar_t*>(std::calloc(s.size() + 1, sizeof(wchar_t)));
  std::wmemcpy(w, s.c_str(), s.size());
  return w;
}

}  // namespace

void reset() {
  std::lock_guard lock(m);
  devices.clear();
  handles = 0;
  enumerations = 0;
}

void plug(const DeviceSpec& spec) {
  {
    std::lock_guard lock(m);
    Device& d = devices[spec.path];
    d.spec = spec;
    d.plugged = true;
    ++d.generation;
    d.input.clear();
  }
  cv.notify_all();
}

void unplug(const std::string& path) {
  {
    std::lock_guard lock(m);
    if (Device* d = find(path)) d->plugged = false;
  }
  cv.notify_all();
}

void set_feature(const std::string& path, std::vector<std::uint8_t> report, int for_id) {
  std::lock_guard lock(m);
  Device& d = devices[path];
  const auto id = static_cast<std::uint8_t>(for_id < 0 ? report.at(0) : for_id);
  d.failing[id] = false;
  d.features[id] = std::move(report);
}

void fail_feature(const std::string& path, std::uint8_t report_id) {
  std::lock_guard lock(m);
  devices[path].failing[report_id] = true;
}

void push_input(const std::string& path, std::vector<std::uint8_t> report) {
  {
    std::lock_guard lock(m);
    devices[path].input.push_back(std::move(report));
  }
  cv.notify_all();
}

std::size_t pending_input(const std::string& path) {
  std::lock_guard lock(m);
  const Device* d = find(path);
  return d ? d->input.size() : 0;
}

std::vector<std::vector<std::uint8_t>> sent_features(const std::string& path) {
  std::lock_guard lock(m);
  const Device* d = find(path);
  return d ? d->sent : std::vector<std::vector<std::uint8_t>>{};
}

int open_count(const std::string& path) {
  std::lock_guard lock(m);
  const Device* d = find(path);
  return d ? d->opens : 0;
}

int open_handles() {
  std::lock_guard lock(m);
  return handles;
}

int enumerate_calls() {
  std::lock_guard lock(m);
  return enumerations;
}

}  // namespace fake_hid

using fake_hid::devices;
using fake_hid::m;

namespace {
// The device behind a handle, if the handle is still live (same plug-in, still plugged).
fake_hid::Device* live(hid_device* h) {
  fake_hid::Device* d = fake_hid::find(h->path);
  return (d && d->plugged && d->generation == h->generation) ? d : nullptr;
}
}  // namespace

extern "C" {

int hid_init(void) {
  return 0;
}
int hid_exit(void) {
  return 0;
}

hid_device_info* hid_enumerate(unsigned short, unsigned short) {
  std::lock_guard lock(m);
  ++fake_hid::enumerations;
  hid_device_info* head = nullptr;
  for (auto it = devices.rbegin(); it != devices.rend(); ++it) {
    const fake_hid::Device& d = it->second;
    if (!d.plugged) continue;
    auto* info = static_cast<hid_device_info*>(std::calloc(1, sizeof(hid_device_info)));
    info->path = strdup(d.spec.path.c_str());
    info->vendor_id = d.spec.vendor_id;
    info->product_id = d.spec.product_id;
    info->usage_page = d.spec.usage_page;
    info->usage = d.spec.usage;
    info->product_string = fake_hid::wcopy(d.spec.product);
    info->manufacturer_string = fake_hid::wcopy(L"gazelod tests");
    info->serial_number = fake_hid::wcopy(L"0001");
    info->interface_number = 0;
    info->next = head;
    head = info;
  }
  return head;
}

void hid_free_enumeration(hid_device_info* devs) {
  while (devs) {
    hid_device_info* next = devs->next;
    std::free(devs->path);
    std::free(devs->product_string);
    std::free(devs->manufacturer_string);
    std::free(devs->serial_number);
    std::free(devs);
    devs = next;
  }
}

hid_device* hid_open_path(const char* path) {
  std::lock_guard lock(m);
  fake_hid::Device* d = fake_hid::find(path);
  if (!d || !d->plugged) return nullptr;
  ++d->opens;
  ++fake_hid::handles;
  return new hid_device_{path, d->generation};
}

void hid_close(hid_device* dev) {
  if (!dev) return;
  {
    std::lock_guard lock(m);
    --fake_hid::handles;
  }
  delete dev;
}

int hid_read_timeout(hid_device* dev, unsigned char* data, size_t length, int milliseconds) {
  std::unique_lock lock(m);
  // Never wait long: the tests use a few ms at most.
  const auto wait = std::chrono::milliseconds(milliseconds < 0 ? 5 : std::min(milliseconds, 5));
  fake_hid::cv.wait_for(lock, wait, [&] {
    fake_hid::Device* d = fake_hid::find(dev->path);
    return !d || !live(dev) || !d->input.empty();
  });
  fake_hid::Device* d = fake_hid::find(dev->path);
  if (!d) return -1;
  if (d->generation == dev->generation && !d->input.empty()) {  // queued reports come first
    std::vector<std::uint8_t> r = std::move(d->input.front());
    d->input.pop_front();
    const std::size_t n = std::min(length, r.size());
    std::memcpy(data, r.data(), n);
    return static_cast<int>(n);
  }
  return live(dev) ? 0 : -1;
}

int hid_read(hid_device* dev, unsigned char* data, size_t length) {
  return hid_read_timeout(dev, data, length, 5);
}

int hid_get_feature_report(hid_device* dev, unsigned char* data, size_t length) {
  std::lock_guard lock(m);
  fake_hid::Device* d = live(dev);
  if (!d || length == 0) return -1;
  auto it = d->features.find(data[0]);
  if (it == d->features.end() || d->failing[data[0]]) return -1;
  const std::size_t n = std::min(length, it->second.size());
  std::memcpy(data, it->second.data(), n);
  return static_cast<int>(n);
}

int hid_send_feature_report(hid_device* dev, const unsigned char* data, size_t length) {
  std::lock_guard lock(m);
  fake_hid::Device* d = live(dev);
  if (!d) return -1;
  d->sent.emplace_back(data, data + length);
  return static_cast<int>(length);
}

const wchar_t* hid_error(hid_device* dev) {
  return dev ? L"fake device gone" : L"fake hidapi error";
}

}  // extern "C"
