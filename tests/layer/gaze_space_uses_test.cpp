// SPDX-License-Identifier: Apache-2.0
// A gaze space used elsewhere than xrLocateSpace, through the Khronos loader with the layer over
// the simulated runtime (which lacks eye gaze): xrLocateSpacesKHR answers as xrLocateSpace does,
// xrLocateViews in a gaze space gives the views in the eye, and a composition layer in a gaze
// space reaches the runtime placed by the eye (the runtime's XR_GAZELOD_simulator_state reports
// what it received). The runtime knows a gaze space only as a VIEW space, so without the layer's
// help each of these would be the head.
#include "xr/khr_locate_spaces.h"
#include "sim/runtime/simulator_state_ext.h"
#include "tests/layer/layer_test_util.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cstring>

namespace gazelod::layer_test {
namespace {

using xrrt_test::proc;

constexpr XrSpaceLocationFlags kAll = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                                      XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT |
                                      XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
constexpr XrViewStateFlags kViewValid = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT;

struct P {  // a pose in double precision
  glm::dquat q{1, 0, 0, 0};
  glm::dvec3 p{0.0};
};
P of(const XrPosef& x) {
  return {glm::normalize(glm::dquat(x.orientation.w, x.orientation.x, x.orientation.y, x.orientation.z)),
          {x.position.x, x.position.y, x.position.z}};
}
P compose(const P& a, const P& b) {
  return {a.q * b.q, a.p + a.q * b.p};
}
P inverse(const P& a) {
  const glm::dquat i = glm::conjugate(a.q);
  return {i, -(i * a.p)};
}
// Same pose within single precision: angle between the orientations and distance.
void expect_near(const P& a, const P& b, const char* what, int frame) {
  EXPECT_LT(2.0 * std::acos(std::min(1.0, std::abs(glm::dot(a.q, b.q)))), 2e-5) << what << ", frame " << frame;
  EXPECT_LT(glm::length(a.p - b.p), 1e-5) << what << ", frame " << frame;
}
bool same(const XrPosef& a, const XrPosef& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// xrLocateSpace with XrSpaceVelocity chained.
struct Single {
  XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
  XrSpaceVelocity velocity{XR_TYPE_SPACE_VELOCITY};
};
Single locate(XrSpace space, XrSpace base, XrTime t) {
  Single s;
  s.location.next = &s.velocity;
  EXPECT_EQ(xrLocateSpace(space, base, t, &s.location), XR_SUCCESS);
  return s;
}

LayerSetup setup_with_blink() {
  const std::string dir = scratch_dir();
  write_trace(dir + "/trace.csv", 3.0, 200.0, 1.0, 1.3);  // stale past the 150 ms hold
  LayerSetup setup;
  setup.trace = dir + "/trace.csv";
  return setup;
}

TEST(LayerGazeSpaceUses, LocateSpacesKhrAnswersAsLocateSpace) {
  apply(setup_with_blink());
  GazeRig rig;
  rig.extensions = {XR_KHR_LOCATE_SPACES_EXTENSION_NAME};
  rig.create();
  if (HasFatalFailure()) return;
  auto locate_spaces = proc<PFN_xrLocateSpacesKHR>(rig.hs.instance, "xrLocateSpacesKHR");
  ASSERT_NE(locate_spaces, nullptr);
  const XrSpace spaces[] = {rig.gaze_space, rig.view, rig.local};
  constexpr std::uint32_t n = 3;
  int located = 0, stale = 0;
  for (int f = 0; f < 200; ++f) {
    const XrTime t = rig.frame();
    ASSERT_EQ(rig.sync(), XR_SUCCESS);
    // The gaze space among the spaces, then as the base, then not at all (passed through).
    const XrSpace bases[] = {rig.local, rig.gaze_space, rig.view};
    for (const XrSpace base : bases) {
      const std::uint32_t count = base == rig.view ? n - 1 : n;  // LOCAL and VIEW only
      const XrSpace* located_spaces = base == rig.view ? spaces + 1 : spaces;
      XrSpaceLocationDataKHR data[n];
      XrSpaceVelocityDataKHR velocity[n];
      for (std::uint32_t i = 0; i < n; ++i) {
        data[i] = {0xff, {{3, 2, 1, 0}, {4, 3, 1}}};  // garbage: must be overwritten
        velocity[i] = {XR_SPACE_VELOCITY_LINEAR_VALID_BIT, {9, 9, 9}, {9, 9, 9}};
      }
      XrSpaceVelocitiesKHR velocities{XR_TYPE_SPACE_VELOCITIES_KHR, nullptr, count, velocity};
      XrSpaceLocationsKHR locations{XR_TYPE_SPACE_LOCATIONS_KHR, &velocities, count, data};
      const XrSpacesLocateInfoKHR info{XR_TYPE_SPACES_LOCATE_INFO_KHR, nullptr, base, t, count, located_spaces};
      ASSERT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_SUCCESS) << "frame " << f;
      for (std::uint32_t i = 0; i < count; ++i) {
        const Single one = locate(located_spaces[i], base, t);
        EXPECT_EQ(data[i].locationFlags, one.location.locationFlags) << "frame " << f << ", space " << i;
        EXPECT_TRUE(same(data[i].pose, one.location.pose)) << "frame " << f << ", space " << i;
        const bool gaze = located_spaces[i] == rig.gaze_space || base == rig.gaze_space;
        if (gaze) {
          EXPECT_EQ(velocity[i].velocityFlags, 0u);
        } else {  // the runtime's
          EXPECT_EQ(velocity[i].velocityFlags, one.velocity.velocityFlags);
          EXPECT_EQ(std::memcmp(&velocity[i].linearVelocity, &one.velocity.linearVelocity, sizeof(XrVector3f)), 0);
          EXPECT_EQ(std::memcmp(&velocity[i].angularVelocity, &one.velocity.angularVelocity, sizeof(XrVector3f)), 0);
        }
      }
      if (base == rig.local) (data[0].locationFlags == kAll ? located : stale) += 1;
    }
  }
  EXPECT_GT(located, 150);
  EXPECT_GT(stale, 10);  // the blink: not located, as xrLocateSpace says

  // With a gaze space, the layer checks the structures as the specification asks.
  const XrTime t = rig.frame();
  ASSERT_EQ(rig.sync(), XR_SUCCESS);
  XrSpaceLocationDataKHR data[n];
  XrSpaceVelocityDataKHR velocity[n];
  XrSpaceVelocitiesKHR velocities{XR_TYPE_SPACE_VELOCITIES_KHR, nullptr, n - 1, velocity};
  XrSpaceLocationsKHR locations{XR_TYPE_SPACE_LOCATIONS_KHR, &velocities, n, data};
  XrSpacesLocateInfoKHR info{XR_TYPE_SPACES_LOCATE_INFO_KHR, nullptr, rig.local, t, n, spaces};
  EXPECT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);  // velocity count
  velocities.velocityCount = n;
  locations.locationCount = n - 1;
  EXPECT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);  // location count
  locations.locationCount = 0;
  info.spaceCount = 0;
  info.baseSpace = rig.gaze_space;
  EXPECT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);  // no spaces
  info.spaceCount = locations.locationCount = n;
  locations.type = XR_TYPE_SPACE_LOCATION;
  EXPECT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);
  locations.type = XR_TYPE_SPACE_LOCATIONS_KHR;
  info.time = 0;
  EXPECT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_ERROR_TIME_INVALID);
  info.time = t;
  EXPECT_EQ(locate_spaces(rig.hs.session, &info, &locations), XR_SUCCESS);
  rig.destroy();
}

// The layer hands out xrLocateSpacesKHR / xrLocateSpaces only when the runtime gives them.
TEST(LayerGazeSpaceUses, LocateSpacesOnlyWhereTheRuntimeHasIt) {
  apply(setup_with_blink());
  GazeRig rig;
  rig.create();
  if (HasFatalFailure()) return;
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(rig.hs.instance, "xrLocateSpacesKHR", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(fn, nullptr);
  EXPECT_EQ(xrGetInstanceProcAddr(rig.hs.instance, "xrLocateSpaces", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);  // 1.0
  EXPECT_EQ(fn, nullptr);
  rig.destroy();
}

TEST(LayerGazeSpaceUses, ViewsLocatedInAGazeSpaceAreInTheEye) {
  apply(setup_with_blink());
  GazeRig rig;
  rig.create();
  if (HasFatalFailure()) return;
  int located = 0, stale = 0;
  for (int f = 0; f < 200; ++f) {
    const XrTime t = rig.frame();
    ASSERT_EQ(rig.sync(), XR_SUCCESS);
    auto views_in = [&](XrSpace space, XrViewState& state, XrView(&views)[2]) {
      XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO};
      info.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
      info.displayTime = t;
      info.space = space;
      std::uint32_t count = 0;
      EXPECT_EQ(xrLocateViews(rig.hs.session, &info, &state, 2, &count, views), XR_SUCCESS);
      EXPECT_EQ(count, 2u);
    };
    XrViewState in_gaze_state{XR_TYPE_VIEW_STATE}, in_local_state{XR_TYPE_VIEW_STATE};
    XrView in_gaze[2] = {{XR_TYPE_VIEW}, {XR_TYPE_VIEW}}, in_local[2] = {{XR_TYPE_VIEW}, {XR_TYPE_VIEW}};
    views_in(rig.gaze_space, in_gaze_state, in_gaze);
    views_in(rig.local, in_local_state, in_local);
    const Single gaze = locate(rig.gaze_space, rig.local, t);
    for (int i = 0; i < 2; ++i) EXPECT_EQ(std::memcmp(&in_gaze[i].fov, &in_local[i].fov, sizeof(XrFovf)), 0);
    if (gaze.location.locationFlags == 0) {
      ++stale;
      EXPECT_EQ(in_gaze_state.viewStateFlags, 0u) << "frame " << f;  // no tracked bits without valid ones
      continue;
    }
    ++located;
    ASSERT_EQ(in_gaze_state.viewStateFlags, in_local_state.viewStateFlags) << "frame " << f;
    ASSERT_EQ(in_local_state.viewStateFlags & kViewValid, kViewValid);
    const P to_gaze = inverse(of(gaze.location.pose));
    for (int i = 0; i < 2; ++i) expect_near(of(in_gaze[i].pose), compose(to_gaze, of(in_local[i].pose)), "view", f);
  }
  EXPECT_GT(located, 150);
  EXPECT_GT(stale, 10);
  rig.destroy();
}

TEST(LayerGazeSpaceUses, LayersInAGazeSpaceReachTheRuntimePlacedByTheEye) {
  apply(setup_with_blink());
  GazeRig rig;
  rig.extensions = {XR_GAZELOD_SIMULATOR_STATE_EXTENSION_NAME};
  rig.create();
  if (HasFatalFailure()) return;
  auto submitted = proc<PFN_xrEnumerateSubmittedLayersGAZELOD>(rig.hs.instance, "xrEnumerateSubmittedLayersGAZELOD");
  ASSERT_NE(submitted, nullptr);
  // A reticle 2 m along the gaze, turned a little; a quad fixed in LOCAL; a projection in the
  // gaze space (headless: no swapchains needed, the runtime only records them).
  XrCompositionLayerQuad reticle{XR_TYPE_COMPOSITION_LAYER_QUAD};
  reticle.space = rig.gaze_space;
  reticle.eyeVisibility = XR_EYE_VISIBILITY_BOTH;
  reticle.pose = {{0.0f, 0.0871557f, 0.0f, 0.9961947f}, {0.05f, -0.02f, -2.0f}};  // 10 degrees about +Y
  reticle.size = {0.1f, 0.1f};
  XrCompositionLayerQuad world = reticle;
  world.space = rig.local;
  world.pose = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.5f, 0.0f, -3.0f}};
  XrCompositionLayerProjectionView views[2] = {{XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW},
                                               {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW}};
  views[0].pose = {{0.0f, 0.0f, 0.0f, 1.0f}, {-0.032f, 0.0f, 0.0f}};
  views[1].pose = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.032f, 0.0f, 0.0f}};
  XrCompositionLayerProjection projection{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  projection.space = rig.gaze_space;
  projection.viewCount = 2;
  projection.views = views;
  const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&world),
                                                  reinterpret_cast<const XrCompositionLayerBaseHeader*>(&reticle),
                                                  reinterpret_cast<const XrCompositionLayerBaseHeader*>(&projection)};
  int placed = 0, held = 0;
  std::optional<P> last;
  for (int f = 0; f < 200; ++f) {
    XrFrameState state{XR_TYPE_FRAME_STATE};
    ASSERT_EQ(xrWaitFrame(rig.hs.session, nullptr, &state), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(rig.hs.session, nullptr), XR_SUCCESS);
    ASSERT_EQ(rig.sync(), XR_SUCCESS);
    const XrTime t = state.predictedDisplayTime;
    const Single eye = locate(rig.gaze_space, rig.view, t);  // the eye in the head
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = t;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    end.layerCount = 3;
    end.layers = layers;
    ASSERT_EQ(xrEndFrame(rig.hs.session, &end), XR_SUCCESS);
    std::uint32_t n = 0;
    ASSERT_EQ(submitted(rig.hs.session, 0, &n, nullptr), XR_SUCCESS);
    std::vector<XrSubmittedLayerGAZELOD> got(n);
    ASSERT_EQ(submitted(rig.hs.session, n, &n, got.data()), XR_SUCCESS);
    ASSERT_GE(n, 1u);
    // The LOCAL quad: untouched.
    EXPECT_EQ(got[0].space, rig.local);
    EXPECT_TRUE(same(got[0].poses[0], world.pose));
    // Every layer reaches the runtime (its checks answer as without the layer); without gaze
    // (the blink) they are placed by the eye they were last placed by.
    ASSERT_EQ(n, 3u) << "frame " << f;
    if (eye.location.locationFlags == 0) {
      ++held;
      ASSERT_TRUE(last.has_value()) << "frame " << f << ": the blink before any gaze";
    } else {
      ++placed;
      last = of(eye.location.pose);
    }
    const P e = *last;
    EXPECT_EQ(got[1].layerType, XR_TYPE_COMPOSITION_LAYER_QUAD);
    EXPECT_EQ(got[1].space, rig.gaze_space);  // its handle: the head (VIEW) on the runtime
    ASSERT_EQ(got[1].poseCount, 1u);
    expect_near(of(got[1].poses[0]), compose(e, of(reticle.pose)), "reticle", f);
    EXPECT_EQ(got[2].layerType, XR_TYPE_COMPOSITION_LAYER_PROJECTION);
    ASSERT_EQ(got[2].poseCount, 2u);
    for (int i = 0; i < 2; ++i) expect_near(of(got[2].poses[i]), compose(e, of(views[i].pose)), "view", f);
  }
  EXPECT_GT(placed, 150);
  EXPECT_GT(held, 10);
  // A pose that is no rotation goes down as given, for the runtime to refuse (composing it
  // would have normalised it into a valid one; this headless session accepts layers unchecked,
  // so what arrived is compared).
  XrFrameState state{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(rig.hs.session, nullptr, &state), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(rig.hs.session, nullptr), XR_SUCCESS);
  XrCompositionLayerQuad bad = reticle;
  bad.pose.orientation = {0.0f, 0.0f, 0.0f, 0.0f};
  const XrCompositionLayerBaseHeader* bad_layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&bad)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = state.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.layerCount = 1;
  end.layers = bad_layers;
  ASSERT_EQ(xrEndFrame(rig.hs.session, &end), XR_SUCCESS);
  XrSubmittedLayerGAZELOD arrived{};
  std::uint32_t n = 0;
  ASSERT_EQ(submitted(rig.hs.session, 1, &n, &arrived), XR_SUCCESS);
  ASSERT_EQ(n, 1u);
  EXPECT_EQ(arrived.poses[0].orientation.w, 0.0f);
  EXPECT_EQ(arrived.poses[0].position.z, -2.0f);
  // The application's layers are its own: nothing written into them.
  EXPECT_EQ(reticle.space, rig.gaze_space);
  EXPECT_EQ(reticle.pose.position.z, -2.0f);
  EXPECT_EQ(projection.views, views);
  EXPECT_EQ(views[1].pose.position.x, 0.032f);
  rig.destroy();
}

}  // namespace
}  // namespace gazelod::layer_test
