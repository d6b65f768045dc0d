// SPDX-License-Identifier: Apache-2.0
// Plugin per-frame cost for 10k objects (the target: begin_frame at most 0.5 ms on one
// core), over gazelod's simulated OpenXR runtime, unpaced. The same process also times the
// bare selection (lod::select_lods) on the same objects, so the ratio shows what the OpenXR
// side (gaze action, xrLocateSpace, xrLocateViews) adds.
//   ./build/bench/plugin/bench_plugin
#include "lod/object_set.hpp"
#include "lod/select.hpp"
#include "apps/xr_host/xr_app.hpp"
#include "plugin/lod_plugin.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <cstdlib>
#include <memory>
#include <random>
#include <vector>

namespace gazelod {
namespace {

struct Field {
  std::vector<ObjectDesc> objects;
};

// Reddy 1998's random field: objects ahead of the viewer, four LODs of 3928/834/254/76 triangles.
Field make_field(std::size_t n) {
  Field f;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::uint32_t tris[4] = {3928, 834, 254, 76};
  for (std::size_t i = 0; i < n; ++i) {
    ObjectDesc d;
    d.center_m = {u(rng) * 40.0, u(rng) * 5.0 + 1.6, -45.0 + u(rng) * 40.0};
    d.radius_m = 0.5;
    if (i % 8 == 0) d.velocity_m_s = {u(rng), 0.0, u(rng)};
    for (int k = 0; k < 4; ++k)
      d.lods.push_back({tris[k], tris[k] / 2 + 2, lod::DetailKind::removed_cycles_per_diameter,
                        k == 0 ? 0.0 : 64.0 / (1 << (2 * k))});
    f.objects.push_back(std::move(d));
  }
  return f;
}

struct Session {
  std::unique_ptr<xr_host::XrApp> app;
  std::unique_ptr<LodPlugin> plugin;
};

Session& session(std::size_t n, bool breakdown) {
  static std::unique_ptr<Session> s;
  static std::size_t made_n = 0;
  static bool made_breakdown = false;
  if (s && made_n == n && made_breakdown == breakdown) return *s;
  s.reset();
  ::setenv("XR_RUNTIME_JSON", GAZELOD_XR_RUNTIME_JSON, 0);
  ::setenv("GAZELOD_SIM_PACED", "0", 1);
  ::setenv("GAZELOD_SIM_DURATION_S", "100000", 1);
  s = std::make_unique<Session>();
  s->app = std::make_unique<xr_host::XrApp>(true);
  PluginConfig cfg;
  cfg.compute_breakdown = breakdown;
  s->plugin = LodPlugin::create(xrGetInstanceProcAddr, s->app->instance(), s->app->system(), s->app->session(),
                                s->app->local_space(), cfg);
  for (const ObjectDesc& d : make_field(n).objects) s->plugin->add_object(d);
  // Run until the session is focused and frames flow.
  for (int i = 0; i < 1000 && !s->app->session_running(); ++i)
    s->app->poll_events([&](XrSessionState st, XrTime t) { s->plugin->on_session_state(st, t); });
  made_n = n;
  made_breakdown = breakdown;
  return *s;
}

void BM_PluginBeginFrame(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Session& s = session(n, state.range(1) != 0);
  std::size_t reduced = 0;
  for (auto _ : state) {
    s.app->poll_events([&](XrSessionState st, XrTime t) { s.plugin->on_session_state(st, t); });
    const XrFrameState fs = s.app->wait_frame();
    s.app->begin_frame();
    const auto t0 = std::chrono::steady_clock::now();
    const FrameDecisions& d = s.plugin->begin_frame(fs.predictedDisplayTime);
    const auto t1 = std::chrono::steady_clock::now();
    state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
    reduced = 0;
    for (std::uint8_t l : d.lod) reduced += l > 0;
    s.app->end_frame(fs.predictedDisplayTime, {});
    s.plugin->end_frame(1.0);
  }
  state.counters["objects_reduced_pct"] = 100.0 * static_cast<double>(reduced) / static_cast<double>(n);
  state.SetLabel(state.range(1) ? "begin_frame + breakdown (3 selections)" : "begin_frame");
}

void BM_BareSelection(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  lod::ObjectStore store;
  for (const ObjectDesc& d : make_field(n).objects) store.add(d.center_m, d.radius_m, d.velocity_m_s, d.lods);
  std::vector<std::uint8_t> a(n), b(n), c(n), e(n), f(n);
  lod::Viewer v;
  v.eye_position_m = {0.0, 1.6, 0.0};
  v.gaze_direction = {0.0, 0.0, -1.0};
  v.xi_cpd = 12.0;
  for (auto _ : state) {
    auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(lod::select_lods(v, store.view(), lod::Decisions{a, b, c, e, f, {}, {}, {}}));
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  state.SetLabel("lod::select_lods alone");
}

BENCHMARK(BM_BareSelection)->Arg(10000)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PluginBeginFrame)->Args({10000, 0})->Args({10000, 1})->UseManualTime()->Unit(benchmark::kMicrosecond);

// The console table, then begin_frame's time over the bare selection's, from this run.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) us_[r.benchmark_name()] = r.GetAdjustedRealTime();
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto bare = us_.find("BM_BareSelection/10000/manual_time");
    if (bare == us_.end() || !(bare->second > 0.0)) return;
    for (const char* name : {"BM_PluginBeginFrame/10000/0/manual_time", "BM_PluginBeginFrame/10000/1/manual_time"})
      if (auto it = us_.find(name); it != us_.end())
        std::printf("%s / lod::select_lods alone: %.2f\n", name, it->second / bare->second);
  }

 private:
  std::map<std::string, double> us_;
};

}  // namespace
}  // namespace gazelod

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  gazelod::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
