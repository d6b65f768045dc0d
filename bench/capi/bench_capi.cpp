// SPDX-License-Identifier: Apache-2.0
// The C ABI's per-frame cost against the C++ engine's, in one process on the same inputs: 10,000
// objects (four levels each, spread ahead of the viewer, one in eight moving), data mode, one
// pushed gaze sample per frame (fixations with a saccade every 300 ms), a turning head.
//   C path    gzl_push_gaze_sample + gzl_begin_frame_data + gzl_get_levels for every handle,
//             through libgazelod.so;
//   C++ path  plugin::LodCore::decide on the same plugin::FrameInput, with the same pushed gaze
//             source and head history as data mode, plus copying the levels out.
// The target: C / C++ <= 1.05, and no allocation per frame in the C path (the header's "the
// per-frame calls do not allocate"). Allocations are counted by this program's operator new
// over the timed loop, after warm-up frames. Before timing, both paths run the same frames and
// their levels are compared.
//   ./build/bench/capi/bench_capi --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
#include "gazelod/gazelod.h"
#include "plugin/head_motion.hpp"
#include "plugin/lod_core.hpp"
#include "plugin/plugin_config.hpp"
#include "plugin/pushed_gaze.hpp"

#include <benchmark/benchmark.h>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <new>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

// ---- allocation counting: every operator new of the process (libgazelod.so's included) ----
namespace {
std::atomic<std::uint64_t> g_allocs{0};

void* counted_alloc(std::size_t n) {
  g_allocs.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* counted_aligned(std::size_t n, std::align_val_t a) {
  g_allocs.fetch_add(1, std::memory_order_relaxed);
  const auto al = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(al, (n + al - 1) / al * al)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) {
  return counted_alloc(n);
}
void* operator new[](std::size_t n) {
  return counted_alloc(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t n, std::align_val_t a) {
  return counted_aligned(n, a);
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return counted_aligned(n, a);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}

namespace gazelod {
namespace {

constexpr std::size_t kObjects = 10'000;
constexpr std::int64_t kFrameNs = 11'111'111;  // 90 Hz
constexpr std::size_t kPattern = 4096;         // frames of head and gaze motion, then repeated
constexpr int kWarmupFrames = 200;

// ---- the scene: the same numbers for both paths --------------------------------------------

struct Scene {
  std::vector<gzl_object_desc> descs;
  std::vector<std::array<gzl_level, 4>> levels;
  std::array<gzl_view, 2> views{};
};

// Reddy 1998's random field (as bench/plugin): ahead of the viewer, four levels of
// 3928/834/254/76 triangles removing 16/4/1 cycles per diameter.
const Scene& scene() {
  static const Scene s = [] {
    Scene sc;
    sc.descs.resize(kObjects);
    sc.levels.resize(kObjects);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::uint32_t tris[4] = {3928, 834, 254, 76};
    for (std::size_t i = 0; i < kObjects; ++i) {
      for (int k = 0; k < 4; ++k) sc.levels[i][k] = {k == 0 ? 0.0 : 64.0 / (1 << (2 * k)), tris[k]};
      gzl_object_desc& d = sc.descs[i];
      d = gzl_object_desc{GZL_TYPE_OBJECT_DESC, nullptr};
      d.center_m = {u(rng) * 40.0, u(rng) * 5.0 + 1.6, -45.0 + u(rng) * 40.0};
      d.radius_m = 0.5;
      if (i % 8 == 0) d.velocity_m_s = {u(rng), 0.0, u(rng)};
      d.metric = GZL_LEVEL_REMOVED_CYCLES_PER_DIAMETER;
      d.level_count = 4;
      d.levels = sc.levels[i].data();
    }
    for (int e = 0; e < 2; ++e) {
      gzl_view& v = sc.views[e];
      v.fov = e == 0 ? gzl_fov{-0.942, 0.698, 0.785, -0.873} : gzl_fov{-0.698, 0.942, 0.785, -0.873};
      v.position_in_head_m = {e == 0 ? -0.032 : 0.032, 0.0, 0.0};
      v.width_px = 1800;
      v.height_px = 1920;
    }
    return sc;
  }();
  return s;
}

// Frame i's head (yawing +-0.3 rad at 0.25 Hz, bobbing a little) and gaze sample (in head space,
// 5 ms before the display time; fixations jittered by the tracker's noise, a saccade to a new
// target every 27 frames).
struct Motion {
  double yaw, pitch;
  glm::dvec3 position;
  glm::dvec3 gaze_head;
};

const std::vector<Motion>& pattern() {
  static const std::vector<Motion> p = [] {
    std::vector<Motion> m(kPattern);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> target(-0.35, 0.35);
    std::normal_distribution<double> noise(0.0, 0.003);
    double tx = 0.0, ty = 0.0;
    for (std::size_t i = 0; i < kPattern; ++i) {
      const double t = static_cast<double>(i) * 1.0 / 90.0;
      if (i % 27 == 0) tx = target(rng), ty = 0.5 * target(rng);
      m[i].yaw = 0.3 * std::sin(2.0 * 3.141592653589793 * 0.25 * t);
      m[i].pitch = 0.05 * std::sin(2.0 * 3.141592653589793 * 0.4 * t);
      m[i].position = {0.02 * std::sin(t), 1.6 + 0.01 * std::sin(3.0 * t), 0.0};
      m[i].gaze_head = glm::normalize(glm::dvec3(std::tan(tx + noise(rng)), std::tan(ty + noise(rng)), -1.0));
    }
    return m;
  }();
  return p;
}

glm::dquat head_orientation(const Motion& m) {
  return glm::angleAxis(m.yaw, glm::dvec3(0.0, 1.0, 0.0)) * glm::angleAxis(m.pitch, glm::dvec3(1.0, 0.0, 0.0));
}

std::int64_t frame_time(std::uint64_t frame) {
  return 1'000'000'000 + static_cast<std::int64_t>(frame) * kFrameNs;
}
constexpr std::int64_t kSampleLeadNs = 5'000'000;

// ---- the C path -------------------------------------------------------------------------------

void need(gzl_result r, const char* what) {
  if (r == GZL_SUCCESS) return;
  char msg[512];
  gzl_get_last_error(nullptr, msg, sizeof msg, nullptr);
  std::fprintf(stderr, "bench_capi: %s: %s (%s)\n", what, gzl_result_to_string(r), msg);
  std::exit(1);
}

struct CPath {
  gzl_plugin p = nullptr;
  std::vector<gzl_object> handles;
  std::vector<std::uint8_t> levels;
  std::uint64_t frame = 0;

  CPath() {
    const Scene& s = scene();
    gzl_data_create_info info{GZL_TYPE_DATA_CREATE_INFO, nullptr};
    info.view_count = 2;
    info.views = s.views.data();
    need(gzl_create_data(&info, &p), "gzl_create_data");
    handles.resize(kObjects);
    levels.resize(kObjects);
    for (std::size_t i = 0; i < kObjects; ++i) need(gzl_add_object(p, &s.descs[i], &handles[i]), "gzl_add_object");
  }
  ~CPath() { gzl_destroy(p); }
  CPath(const CPath&) = delete;
  CPath& operator=(const CPath&) = delete;

  void step() {
    const Motion& m = pattern()[frame % kPattern];
    const std::int64_t t = frame_time(frame);
    gzl_gaze_sample s{GZL_TYPE_GAZE_SAMPLE, nullptr};
    s.time_ns = t - kSampleLeadNs;
    s.direction = {m.gaze_head.x, m.gaze_head.y, m.gaze_head.z};
    s.flags = GZL_GAZE_SAMPLE_VALID;
    need(gzl_push_gaze_sample(p, &s), "gzl_push_gaze_sample");
    gzl_frame_input in{GZL_TYPE_FRAME_INPUT, nullptr};
    in.display_time_ns = t;
    const glm::dquat q = head_orientation(m);
    in.head.orientation = {q.x, q.y, q.z, q.w};
    in.head.position_m = {m.position.x, m.position.y, m.position.z};
    in.head.flags = GZL_HEAD_POSE_VALID;
    need(gzl_begin_frame_data(p, &in), "gzl_begin_frame_data");
    need(gzl_get_levels(p, static_cast<std::uint32_t>(kObjects), handles.data(), levels.data()), "gzl_get_levels");
    ++frame;
  }
};

// ---- the C++ path: the engine with data mode's gaze source and head history -------------------

struct CppPath {
  PluginConfig config;
  plugin::LodCore core{config};
  plugin::HeadHistory heads;
  plugin::PushedGazeSource pushed{heads, static_cast<std::int64_t>(config.max_pushed_sample_age_s * 1e9)};
  plugin::HeadTracker head;
  plugin::FrameInput in;
  std::vector<std::uint8_t> levels;
  std::string why;
  std::uint64_t frame = 0;

  CppPath() {
    core.set_primary(&pushed, GazeSourceKind::pushed, "");
    core.set_orientation_at([this](std::int64_t t_ns) -> std::optional<glm::dquat> {
      if (auto q = pushed.head_at_last_sample()) return q;
      return heads.at(t_ns);
    });
    const Scene& s = scene();
    for (const gzl_object_desc& d : s.descs) {
      ObjectDesc o;
      o.center_m = {d.center_m.x, d.center_m.y, d.center_m.z};
      o.radius_m = d.radius_m;
      o.velocity_m_s = {d.velocity_m_s.x, d.velocity_m_s.y, d.velocity_m_s.z};
      for (std::uint32_t k = 0; k < d.level_count; ++k)
        o.lods.push_back(
            {d.levels[k].triangles, 0, lod::DetailKind::removed_cycles_per_diameter, k == 0 ? 0.0 : d.levels[k].value});
      core.add_object(o);
    }
    in.view_count = 2;
    for (int e = 0; e < 2; ++e) {
      const gzl_view& v = s.views[e];
      plugin::ViewInput& vi = in.views[e];
      vi.fov = {v.fov.angle_left, v.fov.angle_right, v.fov.angle_up, v.fov.angle_down};
      vi.position_in_head_m = {v.position_in_head_m.x, v.position_in_head_m.y, v.position_in_head_m.z};
      vi.width_px = static_cast<int>(v.width_px);
      vi.height_px = static_cast<int>(v.height_px);
    }
    levels.resize(kObjects);
  }

  void step() {
    const Motion& m = pattern()[frame % kPattern];
    const std::int64_t t = frame_time(frame);
    plugin::PushedSample s;
    s.sample.t_ns = t - kSampleLeadNs;
    s.sample.direction = m.gaze_head;
    s.sample.valid = true;
    s.sample.confidence = 1.0f;
    if (pushed.push(s, why) != plugin::PushResult::ok) std::abort();
    plugin::HeadMotion given;
    given.valid = true;
    given.orientation = head_orientation(m);
    given.position_m = m.position;
    in.t_ns = t;
    in.head = head.from_pose(t, given, false, false);
    heads.push(t, in.head.orientation);
    pushed.frame_time(t);
    const FrameDecisions& d = core.decide(in);  // the views every frame, as data mode passes them
    for (std::size_t i = 0; i < kObjects; ++i) levels[i] = d.lod[i];
    ++frame;
  }
};

// ---- the benchmarks ---------------------------------------------------------------------------

template <typename Path>
void run(benchmark::State& state, const char* label) {
  Path path;
  for (int i = 0; i < kWarmupFrames; ++i) path.step();
  const std::uint64_t allocs0 = g_allocs.load();
  for (auto _ : state) {
    path.step();
    benchmark::DoNotOptimize(path.levels.data());
    benchmark::ClobberMemory();
  }
  const std::uint64_t allocs = g_allocs.load() - allocs0;
  std::size_t reduced = 0;
  for (std::uint8_t l : path.levels) reduced += l > 0;
  state.counters["allocs_per_frame"] = benchmark::Counter(
      static_cast<double>(allocs) / static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1)));
  state.counters["reduced_pct"] = 100.0 * static_cast<double>(reduced) / static_cast<double>(kObjects);
  state.SetLabel(label);
}

void BM_CapiFrame(benchmark::State& state) {
  run<CPath>(state, "C ABI: push + begin_frame_data + get_levels");
}
void BM_CppFrame(benchmark::State& state) {
  run<CppPath>(state, "C++: LodCore::decide + copy levels");
}

BENCHMARK(BM_CapiFrame)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CppFrame)->Unit(benchmark::kMicrosecond);

// Both paths on the same frames: the levels must be the same (else the ratio compares different
// work). Returns the number of frames whose levels differed.
int compare_paths(int frames) {
  const std::uint64_t allocs0 = g_allocs.load();
  CPath c;
  // The counter sees libgazelod.so's allocations too (its operator new is this program's).
  std::printf("operator new calls while libgazelod.so created the plugin and added %zu objects: %llu\n", kObjects,
              static_cast<unsigned long long>(g_allocs.load() - allocs0));
  CppPath cpp;
  int differing = 0;
  for (int f = 0; f < frames; ++f) {
    c.step();
    cpp.step();
    if (c.levels != cpp.levels) ++differing;
  }
  std::size_t reduced = 0;
  for (std::uint8_t l : c.levels) reduced += l > 0;
  std::printf("same inputs, %d frames: levels differ in %d frames (C path: %zu of %zu objects reduced at the last)\n",
              frames, differing, reduced, kObjects);
  return differing;
}

// The console table, then C / C++ from the medians (or the single runs) of this run.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  explicit RatioReporter(bool color) : ConsoleReporter(color ? OO_Defaults : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const std::string key =
          r.run_name.function_name + (r.run_type == Run::RT_Aggregate ? "/" + r.aggregate_name : "");
      if (r.run_type == Run::RT_Iteration) {
        auto& v = single_[r.run_name.function_name];
        v.push_back({r.GetAdjustedRealTime(), r.GetAdjustedCPUTime()});
      } else {
        agg_[key] = {r.GetAdjustedRealTime(), r.GetAdjustedCPUTime()};
      }
      if (auto it = r.counters.find("allocs_per_frame"); it != r.counters.end() && r.run_type == Run::RT_Iteration)
        allocs_[r.run_name.function_name] = std::max(allocs_[r.run_name.function_name], it->second.value);
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    auto times = [&](const std::string& fn) -> std::pair<double, double> {
      if (auto it = agg_.find(fn + "/median"); it != agg_.end()) return it->second;
      if (auto it = single_.find(fn); it != single_.end() && !it->second.empty()) return it->second.back();
      return {0.0, 0.0};
    };
    const auto c = times("BM_CapiFrame"), cpp = times("BM_CppFrame");
    if (!(cpp.first > 0.0) || !(cpp.second > 0.0)) return;
    std::printf("C ABI / C++ engine per frame (%zu objects): real %.3f (%.1f / %.1f us), cpu %.3f (%.1f / %.1f us)%s\n",
                kObjects, c.first / cpp.first, c.first, cpp.first, c.second / cpp.second, c.second, cpp.second,
                agg_.count("BM_CapiFrame/median") ? " [medians]" : "");
    for (const auto& [fn, a] : allocs_)
      std::printf("%s: at most %.3f allocations per frame (timed loop, after warm-up)\n", fn.c_str(), a);
  }

 private:
  std::map<std::string, std::pair<double, double>> agg_;
  std::map<std::string, std::vector<std::pair<double, double>>> single_;
  std::map<std::string, double> allocs_;
};

}  // namespace
}  // namespace gazelod

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const int differing = gazelod::compare_paths(300);
  gazelod::RatioReporter reporter(::isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return differing == 0 ? 0 : 1;
}
