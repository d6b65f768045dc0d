// SPDX-License-Identifier: Apache-2.0
// Registration through the C ABI as a streaming world does it (libgazelod.so, data mode):
// gzl_remove_object + gzl_add_object pairs with many objects live, against the same pairs with
// few live (the baseline, same process), and gzl_get_frame_info and the resident memory after
// many pairs against before them. Each ratio should stay near 1: the handle tables follow the
// live count, not the handles ever issued (plugin/capi/capi_handles.hpp).
//
//   build/bench/capi/bench_capi_registration [pairs]   (default 200000)
#include "gazelod/gazelod.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

long rss_kib() {
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return resident * 4;
}

gzl_plugin make_plugin() {
  gzl_view v{};
  v.fov = {-0.8f, 0.8f, 0.8f, -0.8f};
  v.orientation_in_head = {0, 0, 0, 1};
  v.width_px = v.height_px = 2000;
  const gzl_view views[2] = {v, v};
  gzl_data_create_info info{};
  info.type = GZL_TYPE_DATA_CREATE_INFO;
  info.view_count = 2;
  info.views = views;
  gzl_plugin p = nullptr;
  if (gzl_create_data(&info, &p) != GZL_SUCCESS) std::exit(1);
  return p;
}

const gzl_level kLevels[4] = {{0, 4000}, {0.0005, 1000}, {0.002, 250}, {0.008, 60}};

gzl_object add(gzl_plugin p, int i) {
  gzl_object_desc d{};
  d.type = GZL_TYPE_OBJECT_DESC;
  d.center_m = {std::sin(i * 0.01) * 3.0, 0.0, -3.0};
  d.radius_m = 0.1;
  d.metric = GZL_LEVEL_GEOMETRIC_ERROR_M;
  d.level_count = 4;
  d.levels = kLevels;
  gzl_object h = GZL_NULL_OBJECT;
  if (gzl_add_object(p, &d, &h) != GZL_SUCCESS) std::exit(1);
  return h;
}

// Seconds per remove + add pair over `pairs` pairs with `live` objects live.
double churn(gzl_plugin p, std::vector<gzl_object>& live, long pairs) {
  const double t0 = now_s();
  for (long i = 0; i < pairs; ++i) {
    const std::size_t k = static_cast<std::size_t>(i * 7919) % live.size();
    if (gzl_remove_object(p, live[k]) != GZL_SUCCESS) std::exit(1);
    live[k] = add(p, static_cast<int>(i));
  }
  return (now_s() - t0) / static_cast<double>(pairs);
}

// One frame decided (so that gzl_get_frame_info has levels to sum), then the mean cost of
// gzl_get_frame_info.
double frame_info_s(gzl_plugin p, std::int64_t t_ns) {
  gzl_frame_input in{};
  in.type = GZL_TYPE_FRAME_INPUT;
  in.display_time_ns = t_ns;
  in.head.orientation = {0, 0, 0, 1};
  in.head.flags = GZL_HEAD_POSE_VALID;
  if (gzl_begin_frame_data(p, &in) != GZL_SUCCESS) std::exit(1);
  gzl_frame_info info{};
  info.type = GZL_TYPE_FRAME_INFO;
  const double t0 = now_s();
  for (int i = 0; i < 200; ++i)
    if (gzl_get_frame_info(p, &info) != GZL_SUCCESS) std::exit(1);
  return (now_s() - t0) / 200.0;
}

}  // namespace

int main(int argc, char** argv) {
  const long pairs = argc > 1 ? std::max(1000L, std::atol(argv[1])) : 200000L;
  // Baseline: 1 000 live objects.
  gzl_plugin few = make_plugin();
  std::vector<gzl_object> few_live;
  for (int i = 0; i < 1000; ++i) few_live.push_back(add(few, i));
  const double few_pair_s = churn(few, few_live, pairs / 4);
  gzl_destroy(few);
  // 100 000 live objects: registration, then churn.
  gzl_plugin p = make_plugin();
  std::vector<gzl_object> live;
  const double t0 = now_s();
  for (int i = 0; i < 100000; ++i) live.push_back(add(p, i));
  const double add_s = (now_s() - t0) / 100000.0;
  const double info_before = frame_info_s(p, 1'000'000'000);
  const long rss_before = rss_kib();
  const double many_pair_s = churn(p, live, pairs);
  const double info_after = frame_info_s(p, 2'000'000'000);
  const long rss_after = rss_kib();
  gzl_destroy(p);
  std::printf("gzl_add_object, 100 000 in a row: %.2f us each\n", add_s * 1e6);
  std::printf("remove + add pair: %.2f us with 100 000 live, %.2f us with 1 000 live: ratio %.2f\n", many_pair_s * 1e6,
              few_pair_s * 1e6, many_pair_s / few_pair_s);
  std::printf("gzl_get_frame_info, 100 000 live: %.1f us before %ld pairs, %.1f us after: ratio %.2f\n",
              info_before * 1e6, pairs, info_after * 1e6, info_after / info_before);
  std::printf("resident memory: %ld KiB before the pairs, %ld KiB after (%+.1f bytes per pair)\n", rss_before,
              rss_after, static_cast<double>(rss_after - rss_before) * 1024.0 / static_cast<double>(pairs));
  return 0;
}
