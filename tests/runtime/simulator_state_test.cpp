// SPDX-License-Identifier: Apache-2.0
// XR_GAZELOD_simulator_state through the loader: frame count, time base, last predicted time,
// the scenario's end and the last frame's composition layers, as the runtime's side channel
// reports them.
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

// The composition layers of the last xrEndFrame, as the runtime received them (a headless
// session records them without showing them).
TEST(RuntimeSimulatorState, ReportsTheLastFramesLayers) {
  use_runtime(1.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME}));
  auto layers_of = proc<PFN_xrEnumerateSubmittedLayersGAZELOD>(hs.instance, "xrEnumerateSubmittedLayersGAZELOD");
  ASSERT_NE(layers_of, nullptr);
  std::uint32_t n = 7;
  ASSERT_EQ(layers_of(hs.session, 0, &n, nullptr), XR_SUCCESS);
  EXPECT_EQ(n, 0u);  // no frame yet
  const XrSpace local = hs.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSpace view = hs.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  XrCompositionLayerQuad quad{XR_TYPE_COMPOSITION_LAYER_QUAD};
  quad.space = local;
  quad.pose = {{0, 0, 0, 1}, {1, 2, -3}};
  XrCompositionLayerCubeKHR cube{XR_TYPE_COMPOSITION_LAYER_CUBE_KHR};
  cube.space = view;
  cube.orientation = {0, 1, 0, 0};
  XrCompositionLayerProjectionView views[2] = {{XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW},
                                               {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW}};
  views[0].pose = {{0, 0, 0, 1}, {-0.03f, 0, 0}};
  views[1].pose = {{0, 0, 0, 1}, {0.03f, 0, 0}};
  XrCompositionLayerProjection projection{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  projection.space = view;
  projection.viewCount = 2;
  projection.views = views;
  const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&quad),
                                                  reinterpret_cast<const XrCompositionLayerBaseHeader*>(&cube),
                                                  reinterpret_cast<const XrCompositionLayerBaseHeader*>(&projection)};
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = fs.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.layerCount = 3;
  end.layers = layers;
  ASSERT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
  ASSERT_EQ(layers_of(hs.session, 0, &n, nullptr), XR_SUCCESS);
  ASSERT_EQ(n, 3u);
  XrSubmittedLayerGAZELOD got[3];
  EXPECT_EQ(layers_of(hs.session, 2, &n, got), XR_ERROR_SIZE_INSUFFICIENT);
  ASSERT_EQ(layers_of(hs.session, 3, &n, got), XR_SUCCESS);
  EXPECT_EQ(got[0].layerType, XR_TYPE_COMPOSITION_LAYER_QUAD);
  EXPECT_EQ(got[0].space, local);
  ASSERT_EQ(got[0].poseCount, 1u);
  EXPECT_EQ(got[0].poses[0].position.z, -3.0f);
  EXPECT_EQ(got[1].layerType, XR_TYPE_COMPOSITION_LAYER_CUBE_KHR);
  ASSERT_EQ(got[1].poseCount, 1u);
  EXPECT_EQ(got[1].poses[0].orientation.y, 1.0f);
  EXPECT_EQ(got[1].poses[0].position.x, 0.0f);
  EXPECT_EQ(got[2].layerType, XR_TYPE_COMPOSITION_LAYER_PROJECTION);
  EXPECT_EQ(got[2].space, view);
  ASSERT_EQ(got[2].poseCount, 2u);
  EXPECT_EQ(got[2].poses[1].position.x, 0.03f);
  // The next frame, without layers, replaces them.
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(hs.session, nullptr), XR_SUCCESS);
  end.displayTime = fs.predictedDisplayTime;
  end.layerCount = 0;
  end.layers = nullptr;
  ASSERT_EQ(xrEndFrame(hs.session, &end), XR_SUCCESS);
  ASSERT_EQ(layers_of(hs.session, 0, &n, nullptr), XR_SUCCESS);
  EXPECT_EQ(n, 0u);
  EXPECT_EQ(layers_of(XR_NULL_HANDLE, 0, &n, nullptr), XR_ERROR_HANDLE_INVALID);
  hs.destroy();
}

TEST(RuntimeSimulatorState, UnavailableWithoutTheExtension) {
  use_runtime(0.5);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(hs.instance, "xrGetSimulatorStateGAZELOD", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(xrGetInstanceProcAddr(hs.instance, "xrEnumerateSubmittedLayersGAZELOD", &fn),
            XR_ERROR_FUNCTION_UNSUPPORTED);
  hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
