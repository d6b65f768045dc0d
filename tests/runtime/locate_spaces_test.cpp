// SPDX-License-Identifier: Apache-2.0
// XR_KHR_locate_spaces through the loader: xrLocateSpacesKHR locates each space as xrLocateSpace
// does (poses, flags, velocities), refuses what the specification (and CTS 1.1.41's
// test_XR_KHR_locate_spaces) refuses, and is there only when the extension is enabled.
#include "xr/khr_locate_spaces.h"
#include "tests/runtime/xr_client.hpp"

#include <cstring>
#include <vector>

namespace gazelod::xrrt_test {
namespace {

XrSpace reference(XrSession session, XrReferenceSpaceType type, XrPosef pose) {
  XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  info.referenceSpaceType = type;
  info.poseInReferenceSpace = pose;
  XrSpace space = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateReferenceSpace(session, &info, &space), XR_SUCCESS);
  return space;
}

TEST(RuntimeLocateSpaces, EachSpaceAsLocateSpaceLocatesIt) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({XR_KHR_LOCATE_SPACES_EXTENSION_NAME}));
  auto locate_spaces = proc<PFN_xrLocateSpacesKHR>(hs.instance, "xrLocateSpacesKHR");
  ASSERT_NE(locate_spaces, nullptr);
  const XrPosef identity{{0, 0, 0, 1}, {0, 0, 0}};
  const std::vector<XrSpace> spaces = {
      reference(hs.session, XR_REFERENCE_SPACE_TYPE_VIEW, identity),
      reference(hs.session, XR_REFERENCE_SPACE_TYPE_LOCAL, identity),
      reference(hs.session, XR_REFERENCE_SPACE_TYPE_STAGE, identity),
      reference(hs.session, XR_REFERENCE_SPACE_TYPE_VIEW, {{0, 0.7071068f, 0, 0.7071068f}, {0.1f, -0.2f, 0.3f}}),
  };
  const auto n = static_cast<std::uint32_t>(spaces.size());
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  for (int f = 0; f < 30; ++f) {
    XrFrameState fs{XR_TYPE_FRAME_STATE};
    ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
    for (XrSpace base : spaces) {
      std::vector<XrSpaceLocationDataKHR> data(n, {0xff, {{3, 2, 1, 0}, {4, 3, 1}}});
      std::vector<XrSpaceVelocityDataKHR> velocity(n, {0xff, {9, 9, 9}, {9, 9, 9}});
      XrSpaceVelocitiesKHR velocities{XR_TYPE_SPACE_VELOCITIES_KHR, nullptr, n, velocity.data()};
      XrSpaceLocationsKHR locations{XR_TYPE_SPACE_LOCATIONS_KHR, &velocities, n, data.data()};
      XrSpacesLocateInfoKHR info{XR_TYPE_SPACES_LOCATE_INFO_KHR};
      info.baseSpace = base;
      info.time = fs.predictedDisplayTime;
      info.spaceCount = n;
      info.spaces = spaces.data();
      ASSERT_EQ(locate_spaces(hs.session, &info, &locations), XR_SUCCESS);
      for (std::uint32_t i = 0; i < n; ++i) {
        XrSpaceVelocity v{XR_TYPE_SPACE_VELOCITY};
        XrSpaceLocation l{XR_TYPE_SPACE_LOCATION, &v};
        ASSERT_EQ(xrLocateSpace(spaces[i], base, fs.predictedDisplayTime, &l), XR_SUCCESS);
        EXPECT_EQ(data[i].locationFlags, l.locationFlags);
        EXPECT_EQ(std::memcmp(&data[i].pose, &l.pose, sizeof l.pose), 0) << "frame " << f << ", space " << i;
        EXPECT_EQ(velocity[i].velocityFlags, v.velocityFlags);
        EXPECT_EQ(std::memcmp(&velocity[i].linearVelocity, &v.linearVelocity, sizeof(XrVector3f)), 0);
        EXPECT_EQ(std::memcmp(&velocity[i].angularVelocity, &v.angularVelocity, sizeof(XrVector3f)), 0);
      }
    }
  }
  hs.destroy();
}

TEST(RuntimeLocateSpaces, RefusesWhatTheSpecificationRefuses) {
  use_runtime(5.0);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({XR_KHR_LOCATE_SPACES_EXTENSION_NAME}));
  auto locate_spaces = proc<PFN_xrLocateSpacesKHR>(hs.instance, "xrLocateSpacesKHR");
  ASSERT_NE(locate_spaces, nullptr);
  const XrPosef identity{{0, 0, 0, 1}, {0, 0, 0}};
  XrSpace spaces[3];
  for (XrSpace& s : spaces) s = reference(hs.session, XR_REFERENCE_SPACE_TYPE_VIEW, identity);
  ASSERT_NO_FATAL_FAILURE(hs.begin());
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(hs.session, nullptr, &fs), XR_SUCCESS);
  XrSpaceLocationDataKHR data[3];
  XrSpaceVelocityDataKHR velocity[3];
  XrSpaceVelocitiesKHR velocities{XR_TYPE_SPACE_VELOCITIES_KHR, nullptr, 3, velocity};
  XrSpaceLocationsKHR locations{XR_TYPE_SPACE_LOCATIONS_KHR, &velocities, 3, data};
  XrSpacesLocateInfoKHR info{XR_TYPE_SPACES_LOCATE_INFO_KHR, nullptr, spaces[0], fs.predictedDisplayTime, 3, spaces};
  ASSERT_EQ(locate_spaces(hs.session, &info, &locations), XR_SUCCESS);
  for (const XrSpaceVelocityDataKHR& v : velocity)  // identical spaces: known and zero
    EXPECT_EQ(v.velocityFlags, XR_SPACE_VELOCITY_LINEAR_VALID_BIT | XR_SPACE_VELOCITY_ANGULAR_VALID_BIT);

  spaces[2] = XR_NULL_HANDLE;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_HANDLE_INVALID);
  spaces[2] = spaces[1];
  info.baseSpace = XR_NULL_HANDLE;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_HANDLE_INVALID);
  info.baseSpace = spaces[0];
  EXPECT_EQ(locate_spaces(XR_NULL_HANDLE, &info, &locations), XR_ERROR_HANDLE_INVALID);
  info.time = 0;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_TIME_INVALID);
  info.time = -42;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_TIME_INVALID);
  info.time = fs.predictedDisplayTime;
  info.spaceCount = locations.locationCount = 0;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);
  info.spaceCount = 3;
  locations.locationCount = 2;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);
  locations.locationCount = 3;
  velocities.velocityCount = 2;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);
  velocities.velocityCount = 3;
  info.type = XR_TYPE_SPACE_LOCATION;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_ERROR_VALIDATION_FAILURE);
  info.type = XR_TYPE_SPACES_LOCATE_INFO_KHR;
  EXPECT_EQ(locate_spaces(hs.session, &info, &locations), XR_SUCCESS);

  hs.destroy();
}

TEST(RuntimeLocateSpaces, OnlyWithTheExtension) {
  use_runtime(0.5);
  HeadlessSession hs;
  ASSERT_NO_FATAL_FAILURE(hs.create({}));
  PFN_xrVoidFunction fn = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(hs.instance, "xrLocateSpacesKHR", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(xrGetInstanceProcAddr(hs.instance, "xrLocateSpaces", &fn), XR_ERROR_FUNCTION_UNSUPPORTED);  // 1.0
  hs.destroy();
}

}  // namespace
}  // namespace gazelod::xrrt_test
