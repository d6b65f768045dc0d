// SPDX-License-Identifier: Apache-2.0
// Per-report cost on the HID reader thread. Baseline: copying the 65 report bytes, which any
// reader does; the others add decoding, device->host time mapping and the screen geometry.
#include "gaze/hid/clock_map.hpp"
#include "gaze/hid/reports.hpp"
#include "gaze/hid/screen_geometry.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cstring>
#include <vector>

namespace {

using namespace gazelod::gaze::hid;

std::array<std::uint8_t, kTrackingSizeWithHead> make_report(std::uint64_t t_us) {
  std::array<std::uint8_t, kTrackingSizeWithHead> r{};
  r[0] = kReportTrackingData;
  std::memcpy(&r[1], &t_us, 8);  // little-endian host, as on x86-64 and arm64
  const std::int32_t fields[] = {263520, 148230, -32000, 0, 600000, 32000, 0, 600000, 0, 0, 680000, 0, 0, 0};
  std::memcpy(&r[9], fields, sizeof fields);
  return r;
}

void BM_CopyReport_Baseline(benchmark::State& state) {
  auto r = make_report(1000);
  std::array<std::uint8_t, kTrackingSizeWithHead> out{};
  std::uint64_t t = 0;
  for (auto _ : state) {
    std::memcpy(&r[1], &t, 8);
    std::memcpy(out.data(), r.data(), r.size());
    benchmark::DoNotOptimize(out);
    t += 4000;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CopyReport_Baseline);

void BM_DecodeTracking(benchmark::State& state) {
  auto r = make_report(1000);
  std::uint64_t t = 0;
  for (auto _ : state) {
    std::memcpy(&r[1], &t, 8);
    auto d = decode_tracking(r);
    benchmark::DoNotOptimize(d);
    t += 4000;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DecodeTracking);

void BM_ReportToSample(benchmark::State& state) {
  auto r = make_report(1000);
  ClockMap clock;
  const ScreenGeometry screen{0.52704, 0.29646, {}};
  std::uint64_t t = 0;
  std::int64_t host = 5'000'000'000;
  for (auto _ : state) {
    std::memcpy(&r[1], &t, 8);
    auto d = decode_tracking(r);
    auto s = gaze_from_screen(*d.value, screen);
    s.t_ns = clock.map(d.value->timestamp_us, host);
    benchmark::DoNotOptimize(s);
    t += 4000;
    host += 4'000'000 + static_cast<std::int64_t>(t % 3'000'000);  // latency jitter
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ReportToSample);

}  // namespace
BENCHMARK_MAIN();
