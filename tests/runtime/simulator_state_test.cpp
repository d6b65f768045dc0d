// SPDX-License-Identifier: Apache-2.0
// XR_GAZELOD_simulator_state through the loader: frame count, time base, last predicted time
// and the scenario's end, as the runtime's side channel reports them.
#include "sim/runtime/simulator_state_ext.h"
#include "tests/runtime/xr_client.hpp"

namespace gazelod::xrrt_test {
namespace {

TEST(RuntimeSimulatorState, ReportsFramesTimeBaseAndScenarioEnd) {
  use_runtime(0.5);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME}));
  auto get_state = proc<PFN_xrGetSimulatorStateGAZELOD>(hs.instance, "xrGetSimulatorStateGAZELOD");
  ASSERT_NE(get_state, nullptr);
  XrSimulatorStateGAZELOD st{};
  ASSERT_EQ(get_state(hs.session, &st), XR_SUCCESS);
  EXPECT_EQ(st.frameCount, 0u);
  EXPECT_EQ(st.lastPredictedDisplayTime, 0);
  EXPECT_EQ(st.scenarioTimeBase, 1'000'000'000);
  EXPECT_EQ(st.scenarioDuration, 500'000'000);
  EXPECT_EQ(st.paced, XR_FALSE);
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  for (int i = 0; i < 10; ++i) ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(get_state(hs.session, &st), XR_SUCCESS);
  EXPECT_EQ(st.frameCount, 10u);
  EXPECT_EQ(st.lastPredictedDisplayTime, fs.predictedDisplayTime);
  EXPECT_EQ(st.scenarioEnded, XR_FALSE);
  while (fs.predictedDisplayTime - st.scenarioTimeBase < st.scenarioDuration)
    ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(get_state(hs.session, &st), XR_SUCCESS);
  EXPECT_EQ(st.scenarioEnded, XR_TRUE);
  hs.destroy();
}

TEST(RuntimeSimulatorState, UnavailableWithoutTheExtension) {
  use_runtime(0.5);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(hs.instance, "xrGetSimulatorStateGAZELOD", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
