// SPDX-License-Identifier: Apache-2.0
// Shared by the C ABI's tests: a data-mode display, object grids and the last error as text.
#pragma once

#include "gazelod/gazelod.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace gazelod::test {

inline std::string last_error(gzl_plugin p) {
  char buf[1024];
  gzl_get_last_error(p, buf, sizeof buf, nullptr);
  return buf;
}

// A stereo display: 1800 x 1800 px per eye over 90 x 90 deg.
inline std::vector<gzl_view> stereo_views() {
  gzl_view v{};
  v.fov = {-M_PI / 4, M_PI / 4, M_PI / 4, -M_PI / 4};
  v.orientation_in_head = {0, 0, 0, 1};
  v.width_px = 1800;
  v.height_px = 1800;
  gzl_view l = v, r = v;
  l.position_in_head_m = {-0.032, 0, 0};
  r.position_in_head_m = {0.032, 0, 0};
  return {l, r};
}

inline gzl_plugin make_data_plugin(const gzl_config* config = nullptr) {
  const std::vector<gzl_view> views = stereo_views();
  gzl_data_create_info info{};
  info.type = GZL_TYPE_DATA_CREATE_INFO;
  info.view_count = 2;
  info.views = views.data();
  info.config = config;
  gzl_plugin p = nullptr;
  if (gzl_create_data(&info, &p) != GZL_SUCCESS) return nullptr;
  return p;
}

// Levels that remove detail of 0.5, 2 and 8 mm.
inline const gzl_level* four_levels() {
  static const gzl_level levels[4] = {{0, 4000}, {0.0005, 1000}, {0.002, 250}, {0.008, 60}};
  return levels;
}

inline gzl_object_desc object_at(double yaw_deg, double pitch_deg, double distance_m, double radius_m = 0.1) {
  const double y = yaw_deg * M_PI / 180, p = pitch_deg * M_PI / 180;
  gzl_object_desc d{};
  d.type = GZL_TYPE_OBJECT_DESC;
  d.center_m = {-std::sin(y) * std::cos(p) * distance_m, std::sin(p) * distance_m,
                -std::cos(y) * std::cos(p) * distance_m};
  d.radius_m = radius_m;
  d.metric = GZL_LEVEL_GEOMETRIC_ERROR_M;
  d.level_count = 4;
  d.levels = four_levels();
  return d;
}

inline gzl_gaze_sample gaze_at(int64_t t_ns, double yaw_deg) {
  gzl_gaze_sample s{};
  s.type = GZL_TYPE_GAZE_SAMPLE;
  s.time_ns = t_ns;
  const double y = yaw_deg * M_PI / 180;
  s.direction = {-std::sin(y), 0, -std::cos(y)};
  s.flags = GZL_GAZE_SAMPLE_VALID;
  return s;
}

inline gzl_frame_input still_head(int64_t t_ns) {
  gzl_frame_input in{};
  in.type = GZL_TYPE_FRAME_INPUT;
  in.display_time_ns = t_ns;
  in.head.orientation = {0, 0, 0, 1};
  in.head.flags = GZL_HEAD_POSE_VALID | GZL_HEAD_ANGULAR_VELOCITY_VALID | GZL_HEAD_LINEAR_VELOCITY_VALID;
  return in;
}

}  // namespace gazelod::test
