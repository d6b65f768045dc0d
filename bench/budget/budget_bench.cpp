// What accuracy costs in time (issue 6): every solver on scenes of 100 to 100k objects with 4
// to 8 levels each, solve time per frame and the gap to the exact optimum (100 objects) or the
// LP upper bound (larger); and Mason's incremental solver under frame-to-frame coherence (every
// object's benefit drifts by ~1 % per frame), against the same scene solved from scratch.
// Scenes: cost = F&S max(C1 tris + C2 verts, C3 pixels) in ms, benefit = pixels x F&S accuracy.
#include "lod/benefit.hpp"
#include "lod/cost_model.hpp"
#include "lod/knapsack.hpp"
#include "lod/knapsack_incremental.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace gazelod::lod {
namespace {

struct Scene {
  MckpInstance inst;
  std::vector<double> size_px;  // per object, drifts per frame
  std::vector<std::uint32_t> tris;  // per item
};

const CostCoefficients kCoeff{0.0, 2e-6, 1e-6, 2e-7};  // ms per triangle / vertex / pixel

void set_profits(Scene& s) {
  for (std::size_t k = 0; k < s.inst.subset_count(); ++k)
    for (std::uint32_t j = s.inst.subset_offsets[k]; j < s.inst.subset_offsets[k + 1]; ++j)
      s.inst.items[j].profit = s.size_px[k] * fs_accuracy(s.tris[j], s.size_px[k], 1.0, 0.5);
}

Scene make_scene(std::size_t objects, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> levels(4, 8);
  std::lognormal_distribution<double> top_tris(std::log(20000.0), 1.0), px(std::log(5000.0), 1.2);
  Scene s;
  double lo = 0, hi = 0;
  std::vector<MckpItem> items;
  for (std::size_t k = 0; k < objects; ++k) {
    const int m = levels(rng);
    const double top = top_tris(rng);
    s.size_px.push_back(px(rng));
    items.clear();
    for (int j = 0; j < m; ++j) {  // coarse to fine, triangles halving per level
      const double t = std::max(8.0, std::round(top / std::pow(2.0, m - 1 - j)));
      s.tris.push_back(static_cast<std::uint32_t>(t));
      items.push_back({0.0, object_cost_s(kCoeff, t, 0.6 * t, s.size_px.back())});
    }
    lo += items.front().cost;
    hi += items.back().cost;
    s.inst.add_subset(items);
  }
  s.inst.capacity = lo + 0.5 * (hi - lo);
  set_profits(s);
  return s;
}

void drift(Scene& s, std::mt19937& rng, double sigma) {
  std::normal_distribution<double> z(0.0, sigma);
  for (double& p : s.size_px) p *= std::exp(z(rng));
  set_profits(s);
}

// Gap in percent to the best reference available: the proven optimum for small scenes, the LP
// relaxation (an upper bound) otherwise.
double gap_pct(const MckpInstance& inst, double profit, bool* exact_ref) {
  double ref = 0.0;
  *exact_ref = false;
  if (inst.subset_count() <= 100) {
    const MckpSolution opt = solve_exact(inst);
    if (opt.proven_optimal) {
      ref = opt.profit;
      *exact_ref = true;
    }
  }
  if (!*exact_ref) ref = lp_upper_bound(inst);
  return ref > 0 ? 100.0 * (ref - profit) / ref : 0.0;
}

void BM_Solve(benchmark::State& state) {
  const auto kind = static_cast<SolverKind>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  const Scene scene = make_scene(n, 42);
  MckpSolution sol;
  for (auto _ : state) {
    sol = solve(kind, scene.inst);
    benchmark::DoNotOptimize(sol.profit);
  }
  bool exact_ref = false;
  state.counters["gap_pct"] = sol.feasible ? gap_pct(scene.inst, sol.profit, &exact_ref) : NAN;
  state.counters["ref_exact"] = exact_ref;
  state.counters["feasible"] = sol.feasible;
  state.SetLabel(std::string(solver_name(kind)));
}

// Mason's incremental solver, frame after frame, from the previous frame's answer.
void BM_IncrementalCoherent(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Scene scene = make_scene(n, 42);
  std::mt19937 rng(7);
  IncrementalScheduler sched;
  sched.reset(scene.inst);
  MckpSolution prev, cur;
  sched.step(scene.inst, {}, {}, std::chrono::seconds(10), prev);  // converge once
  double moves = 0, frames = 0, truncated = 0;
  for (auto _ : state) {
    state.PauseTiming();
    drift(scene, rng, 0.01);
    state.ResumeTiming();
    sched.step(scene.inst, prev.choice, {}, std::chrono::milliseconds(5), cur);
    state.PauseTiming();
    moves += static_cast<double>(cur.iterations);
    truncated += cur.truncated;
    frames += 1;
    std::swap(prev, cur);
    state.ResumeTiming();
  }
  bool exact_ref = false;
  state.counters["gap_pct"] = gap_pct(scene.inst, prev.profit, &exact_ref);
  state.counters["ref_exact"] = exact_ref;
  state.counters["moves_per_frame"] = moves / std::max(frames, 1.0);
  state.counters["truncated_frames"] = truncated;
  // Baseline in the same process: Mason's greedy from scratch on this frame's scene.
  const auto t0 = std::chrono::steady_clock::now();
  const MckpSolution scratch = solve_mason_greedy(scene.inst);
  const double scratch_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  state.counters["scratch_greedy_ms"] = scratch_ms;
  state.counters["scratch_gap_pct"] = gap_pct(scene.inst, scratch.profit, &exact_ref);
  state.SetLabel("mason-incremental, coherent frames");
}

void solve_args(benchmark::internal::Benchmark* b) {
  for (std::string_view name : solver_names()) {
    const auto kind = static_cast<int64_t>(*solver_from_name(name));
    for (int64_t n : {100, 1000, 10000, 100000}) {
      if (*solver_from_name(name) == SolverKind::exact && n > 100) continue;  // exponential
      b->Args({kind, n});
    }
  }
}

BENCHMARK(BM_Solve)->Apply(solve_args)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IncrementalCoherent)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gazelod::lod

BENCHMARK_MAIN();
