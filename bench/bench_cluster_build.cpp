// SPDX-License-Identifier: Apache-2.0
// Cluster hierarchy build (bake/cluster/cluster_build.hpp) throughput in input triangles per second on
// a generated terrain of 1,002,528 triangles (708 x 708 quads over 100 m, four octaves of
// sines up to 4 m). Baseline in the same process, registered first: one meshopt_simplify of the
// whole mesh to half its triangles. Counters: triangles_per_s = input triangles / wall time;
// x_simplify = the build's wall time over the baseline's (how many whole-mesh halvings the
// hierarchy costs); digest = an FNV-1a hash of the hierarchy's indices and errors (48 bits), the
// same for any thread count and across a change that must not alter the output; *_ms = wall
// milliseconds per phase of the last iteration (ClusterBuildResult::Phases); folded = the
// folds left (ClusterBuildResult::folded_triangles). The build runs with 1 thread and with all
// cores (threads 0), and with all cores without fold retries (fold_retries 0: their cost).
#include "bake/cluster/cluster_build.hpp"
#include "tests/bake/test_meshes.hpp"

#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <bit>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <numbers>

namespace gazelod::bake {
namespace {

constexpr int kQuads = 708;

const testing::TestMesh& terrain() {
  static const testing::TestMesh m = [] {
    testing::TestMesh t = testing::grid(kQuads, 100.0, 0.0);
    const double k = 2.0 * std::numbers::pi / 100.0;
    for (std::size_t i = 0; i < t.positions.size(); i += 3) {
      const double x = t.positions[i], y = t.positions[i + 1];
      double z = 0.0;
      for (int o = 0; o < 4; ++o) {
        const double f = k * std::pow(3.0, o);
        z += 4.0 / std::pow(2.5, o) * std::sin(f * x + o) * std::cos(f * y * 1.3 + 2 * o);
      }
      t.positions[i + 2] = static_cast<float>(z);
    }
    return t;
  }();
  return m;
}

double& baseline_s() {  // seconds per meshopt_simplify to half, set by the baseline
  static double s = 0.0;
  return s;
}

// FNV-1a over the indices and the self and parent errors' bits, folded to 48 bits (exact in a
// double counter).
double digest(const ClusterBuildResult& r) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](std::uint32_t x) {
    for (int b = 0; b < 4; ++b) h = (h ^ ((x >> (8 * b)) & 0xffu)) * 1099511628211ull;
  };
  for (std::uint32_t i : r.indices) mix(i);
  for (std::size_t c = 0; c < r.hierarchy.size(); ++c) {
    mix(std::bit_cast<std::uint32_t>(r.hierarchy.self_error_m[c]));
    mix(std::bit_cast<std::uint32_t>(r.hierarchy.parent_error_m[c]));
  }
  return static_cast<double>((h ^ (h >> 48)) & ((std::uint64_t{1} << 48) - 1));
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void report(benchmark::State& state, double wall_s) {
  const double per_iteration_s = wall_s / static_cast<double>(state.iterations());
  const double tris = static_cast<double>(terrain().triangles());
  state.counters["triangles_per_s"] = per_iteration_s > 0.0 ? tris / per_iteration_s : 0.0;
  if (baseline_s() > 0.0) state.counters["x_simplify"] = per_iteration_s / baseline_s();
}

void BM_MeshoptSimplifyHalf(benchmark::State& state) {
  const testing::TestMesh& m = terrain();
  std::vector<unsigned> dst(m.indices.size());
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    float err = 0.0f;
    benchmark::DoNotOptimize(meshopt_simplify(dst.data(), m.indices.data(), m.indices.size(), m.positions.data(),
                                              m.positions.size() / 3, 12, m.indices.size() / 2, 1.0f, 0, &err));
  }
  const double wall_s = seconds_since(t0);
  baseline_s() = wall_s / static_cast<double>(state.iterations());
  report(state, wall_s);
}

void BM_ClusterBuild(benchmark::State& state) {
  const testing::TestMesh& m = terrain();
  ClusterBuildOptions o;
  o.threads = static_cast<unsigned>(state.range(0));
  o.fold_retries = static_cast<unsigned>(state.range(1));
  ClusterBuildResult r;  // the last iteration's, looked at after the timing
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    r = build_cluster_hierarchy(m.positions, m.indices, o);
    benchmark::DoNotOptimize(r.indices.data());
  }
  report(state, seconds_since(t0));
  state.counters["clusters"] = static_cast<double>(r.hierarchy.size());
  state.counters["levels"] = static_cast<double>(r.levels);
  state.counters["folded"] = static_cast<double>(r.folded_triangles);
  state.counters["digest"] = digest(r);
  const ClusterBuildResult::Phases& phases = r.phases;
  // Milliseconds per phase, the last iteration's.
  state.counters["weld_ms"] = 1e3 * phases.weld_s;
  state.counters["source_ms"] = 1e3 * phases.source_clusters_s;
  state.counters["grouping_ms"] = 1e3 * phases.grouping_s;
  state.counters["shared_ms"] = 1e3 * phases.shared_s;
  state.counters["groups_ms"] = 1e3 * phases.groups_s;
  state.counters["sliced_ms"] = 1e3 * phases.sliced_measure_s;
}

BENCHMARK(BM_MeshoptSimplifyHalf)->Unit(benchmark::kMillisecond)->UseRealTime();
// Args: threads (0: all cores), fold retries (the default 2, and 0: what they cost).
BENCHMARK(BM_ClusterBuild)
    ->ArgNames({"threads", "fold_retries"})
    ->Args({1, 2})
    ->Args({0, 2})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace gazelod::bake

BENCHMARK_MAIN();
