// SPDX-License-Identifier: Apache-2.0
// The frame's cluster cut at scene scale: hundreds of instances of one baked hierarchy (a
// generated terrain tile of 1 M triangles, bake's cluster hierarchy, 64 m square) tiled on a
// grid around sim/scenarios/terrain-walk.json's path, the viewer taken from that scenario (true
// head and gaze, xi 20 cycles/deg) at 64 times spread over its 200 s, one per iteration in turn.
// Per case (`mode`), in the same process, the linear pass first:
//   0  today's linear pass: ClusterStore (every instance's records copied to world space),
//      select_clusters over its distinct records with drawn, limited_by and record bits (what
//      the plugin ran before);
//   1  the linear pass in each instance's space (select_clusters_local), the same outputs;
//   2  ClusterSelector (bounding hierarchy) on 1 thread, the cut as a list only;
//   3  the same with the three byte arrays written incrementally (what the plugin runs now);
//   4  the same writing every byte each frame;
//   5  mode 2 on 2 threads; 6  mode 3 on 2 threads.
// BM_LocalVsWorld (below) counts how often the local cut differs from the world-space one.
// BM_PluginClusterFrame (below): the plugin's whole cluster frame with the switch policy, over
// consecutive frames at 90 Hz.
// Counters: ms_per_frame = wall time, cpu_ms_per_frame = the calling thread's CPU time (on a
// shared machine the one-thread figure to trust; with 2 threads it leaves out the worker's);
// cpu_ns_per_drawn = that over the clusters in the cut; x_linear = CPU time over mode 0's at the
// same size; x_one = CPU time over mode 2's for ONE instance of the tile (clusters 1: the tile
// under the eye alone, moved along with the walk, the most expensive single instance of the
// grid); x_1thread_wall (modes 5, 6) = wall time over mode 2's (3's) at the same size, and
// all_threads_cpu_ms the CPU time of both threads per frame;
// drawn / evaluated / nodes = the cut, the clusters evaluated and the node records tested per
// frame (averages); store_MB = the records held (ClusterStore's arrays for mode 0, the shared
// hierarchy, its tree and the poses otherwise), x_one_MB = that over the same store holding one
// instance.
#include "lod/cluster/cluster_local_view.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/cluster/cluster_selector.hpp"
#include "lod/cluster/cluster_switch_policy.hpp"
#include "plugin/cluster_meshes.hpp"
#include "tests/lod/cluster_instance_scene.hpp"

#include <benchmark/benchmark.h>
#include <glm/gtc/quaternion.hpp>

#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace gazelod::lod {
namespace {

constexpr double kTileM = 64.0;
constexpr std::size_t kFrames = 64;

const ClusterHierarchy& tile() {
  static const ClusterHierarchy h = test::baked_terrain(1'000'000, kTileM, 8.0);
  return h;
}

const std::vector<Viewer>& walk() {
  static const std::vector<Viewer> frames = [] {
    sim::Simulator s(sim::load_scenario_file(std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/terrain-walk.json"));
    std::vector<Viewer> out;
    for (std::size_t f = 0; f < kFrames; ++f)
      out.push_back(test::scenario_viewer(s, s.duration_ns() / std::int64_t(kFrames) * std::int64_t(f), 20.0));
    return out;
  }();
  return frames;
}

// The instances: a square grid of tiles centred on the walk's middle (x 0, z 5), nearest first;
// every third tile turned by a multiple of 90 degrees (the tile is square about its origin).
std::vector<InstanceTransform> poses(std::size_t count) {
  const auto side = static_cast<int>(std::ceil(std::sqrt(double(count))));
  std::vector<std::pair<double, InstanceTransform>> all;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      InstanceTransform p;
      p.translation_m = {(i - side / 2) * kTileM, 0.0, (j - side / 2) * kTileM};
      if ((i + 2 * j) % 3 == 0)
        p.rotation = glm::angleAxis(0.5 * std::numbers::pi * (1 + (i + j) % 3), glm::dvec3{0, 1, 0});
      all.emplace_back(std::hypot(p.translation_m.x, p.translation_m.z - 5.0), p);
    }
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<InstanceTransform> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(all[k].second);
  return out;
}

std::size_t instances_for(std::size_t clusters) {
  return std::max<std::size_t>(1, clusters / tile().size());
}

struct Scene {
  ClusterInstances instances;
  std::unique_ptr<ClusterStore> store;  // with `world` only
  double store_bytes = 0.0, one_bytes = 0.0, world_bytes = 0.0, world_one_bytes = 0.0;
};

Scene& scene(std::size_t count, bool world) {
  static std::map<std::pair<std::size_t, bool>, std::unique_ptr<Scene>> cache;
  if (auto it = cache.find({count, world}); it != cache.end()) return *it->second;
  cache.clear();  // one scene at a time: the 10 M world store alone takes gigabytes
  auto s = std::make_unique<Scene>();
  const std::vector<InstanceTransform> ps = poses(count);
  const std::uint32_t h = s->instances.add_hierarchy(tile(), 1u << 30);
  for (const InstanceTransform& p : ps) s->instances.add_instance(h, p, glm::dvec3(0.0));
  ClusterInstances one;
  one.add_instance(one.add_hierarchy(tile(), 1u << 30), ps[0], glm::dvec3(0.0));
  s->store_bytes = double(s->instances.memory_bytes());
  s->one_bytes = double(one.memory_bytes());
  if (world) {
    s->store = std::make_unique<ClusterStore>();
    s->store->reserve(count, count * tile().size());
    for (const InstanceTransform& p : ps) s->store->add_mesh(tile(), p, glm::dvec3(0.0), 1u << 30);
    const ClusterSet v = s->store->view();
    for (std::span<const float> a :
         {v.self_center_x_m, v.self_center_y_m, v.self_center_z_m, v.self_radius_m, v.self_error_m, v.parent_center_x_m,
          v.parent_center_y_m, v.parent_center_z_m, v.parent_radius_m, v.parent_error_m, v.record_center_x_m,
          v.record_center_y_m, v.record_center_z_m, v.record_radius_m, v.record_error_m})
      s->world_bytes += double(a.size_bytes());
    s->world_bytes += double(v.self_record.size_bytes() + v.parent_record.size_bytes());
    s->world_one_bytes = s->world_bytes / double(count);
  }
  return *cache.emplace(std::make_pair(count, world), std::move(s)).first->second;
}

// Reference times, CPU ms of the calling thread per frame: mode 0's by instance count, mode 2's
// with one instance; and wall ms of modes 2 and 3 by (instance count, mode), for modes 5 and 6.
std::map<std::size_t, double>& linear_cpu_ms() {
  static std::map<std::size_t, double> m;
  return m;
}
double& one_instance_cpu_ms() {
  static double ms = 0.0;
  return ms;
}
std::map<std::pair<std::size_t, int>, double>& one_thread_ms() {
  static std::map<std::pair<std::size_t, int>, double> m;
  return m;
}

double cpu_ms(clockid_t clock) {  // CLOCK_THREAD_CPUTIME_ID: this thread; CLOCK_PROCESS_CPUTIME_ID: all
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

void BM_ClusterCut(benchmark::State& state) {
  const std::size_t count = instances_for(static_cast<std::size_t>(state.range(0)));
  const int mode = static_cast<int>(state.range(1));
  Scene& sc = scene(count, mode == 0);
  const std::size_t n = count * tile().size();
  test::CutBytes bytes(n);
  std::vector<std::uint32_t> flags(mode == 0 ? sc.store->record_count() : 0);
  ClusterSelector selector(mode >= 5 ? 2 : 1);
  const bool with_bytes = mode == 3 || mode == 4 || mode == 6;
  const std::vector<Viewer>& frames = walk();
  double drawn = 0.0, evaluated = 0.0, nodes = 0.0;
  std::size_t f = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = cpu_ms(CLOCK_THREAD_CPUTIME_ID), all0 = cpu_ms(CLOCK_PROCESS_CPUTIME_ID);
  for (auto _ : state) {
    const Viewer& v = frames[f++ % kFrames];
    if (count == 1) {  // the tile under the eye (a pose change costs nothing)
      InstanceTransform under;
      under.translation_m = {kTileM * std::round(v.eye_position_m.x / kTileM), 0.0,
                             kTileM * std::round(v.eye_position_m.z / kTileM)};
      sc.instances.set_pose(0, under, glm::dvec3(0.0));
    }
    std::string err;
    if (mode == 0) {
      err = select_clusters(v, sc.store->view(), {bytes.drawn, bytes.why, {}, {}, {}, bytes.bits, flags});
    } else if (mode == 1) {
      err = select_clusters_local(v, sc.instances, {bytes.drawn, bytes.why, {}, {}, {}, bytes.bits});
    } else {
      const ClusterCutBytes out =
          with_bytes ? ClusterCutBytes{bytes.drawn, bytes.why, bytes.bits, mode != 4} : ClusterCutBytes{};
      err = selector.select(v, sc.instances, out);
      drawn += double(selector.drawn().size());
      evaluated += double(selector.clusters_evaluated());
      nodes += double(selector.nodes_tested());
    }
    if (!err.empty()) state.SkipWithError(err.c_str());
    benchmark::ClobberMemory();
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
                    double(state.iterations());
  const double frames_run = double(state.iterations());
  const double cpu = (cpu_ms(CLOCK_THREAD_CPUTIME_ID) - cpu0) / frames_run;
  const double all = (cpu_ms(CLOCK_PROCESS_CPUTIME_ID) - all0) / frames_run;
  if (mode == 0) linear_cpu_ms()[count] = cpu;
  if (mode == 2 && count == 1) one_instance_cpu_ms() = cpu;
  if (mode == 2 || mode == 3) one_thread_ms()[{count, mode}] = ms;
  state.counters["clusters"] = double(n);
  state.counters["instances"] = double(count);
  state.counters["ms_per_frame"] = ms;
  state.counters["cpu_ms_per_frame"] = cpu;
  if (mode >= 5) state.counters["all_threads_cpu_ms"] = all;
  state.counters["store_MB"] = (mode == 0 ? sc.world_bytes : sc.store_bytes) / 1e6;
  state.counters["x_one_MB"] = mode == 0 ? sc.world_bytes / sc.world_one_bytes : sc.store_bytes / sc.one_bytes;
  if (mode >= 2) {
    state.counters["drawn"] = drawn / frames_run;
    state.counters["evaluated"] = evaluated / frames_run;
    state.counters["nodes"] = nodes / frames_run;
    state.counters["cpu_ns_per_drawn"] = cpu * 1e6 / std::max(1.0, drawn / frames_run);
  }
  if (mode < 5) {  // one thread: CPU time against CPU time
    if (auto it = linear_cpu_ms().find(count); it != linear_cpu_ms().end())
      state.counters["x_linear"] = cpu / it->second;
    if (one_instance_cpu_ms() > 0.0) state.counters["x_one"] = cpu / one_instance_cpu_ms();
  } else if (auto it = one_thread_ms().find({count, mode - 3}); it != one_thread_ms().end()) {
    state.counters["x_1thread_wall"] = ms / it->second;  // against mode 2 (5) or 3 (6)
  }
}

// How often the local-space cut (select_clusters_local) differs from today's world-space one
// (ClusterStore, select_clusters over distinct records) over a whole scenario walk, 1 M
// clusters, every `every`-th frame: record decisions (two per cluster and frame) where the local
// record is invisible and the world one not (local_coarser) or the reverse (local_finer), and
// clusters drawn differently. One iteration; its time is both passes over every frame.
void BM_LocalVsWorld(benchmark::State& state) {
  const char* const files[] = {"terrain-walk.json", "fast_turn.json", "default-120hz-50ms.json"};
  const std::string file = files[state.range(0)];
  const auto every = static_cast<std::size_t>(state.range(1));
  const std::size_t count = instances_for(1'000'000);
  Scene& sc = scene(count, true);
  sim::Simulator sim(sim::load_scenario_file(std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/" + file));
  const std::size_t n = sc.instances.size();
  test::CutBytes local(n), world(n);
  std::vector<std::uint32_t> flags(sc.store->record_count());
  test::Disagreement d;
  const double step_ns = 1e9 / sim.scenario().frame_rate_hz;
  for (auto _ : state)
    for (std::size_t f = 0; double(f) * step_ns < double(sim.duration_ns()); f += every) {
      const Viewer v = test::scenario_viewer(sim, static_cast<std::int64_t>(double(f) * step_ns), 20.0);
      std::string err = select_clusters_local(v, sc.instances, {local.drawn, local.why, {}, {}, {}, local.bits});
      if (err.empty())
        err = select_clusters(v, sc.store->view(), {world.drawn, world.why, {}, {}, {}, world.bits, flags});
      if (!err.empty()) state.SkipWithError(err.c_str());
      d.add(local, world);
    }
  state.counters["frames"] = double(d.frames);
  state.counters["decisions"] = double(d.decisions);
  state.counters["local_coarser"] = double(d.local_coarser);
  state.counters["local_finer"] = double(d.local_finer);
  state.counters["drawn_differ"] = double(d.drawn_differ);
}

// The plugin's cluster frame with the switch policy (its default) at 10 M clusters (399 tiles),
// over 180 consecutive frames at 90 Hz of the terrain walk from t = 60 s (a saccade every
// 23rd frame): mode 0, what the plugin ran before: the selector writing its bytes
// incrementally, then lod::apply_cluster_switch_policy over every cluster; mode 1,
// plugin::ClusterMeshes::update, which steps only the clusters whose bits may have changed
// and those still held back. Both with the plugin's kClusterThreads. Counters as
// BM_ClusterCut's; stepped = clusters the policy stepped per frame (mode 1); x_full = the CPU
// time of all threads over mode 0's.
void BM_PluginClusterFrame(benchmark::State& state) {
  constexpr std::size_t kRun = 180;
  static const std::vector<Viewer> frames = [] {
    sim::Simulator s(sim::load_scenario_file(std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/terrain-walk.json"));
    std::vector<Viewer> out;
    for (std::size_t f = 0; f < kRun; ++f)
      out.push_back(test::scenario_viewer(s, 60'000'000'000 + std::int64_t(f) * 11'111'111, 20.0));
    return out;
  }();
  static double full_cpu_ms = 0.0;
  const int mode = static_cast<int>(state.range(0));
  const std::vector<InstanceTransform> ps = poses(instances_for(10'000'000));
  ClusterInstances instances;
  plugin::ClusterMeshes meshes;
  const std::uint32_t h = instances.add_hierarchy(tile(), 1u << 30);
  for (const InstanceTransform& p : ps) {
    if (mode == 0) {
      (void)instances.add_instance(h, p, glm::dvec3(0.0));
      continue;
    }
    ClusterMeshDesc d;
    d.hierarchy = tile();
    d.index_count = 1u << 30;
    d.pose = p;
    (void)meshes.add(d);
  }
  const std::size_t n = mode == 0 ? instances.size() : meshes.cluster_count();
  test::CutBytes bytes(n);
  std::vector<std::uint8_t> record_held(n), drawn(n), held(n);
  std::vector<double> self_window(n, kNoSwitchWindow), parent_window(n, kNoSwitchWindow);
  const ClusterSwitchState policy_state{record_held, self_window, parent_window};
  ClusterSelector selector(plugin::kClusterThreads);  // the plugin's threads in both modes
  const SwitchPolicyConfig policy;
  std::size_t f = 0, stepped = 0;
  bool incremental = false;
  const double cpu0 = cpu_ms(CLOCK_THREAD_CPUTIME_ID), all0 = cpu_ms(CLOCK_PROCESS_CPUTIME_ID);
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    const Viewer& v = frames[f % kRun];
    const double t_s = double(f) / 90.0;  // the clock runs on over the repeats
    const bool suppressed = f % 23 < 3;
    if (mode == 0) {
      std::string err = selector.select(v, instances, {bytes.drawn, bytes.why, bytes.bits, incremental});
      incremental = err.empty();
      if (f == 0) std::copy(bytes.bits.begin(), bytes.bits.end(), record_held.begin());
      if (err.empty())
        err = apply_cluster_switch_policy(policy, t_s, suppressed, bytes.bits, policy_state, drawn, held);
      if (!err.empty()) state.SkipWithError(err.c_str());
    } else {
      meshes.update(v, &policy, t_s, suppressed);
      stepped += meshes.policy_clusters_stepped();
    }
    ++f;
    benchmark::ClobberMemory();
  }
  const double frames_run = double(state.iterations());
  const double cpu = (cpu_ms(CLOCK_THREAD_CPUTIME_ID) - cpu0) / frames_run;
  const double all = (cpu_ms(CLOCK_PROCESS_CPUTIME_ID) - all0) / frames_run;
  state.counters["clusters"] = double(n);
  state.counters["all_threads_cpu_ms"] = all;
  state.counters["ms_per_frame"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / frames_run;
  state.counters["cpu_ms_per_frame"] = cpu;
  if (mode == 0) full_cpu_ms = all;
  if (mode == 1) {
    state.counters["stepped"] = double(stepped) / frames_run;
    if (full_cpu_ms > 0.0) state.counters["x_full"] = all / full_cpu_ms;
  }
}

BENCHMARK(BM_PluginClusterFrame)->Arg(0)->Arg(1)->ArgNames({"mode"})->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK(BM_LocalVsWorld)
    ->Args({0, 3})
    ->Args({1, 1})
    ->Args({2, 1})
    ->ArgNames({"scenario", "every"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// One instance first (x_one's reference), then at each size the linear pass first (x_linear's).
void cut_cases(benchmark::internal::Benchmark* b) {
  b->Args({1, 2});
  for (std::int64_t clusters : {1'000'000, 10'000'000})
    for (std::int64_t mode = 0; mode <= 6; ++mode) b->Args({clusters, mode});
}

BENCHMARK(BM_ClusterCut)
    ->Apply(cut_cases)
    ->ArgNames({"clusters", "mode"})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gazelod::lod

BENCHMARK_MAIN();
