// SPDX-License-Identifier: Apache-2.0
// Shared by the C ABI's tests over the fake OpenXR runtime (tests/plugin/fake_xr.hpp): the
// create info an engine fills from its own handles, a frame loop, and the last frame's outputs.
#pragma once

#include "tests/capi/capi_test_util.hpp"
#include "tests/plugin/fake_xr.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gazelod::test {

inline constexpr int64_t kXrFrameNs = 11'111'111;  // 90 Hz
inline constexpr int64_t kXrStartNs = 1'000'000'000;

// What an engine passes: its loader's xrGetInstanceProcAddr and its handles (the fake's).
inline gzl_openxr_create_info fake_openxr_info(gzl_gaze_input input, const gzl_config* config = nullptr) {
  const FakeXr& xr = FakeXr::get();
  gzl_openxr_create_info info{};
  info.type = GZL_TYPE_OPENXR_CREATE_INFO;
  info.get_instance_proc_addr = reinterpret_cast<gzl_void_function>(xr.get_instance_proc_addr());
  info.instance = GZL_XR_HANDLE(xr.instance());
  info.system_id = xr.system();
  info.session = GZL_XR_HANDLE(xr.session());
  info.base_space = GZL_XR_HANDLE(xr.local_space());
  info.gaze_input = input;
  if (input == GZL_GAZE_INPUT_APP_SPACE) {
    info.gaze_space = GZL_XR_HANDLE(xr.app_gaze_space());
    info.gaze_action = GZL_XR_HANDLE(xr.app_gaze_action());
  }
  info.config = config;
  return info;
}

// gzl_create_openxr on the fake; null (with the reason in the test's output) on failure.
inline gzl_plugin create_on_fake(gzl_gaze_input input, const gzl_config* config = nullptr) {
  const gzl_openxr_create_info info = fake_openxr_info(input, config);
  gzl_plugin p = nullptr;
  const gzl_result r = gzl_create_openxr(&info, &p);
  EXPECT_EQ(r, GZL_SUCCESS) << gzl_result_to_string(r) << ": " << last_error(nullptr);
  return p;
}

// `frames` frames after t (each must succeed); returns the last frame's display time.
inline int64_t run_xr_frames(gzl_plugin p, int64_t t, int frames) {
  for (int f = 0; f < frames; ++f) {
    t += kXrFrameNs;
    const gzl_result r = gzl_begin_frame_openxr(p, t);
    EXPECT_EQ(r, GZL_SUCCESS) << gzl_result_to_string(r) << ": " << last_error(p);
  }
  return t;
}

inline std::vector<uint8_t> levels_of(gzl_plugin p, const std::vector<gzl_object>& objects) {
  std::vector<uint8_t> out(objects.size(), 0xEE);
  EXPECT_EQ(gzl_get_levels(p, static_cast<uint32_t>(objects.size()), objects.data(), out.data()), GZL_SUCCESS);
  return out;
}

inline gzl_frame_info frame_info_of(gzl_plugin p) {
  gzl_frame_info info{};
  info.type = GZL_TYPE_FRAME_INFO;
  EXPECT_EQ(gzl_get_frame_info(p, &info), GZL_SUCCESS);
  return info;
}

inline std::string gaze_status_of(gzl_plugin p) {
  char buf[1024];
  EXPECT_EQ(gzl_get_gaze_status(p, buf, sizeof buf, nullptr), GZL_SUCCESS);
  return buf;
}

inline bool contains(const std::string& text, const char* part) {
  return text.find(part) != std::string::npos;
}

}  // namespace gazelod::test
