// SPDX-License-Identifier: Apache-2.0
// Bake throughput in input triangles per second on generated icospheres (5120 to 81920
// triangles). Baseline in the same process: the bare meshopt_simplify call for one level at
// 1/4; then the default 4-level chain (simplify_chain: every level from the original, plus
// meshopt_optimizeVertexCache); then the whole in-memory bake (extraction, bounds, chain,
// MSFT_lod nodes and index buffers); then bake_file with .glb read and atomic write.
#include "bake/bake.hpp"
#include "bake/simplify_chain.hpp"
#include "tests/bake/test_meshes.hpp"

#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <string>

namespace gazelod::bake {
namespace {

void BM_MeshoptSimplifyOneLevel(benchmark::State& state) {
  const auto m = testing::icosphere(int(state.range(0)), 0.5);
  std::vector<unsigned> dst(m.indices.size());
  for (auto _ : state) {
    float err = 0.0f;
    benchmark::DoNotOptimize(meshopt_simplify(dst.data(), m.indices.data(), m.indices.size(), m.positions.data(),
                                              m.positions.size() / 3, 12, m.indices.size() / 4, 1.0f, 0, &err));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.triangles()));
}

void BM_SimplifyChain(benchmark::State& state) {
  const auto m = testing::icosphere(int(state.range(0)), 0.5);
  for (auto _ : state) benchmark::DoNotOptimize(simplify_chain(m.positions, m.indices, ChainOptions{}));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.triangles()));
}

void BM_BakeModel(benchmark::State& state) {
  const auto m = testing::icosphere(int(state.range(0)), 0.5);
  const tinygltf::Model model = testing::single_mesh_model(m);
  for (auto _ : state) {
    state.PauseTiming();
    tinygltf::Model copy = model;
    state.ResumeTiming();
    benchmark::DoNotOptimize(bake_model(copy, BakeOptions{}));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.triangles()));
}

void BM_BakeFile(benchmark::State& state) {
  const auto m = testing::icosphere(int(state.range(0)), 0.5);
  const std::string dir = testing::temp_dir("bench_" + std::to_string(state.range(0)));
  const std::string in = testing::write_model(testing::single_mesh_model(m), dir + "/in.glb");
  for (auto _ : state) benchmark::DoNotOptimize(bake_file(in, dir + "/out.glb", BakeOptions{}));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.triangles()));
}

BENCHMARK(BM_MeshoptSimplifyOneLevel)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SimplifyChain)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BakeModel)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BakeFile)->DenseRange(4, 6)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gazelod::bake

BENCHMARK_MAIN();
