// SPDX-License-Identifier: Apache-2.0
// What accuracy costs in time. Two benchmarks over scenes of 100 to 100k objects with
// 4 and 8 levels each (budget_scene.hpp):
//  - BM_Solve: every solver from scratch on one frame: time per frame and the gap to the
//    reference, which is the proven optimum (branch and bound, where it finishes within its
//    node limit) or else the LP-relaxation upper bound (the gap is then an over-estimate).
//  - BM_IncrementalCoherent: Mason's incremental solver frame after frame, each frame started
//    from the previous answer while every object's projected size drifts by 1 % (costs and
//    benefits recomputed outside the timed region; step() alone is timed, in thread CPU time,
//    with its wall time as the counter wall_ms; no move or time limit, so every frame runs to
//    convergence and the answers do not depend on timing). The
//    same-process baseline is BM_Solve's mason-greedy / mason-incremental from scratch.
// After the console output, one markdown table with plain numbers (no SI prefixes).
#include "budget_scene.hpp"
#include "thread_cpu.hpp"
#include "budget/knapsack_incremental.hpp"

#include <benchmark/benchmark.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gazelod::budget::bench {
namespace {

constexpr std::uint64_t kExactNodeLimit = 2'000'000;

struct Reference {
  double profit = 0.0;
  bool exact = false;  // proven optimum; else the LP upper bound
};

Reference reference(const MckpInstance& inst) {
  if (inst.subset_count() <= 1000) {
    try {
      const MckpSolution opt = solve_exact(inst, kExactNodeLimit);
      if (opt.proven_optimal) return {opt.profit, true};
    } catch (const std::invalid_argument&) {  // too large for branch and bound
    }
  }
  return {lp_upper_bound(inst), false};
}

// Gap in percent of the reference; rounding noise (|gap| < 1e-9 %) prints as 0.
double gap_pct(const Reference& ref, double profit) {
  if (!(ref.profit > 0.0)) return 0.0;
  const double g = 100.0 * (ref.profit - profit) / ref.profit;
  return std::fabs(g) < 1e-9 ? 0.0 : g;
}

// One static scene and its reference per (objects, levels), shared by every solver.
const std::pair<Scene, Reference>& static_scene(std::size_t n, int m) {
  static std::map<std::pair<std::size_t, int>, std::pair<Scene, Reference>> cache;
  auto it = cache.find({n, m});
  if (it == cache.end()) {
    Scene s = make_scene(n, m, 42);
    const Reference ref = reference(s.inst);
    it = cache.emplace(std::make_pair(n, m), std::make_pair(std::move(s), ref)).first;
  }
  return it->second;
}

void BM_Solve(benchmark::State& state) {
  const auto kind = static_cast<SolverKind>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  const auto m = static_cast<int>(state.range(2));
  const auto& [scene, ref] = static_scene(n, m);
  MckpSolution sol;
  for (auto _ : state) {
    sol = kind == SolverKind::exact ? solve_exact(scene.inst, kExactNodeLimit) : solve(kind, scene.inst);
    benchmark::DoNotOptimize(sol.profit);
  }
  state.counters["gap_pct"] = sol.feasible ? gap_pct(ref, sol.profit) : NAN;
  state.counters["ref_exact"] = ref.exact;
  state.counters["feasible"] = sol.feasible;
  if (kind == SolverKind::exact) state.counters["proven"] = sol.proven_optimal;
  state.SetLabel(std::string(solver_name(kind)));
}

void BM_IncrementalCoherent(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto m = static_cast<int>(state.range(1));
  Scene scene = make_scene(n, m, 42);
  std::mt19937 rng(7);
  IncrementalScheduler sched;
  sched.reset(scene.inst);  // every level kept: profits change per frame
  MckpSolution prev, cur;
  const SolveLimits converge;                      // no limit
  sched.step(scene.inst, {}, {}, converge, prev);  // converge once
  double moves = 0, frames = 0, truncated = 0, wall_s = 0;
  for (auto _ : state) {
    drift(scene, rng, 0.01);
    const double c0 = thread_cpu_s();
    const auto t0 = std::chrono::steady_clock::now();
    sched.step(scene.inst, prev.choice, {}, converge, cur);
    const auto t1 = std::chrono::steady_clock::now();
    state.SetIterationTime(thread_cpu_s() - c0);
    wall_s += std::chrono::duration<double>(t1 - t0).count();
    moves += static_cast<double>(cur.iterations);
    truncated += cur.truncated;
    frames += 1;
    std::swap(prev, cur);
  }
  // Quality of the last frame: against the reference, and against Mason's greedy from
  // scratch (stopping at the critical item: the state the incremental algorithm converges to).
  const Reference ref = reference(scene.inst);
  state.counters["gap_pct"] = gap_pct(ref, prev.profit);
  state.counters["ref_exact"] = ref.exact;
  state.counters["feasible"] = prev.feasible;
  state.counters["vs_greedy_pct"] = gap_pct({solve_mason_greedy(scene.inst, false).profit, false}, prev.profit);
  state.counters["moves_per_frame"] = moves / std::max(frames, 1.0);
  state.counters["truncated_frames"] = truncated;
  state.counters["wall_ms"] = 1e3 * wall_s / std::max(frames, 1.0);
  state.SetLabel("mason-incremental, coherent");
}

void solve_args(benchmark::internal::Benchmark* b) {
  for (std::string_view name : solver_names())
    for (int64_t m : {4, 8})
      for (int64_t n : {100, 1000, 10000, 100000}) {
        const SolverKind kind = *solver_from_name(name);
        if (kind == SolverKind::exact && n > 1000) continue;  // exponential
        b->Args({static_cast<int64_t>(kind), n, m});
      }
}

void coherent_args(benchmark::internal::Benchmark* b) {
  for (int64_t m : {4, 8})
    for (int64_t n : {100, 1000, 10000, 100000}) b->Args({n, m});
}

// One subset of n items in random order (the `budget --instance` case of issue #40: one object
// with 200k candidate levels): every solver's cost should grow as n log n (the sort), not n^2,
// i.e. a little more than double from one n to the next.
void BM_OneLargeSubset(benchmark::State& state) {
  const auto kind = static_cast<SolverKind>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 100.0);
  std::vector<MckpItem> items(n);
  for (MckpItem& it : items) it.profit = u(rng), it.cost = u(rng);
  MckpInstance inst;
  inst.capacity = 50.0;
  inst.add_subset(items);
  MckpSolution sol;
  for (auto _ : state) {
    sol = kind == SolverKind::exact ? solve_exact(inst, kExactNodeLimit) : solve(kind, inst);
    benchmark::DoNotOptimize(sol.profit);
  }
  state.SetLabel(std::string(solver_name(kind)) + ", one subset");
}

void one_subset_args(benchmark::internal::Benchmark* b) {
  for (SolverKind kind : {SolverKind::exact, SolverKind::mason_incremental, SolverKind::funkhouser_incremental})
    for (int64_t n : {50000, 100000, 200000}) b->Args({static_cast<int64_t>(kind), n});
}

BENCHMARK(BM_Solve)->Apply(solve_args)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OneLargeSubset)->Apply(one_subset_args)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IncrementalCoherent)->Apply(coherent_args)->UseManualTime()->Unit(benchmark::kMillisecond);

// Console output as usual, plus the runs kept for the table.
class TableReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && !r.error_occurred) runs_.push_back(r);
    ConsoleReporter::ReportRuns(runs);
  }
  void print_table() const {
    std::printf("\n| solver | objects | levels | CPU ms/frame | wall ms/frame | gap (%%) | reference | notes |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---|---|\n");
    for (const Run& r : runs_) {
      const std::string name = r.benchmark_name();
      // Arguments from the name: BM_Solve/<kind>/<n>/<m> or BM_IncrementalCoherent/<n>/<m>/...
      std::vector<long> args;
      for (std::size_t p = name.find('/'); p != std::string::npos; p = name.find('/', p + 1))
        if (std::isdigit(static_cast<unsigned char>(name[p + 1]))) args.push_back(std::stol(name.substr(p + 1)));
      const bool coherent = name.rfind("BM_IncrementalCoherent", 0) == 0 || name.rfind("BM_FrameBudget", 0) == 0;
      const long n = coherent ? args.at(0) : args.at(1), m = coherent ? args.at(1) : args.at(2);
      auto counter = [&](const char* c) {
        const auto it = r.counters.find(c);
        return it == r.counters.end() ? NAN : it->second.value;
      };
      // Incremental: manual time = this thread's CPU time, wall time in a counter. From scratch:
      // the process CPU time and the wall time of Google Benchmark.
      const double unit_ms = r.time_unit == benchmark::kMillisecond ? 1.0 : 1e3;
      const double cpu_ms = (coherent ? r.GetAdjustedRealTime() : r.GetAdjustedCPUTime()) * unit_ms;
      const double wall_ms = coherent ? counter("wall_ms") : r.GetAdjustedRealTime() * unit_ms;
      std::string notes;
      if (counter("feasible") == 0.0) notes += "INFEASIBLE ";
      if (coherent && std::isnan(counter("vs_greedy_pct"))) {  // BM_FrameBudget
        char limit[96];
        if (args.at(3) > 0)
          std::snprintf(limit, sizeof limit, "max %ld moves", args.at(3));
        else
          std::snprintf(limit, sizeof limit, "no move limit");
        if (args.at(4) > 0)
          std::snprintf(limit + std::strlen(limit), sizeof limit - std::strlen(limit), ", wall-clock limit %.1f ms",
                        1e-3 * static_cast<double>(args.at(4)));
        char buf[384];
        std::snprintf(buf, sizeof buf,
                      "choose() + observe(), %.1f %% of objects change perceptual level per frame, "
                      "%s; moves/frame %.1f mean, %.0f p99, %.0f max; of %lld frames: %.0f "
                      "truncated, %.0f infeasible, %.0f measured over budget",
                      0.1 * static_cast<double>(args.at(2)), limit, counter("moves_per_frame"), counter("moves_p99"),
                      counter("moves_max"), static_cast<long long>(r.iterations), counter("truncated_frames"),
                      counter("infeasible_frames"), counter("over_budget_frames"));
        notes += buf;
      } else if (coherent) {
        char buf[256];
        std::snprintf(buf, sizeof buf, "%.1f moves/frame, %.0f of %lld frames truncated; vs greedy %.4f %%",
                      counter("moves_per_frame"), counter("truncated_frames"), static_cast<long long>(r.iterations),
                      counter("vs_greedy_pct"));
        notes += buf;
      }
      if (counter("proven") == 0.0) notes += "not proven optimal (node limit)";
      const double ref = counter("ref_exact");
      char gap[32] = "-";
      if (!std::isnan(counter("gap_pct"))) std::snprintf(gap, sizeof gap, "%.4f", counter("gap_pct"));
      std::printf("| %s | %ld | %ld | %.4f | %.4f | %s | %s | %s |\n", r.report_label.c_str(), n, m, cpu_ms, wall_ms,
                  gap,
                  std::isnan(ref) ? "-"
                  : ref > 0.5     ? "exact"
                                  : "LP bound",
                  notes.c_str());
    }
  }

 private:
  std::vector<Run> runs_;
};

}  // namespace
}  // namespace gazelod::budget::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  gazelod::budget::bench::TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_table();
  benchmark::Shutdown();
  return 0;
}
