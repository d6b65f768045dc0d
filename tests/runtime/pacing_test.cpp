// SPDX-License-Identifier: Apache-2.0
// Paced frame loop: xrWaitFrame sleeps to the display refresh, predicted display times lie on
// the refresh grid and in the future of CLOCK_MONOTONIC (XR_KHR_convert_timespec_time).
// Lower bounds on elapsed time only: a slow machine cannot make it fail.
#include "sim/runtime/xr_headers.hpp"
#include "tests/runtime/xr_client.hpp"

#include <time.h>

namespace gazelod::xrrt_test {
namespace {

std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

TEST(RuntimePacing, WaitFrameSleepsToTheDisplayRefresh) {
  use_runtime(30.0, /*paced=*/true);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME}));
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  auto to_xr = proc<PFN_xrConvertTimespecTimeToTimeKHR>(hs.instance, "xrConvertTimespecTimeToTimeKHR");
  auto to_timespec = proc<PFN_xrConvertTimeToTimespecTimeKHR>(hs.instance, "xrConvertTimeToTimespecTimeKHR");
  ASSERT_TRUE(to_xr && to_timespec);
  constexpr int kFrames = 20;
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  const XrTime first = fs.predictedDisplayTime;
  const std::int64_t start_ns = monotonic_ns();
  for (int i = 0; i < kFrames; ++i) {
    const XrTime before = fs.predictedDisplayTime;
    // The clock just before the call: the prediction must lie ahead of it. (Reading the clock
    // after the call would flake on a loaded machine, where the thread may be descheduled.)
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = fs.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ASSERT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
    EXPECT_GT(fs.predictedDisplayTime, before);
    EXPECT_EQ((fs.predictedDisplayTime - first) % fs.predictedDisplayPeriod, 0) << "on the refresh grid";
    XrTime now_xr = 0;
    ASSERT_EQ(to_xr(hs.instance, &now, &now_xr), XR_SUCCESS);
    EXPECT_GT(fs.predictedDisplayTime, now_xr);
  }
  const std::int64_t elapsed_ns = monotonic_ns() - start_ns;
  EXPECT_GE(elapsed_ns, (kFrames - 1) * fs.predictedDisplayPeriod) << "xrWaitFrame did not pace";
  // Round trip of the time conversion.
  timespec ts{};
  ASSERT_EQ(to_timespec(hs.instance, fs.predictedDisplayTime, &ts), XR_SUCCESS);
  XrTime back = 0;
  ASSERT_EQ(to_xr(hs.instance, &ts, &back), XR_SUCCESS);
  EXPECT_EQ(back, fs.predictedDisplayTime);
  EXPECT_EQ(to_timespec(hs.instance, 0, &ts), XR_ERROR_TIME_INVALID);
  hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
