// SPDX-License-Identifier: Apache-2.0
// A C++17 application using gazelod through its header-only wrapper (<gazelod/gazelod.hpp>):
// RAII for the plugin, exceptions carrying gazelod's message, the C ABI underneath. Data mode,
// no OpenXR: a head held still, a gaze fixating one object of a row, pushed at 120 Hz.
//
// It also shows what gzl_config.disabled_criteria does: a second plugin with eccentricity
// switched off may not coarsen an object for being away from the gaze, so the row's far-off
// objects are drawn as finely as the fixated one (only their size and motion count).
//
// Exits 1 unless: with every criterion the fixated object is finer than the one 30 deg away;
// without eccentricity both are drawn alike; a bad call throws gazelod::Error with its code and a
// "gazelod:" message.
#include <gazelod/gazelod.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int64_t kFrameNs = 11'111'111;  // 90 Hz

gzl_view eye(double x_m) {
  gzl_view v{};
  v.fov = {-kPi / 4, kPi / 4, kPi / 4, -kPi / 4};  // 90 x 90 deg
  v.orientation_in_head = {0, 0, 0, 1};
  v.position_in_head_m = {x_m, 0, 0};
  v.width_px = v.height_px = 1800;
  return v;
}

// Levels 2 m away at yaw -30, 0 and +30 deg; errors of 0.5, 2 and 8 mm.
std::vector<gzl_object> add_row(gazelod::Plugin& p) {
  static const gzl_level levels[4] = {{0, 4000}, {0.0005, 1000}, {0.002, 250}, {0.008, 60}};
  std::vector<gzl_object> row;
  for (double yaw_deg : {-30.0, 0.0, 30.0}) {
    gzl_object_desc d{};
    d.type = GZL_TYPE_OBJECT_DESC;
    const double y = yaw_deg * kPi / 180;
    d.center_m = {-2.0 * std::sin(y), 0, -2.0 * std::cos(y)};
    d.radius_m = 0.1;
    d.metric = GZL_LEVEL_GEOMETRIC_ERROR_M;
    d.level_count = 4;
    d.levels = levels;
    row.push_back(p.add_object(d));
  }
  return row;
}

// One second of frames fixating straight ahead; the row's levels at the end.
std::vector<uint8_t> fixate_ahead(gazelod::Plugin& p, const std::vector<gzl_object>& row) {
  int64_t t = 0;
  for (int f = 0; f < 90; ++f) {
    t += kFrameNs;
    gzl_gaze_sample s{};
    s.type = GZL_TYPE_GAZE_SAMPLE;
    s.time_ns = t - 5'000'000;
    s.direction = {0, 0, -1};
    s.flags = GZL_GAZE_SAMPLE_VALID;
    p.push_gaze(s);
    gzl_frame_input in{};
    in.type = GZL_TYPE_FRAME_INPUT;
    in.display_time_ns = t;
    in.head.orientation = {0, 0, 0, 1};
    in.head.flags = GZL_HEAD_POSE_VALID | GZL_HEAD_ANGULAR_VELOCITY_VALID | GZL_HEAD_LINEAR_VELOCITY_VALID;
    p.begin_frame(in);
  }
  std::vector<uint8_t> levels(row.size());
  p.levels(static_cast<uint32_t>(row.size()), row.data(), levels.data());
  return levels;
}

gazelod::Plugin make(const gzl_config* config) {
  const gzl_view views[2] = {eye(-0.032), eye(0.032)};
  gzl_data_create_info info{};
  info.type = GZL_TYPE_DATA_CREATE_INFO;
  info.view_count = 2;
  info.views = views;
  info.config = config;
  return gazelod::Plugin::data(info);
}

}  // namespace

int main() {
  bool ok = true;
  try {
    gazelod::Plugin all = make(nullptr);
    const std::vector<gzl_object> row = add_row(all);
    const std::vector<uint8_t> a = fixate_ahead(all, row);
    std::printf("every criterion:      left L%d, ahead L%d, right L%d\n", a[0], a[1], a[2]);
    if (!(a[1] < a[0] && a[1] < a[2])) {
      std::printf("FAIL: the fixated object is not finer than the ones 30 deg away\n");
      ok = false;
    }

    gzl_config config{};
    config.type = GZL_TYPE_CONFIG;
    config.disabled_criteria = GZL_CRITERION_ECCENTRICITY;
    gazelod::Plugin no_ecc = make(&config);
    const std::vector<gzl_object> row2 = add_row(no_ecc);
    const std::vector<uint8_t> b = fixate_ahead(no_ecc, row2);
    std::printf("without eccentricity: left L%d, ahead L%d, right L%d\n", b[0], b[1], b[2]);
    if (!(b[0] == b[1] && b[1] == b[2] && b[1] == a[1])) {
      std::printf("FAIL: without eccentricity the row should be drawn like the fixated object\n");
      ok = false;
    }

    try {
      gzl_object_desc bad{};
      bad.type = GZL_TYPE_OBJECT_DESC;  // no levels
      all.add_object(bad);
      std::printf("FAIL: an object without levels was accepted\n");
      ok = false;
    } catch (const gazelod::Error& e) {
      std::printf("refused as expected: %s (%s)\n", e.what(), gzl_result_to_string(e.result()));
      if (std::string(e.what()).rfind("gazelod:", 0) != 0) ok = false;
    }
  } catch (const gazelod::Error& e) {
    std::printf("FAIL: %s (%s)\n", e.what(), gzl_result_to_string(e.result()));
    return 1;
  }
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
