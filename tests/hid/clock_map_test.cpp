// SPDX-License-Identifier: Apache-2.0
// Device-to-host time mapping: a simulated device clock with a known offset and drift, USB
// latency with a known floor, 32-bit counter wrap-around, and device restarts.
#include "gaze/hid/clock_map.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstdint>

namespace gazelod::gaze::hid {
namespace {

// A deterministic latency generator: floor + a spread, with every 8th report at the floor
// (as real USB polling gives the minimum often).
struct Latency {
  std::uint64_t state = 12345;
  std::int64_t floor_ns, spread_ns;
  std::int64_t next(int i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    if (i % 8 == 0) return floor_ns;
    return floor_ns + static_cast<std::int64_t>((state >> 33) % static_cast<std::uint64_t>(spread_ns));
  }
};

TEST(HidClockMap, RecoversOffsetAndDriftFromNoisyLatency) {
  ClockMap map;
  const double drift = 80e-6;                 // device clock runs 80 ppm slow
  const std::int64_t offset = 5'000'000'000;  // host = device + 5 s at start
  Latency lat{12345, 1'000'000, 3'000'000};   // 1..4 ms
  const std::int64_t period_us = 4000;        // 250 Hz
  std::int64_t worst_ns = 0;
  for (int i = 0; i < 250 * 30; ++i) {
    const std::int64_t dev_us = 1000 + i * period_us;
    const std::int64_t true_host_ns =
        offset + static_cast<std::int64_t>(std::llround(static_cast<double>(dev_us) * 1000.0 * (1.0 + drift)));
    const std::int64_t recv = true_host_ns + lat.next(i);
    const std::int64_t mapped = map.map(static_cast<std::uint64_t>(dev_us), recv);
    EXPECT_LE(mapped, recv);
    // After the first 5 s the fit has settled: within the latency floor (+ 0.2 ms).
    if (i > 250 * 5) worst_ns = std::max(worst_ns, std::abs(mapped - (true_host_ns + 1'000'000)));
  }
  EXPECT_LT(worst_ns, 200'000);
  EXPECT_NEAR(map.drift_ppm(), 80.0, 5.0);
  EXPECT_EQ(map.clock_resets(), 0u);
}

// A reader thread 20 ms behind for the first second (every report read 20 ms late), which then
// catches up: the backlog arrives at one read, after which USB latency is 1-4 ms. The mapped
// times must never go backwards (a recorded trace would be rejected), and the device's own
// timing must be back at once: the fit over earlier windows alone stays 20 ms high until they
// age out (20 s), leaving every sample at its jittered receive time.
TEST(HidClockMap, CaughtUpBacklogNeitherReversesTimeNorLingers) {
  for (const int rate_hz : {120, 250, 1000}) {
    ClockMap map;
    Latency lat{777, 1'000'000, 3'000'000};
    const std::int64_t period_us = 1'000'000 / rate_hz;
    const std::int64_t start_ns = 7'000'000'000, caught_up_ns = start_ns + 1'001'000'000;
    std::int64_t previous = INT64_MIN, previous_recv = INT64_MIN, worst_ns = 0;
    for (int i = 0; i < rate_hz * 5; ++i) {
      const std::int64_t dev_us = i * period_us;
      const std::int64_t true_host_ns = start_ns + dev_us * 1000;
      std::int64_t recv = true_host_ns + 20'000'000;
      if (recv >= caught_up_ns) recv = std::max(caught_up_ns, true_host_ns + lat.next(i));
      recv = std::max(recv, previous_recv);  // one reader: reports arrive in order
      previous_recv = recv;
      const std::int64_t mapped = map.map(static_cast<std::uint64_t>(dev_us), recv);
      ASSERT_GE(mapped, previous) << rate_hz << " Hz, sample " << i;
      ASSERT_LE(mapped, recv);
      previous = mapped;
      if (dev_us >= 1'600'000) worst_ns = std::max(worst_ns, std::abs(mapped - (true_host_ns + 1'000'000)));
    }
    EXPECT_LT(worst_ns, 200'000) << rate_hz << " Hz";
  }
}

TEST(HidClockMap, ThirtyTwoBitCounterWrapsWithoutAJump) {
  ClockMap map;  // 32-bit unwrap by default
  const std::uint64_t wrap = std::uint64_t{1} << 32;
  const std::uint64_t start = wrap - 10'000;  // 10 ms before the wrap
  std::int64_t prev = 0;
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t dev_us = (start + static_cast<std::uint64_t>(i) * 1000) % wrap;
    const std::int64_t recv = 7'000'000'000 + i * 1'000'000;  // exactly 1 ms apart, no jitter
    const std::int64_t mapped = map.map(dev_us, recv);
    EXPECT_EQ(mapped, recv) << i;  // constant latency: mapping = receive time
    if (i > 0) {
      EXPECT_EQ(mapped - prev, 1'000'000) << "step across the wrap at i = " << i;
    }
    prev = mapped;
  }
  EXPECT_EQ(map.device_ns(), 99 * 1'000'000);
  EXPECT_EQ(map.clock_resets(), 0u);
}

TEST(HidClockMap, SixtyFourBitTimestampsBeyondTwoToThe32AreUnwrappedToo) {
  ClockMap map;
  const std::uint64_t base = (std::uint64_t{1} << 40) + 123;  // a device up for ~13 days
  for (int i = 0; i < 10; ++i) map.map(base + static_cast<std::uint64_t>(i) * 4000, i * 4'000'000);
  EXPECT_EQ(map.device_ns(), 9 * 4'000'000);
}

TEST(HidClockMap, BackwardsOrHugeJumpRestartsTheFit) {
  ClockMap map;
  for (int i = 0; i < 50; ++i) map.map(1'000'000 + static_cast<std::uint64_t>(i) * 4000, 1'000'000'000 + i * 4'000'000);
  // Device restarted: its clock is back near zero.
  const std::int64_t recv = 2'000'000'000;
  EXPECT_EQ(map.map(500, recv), recv);
  EXPECT_EQ(map.clock_resets(), 1u);
  EXPECT_EQ(map.device_ns(), 0);
  // Silence of a minute (> 10 s gap) is a restart as well.
  EXPECT_EQ(map.map(500 + 60'000'000, recv + 60'000'000'000), recv + 60'000'000'000);
  EXPECT_EQ(map.clock_resets(), 2u);
}

TEST(HidClockMap, ExcessiveDriftIsClamped) {
  ClockMapConfig c;
  c.max_drift_ppm = 100.0;
  ClockMap map(c);
  // Host advances 1% faster than the device: far beyond any crystal; the fit clamps at 100 ppm.
  for (int i = 0; i < 250 * 10; ++i)
    map.map(static_cast<std::uint64_t>(i) * 4000, static_cast<std::int64_t>(i * 4'040'000.0));
  EXPECT_NEAR(map.drift_ppm(), 100.0, 1e-9);
}

}  // namespace
}  // namespace gazelod::gaze::hid
