// SPDX-License-Identifier: Apache-2.0
// ns per object for the full selection (lod/select.hpp) at 1k..1M objects, beside a naive
// per-object baseline in the same run: array of structs, acos of a dot product, asin, log10
// and a division per level, as a first implementation of Reddy 1998 would do it.
// Counters: ns_per_object = this thread's CPU time / (iterations x objects), a plain number
// in ns; speedup_vs_naive = the naive loop's ns_per_object at the same size (run first, same
// process) over this one's. The naive benchmarks are registered first for that reason.
#include "lod/select.hpp"

#include <benchmark/benchmark.h>

#include <memory>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

std::vector<LodLevel> chain(int variant) {
  if (variant % 2)
    return {{3928, 0, DetailKind::removed_cycles_per_diameter, 0.0},
            {834, 0, DetailKind::removed_cycles_per_diameter, 400.0},
            {254, 0, DetailKind::removed_cycles_per_diameter, 120.0},
            {76, 0, DetailKind::removed_cycles_per_diameter, 30.0}};
  return {{1000, 0, DetailKind::geometric_error_m, 0.0},
          {300, 0, DetailKind::geometric_error_m, 0.002},
          {80, 0, DetailKind::geometric_error_m, 0.01},
          {20, 0, DetailKind::geometric_error_m, 0.05}};
}

// A walk-through with the head turning at 60 deg/s and the eyes pursuing a little.
Viewer viewer() {
  Viewer vw;
  vw.eye_position_m = {0.0, 1.6, 0.0};
  vw.eye_velocity_m_s = {0.0, 0.0, -1.4};
  vw.gaze_direction = glm::normalize(glm::dvec3{0.2, -0.1, -1.0});
  vw.head_angular_velocity_rad_s = {0.0, 60.0 * M_PI / 180, 0.0};
  vw.gaze_angular_velocity_in_head_rad_s = {0.0, -0.2, 0.0};
  vw.xi_cpd = 10.75;  // Quest 3
  vw.tracker_error_deg = 1.5;
  return vw;
}

struct NaiveObject {
  glm::dvec3 c, v;
  double r;
  std::vector<LodLevel> lods;
};

struct Scene {
  ObjectStore store;
  std::vector<NaiveObject> naive;
};

const Scene& scene(std::size_t n) {
  static std::vector<std::pair<std::size_t, std::unique_ptr<Scene>>> cache;
  for (auto& [k, s] : cache)
    if (k == n) return *s;
  auto s = std::make_unique<Scene>();
  std::mt19937_64 rng(n);
  std::uniform_real_distribution<double> u(-1, 1);
  s->store.reserve(n, 4 * n);
  s->naive.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 c{u(rng) * 100, u(rng) * 10 + 1.6, u(rng) * 100};
    const double r = std::pow(10.0, u(rng) - 0.5);
    const glm::dvec3 v = (i % 4 == 0) ? glm::dvec3{u(rng) * 3, 0, u(rng) * 3} : glm::dvec3{0.0};
    auto ch = chain(static_cast<int>(i));
    s->store.add(c, r, v, ch);
    s->naive.push_back({c, v, r, ch});
  }
  cache.emplace_back(n, std::move(s));
  return *cache.back().second;
}

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

double per_object_ns(const benchmark::State& state, std::size_t n, double cpu_ns) {
  return cpu_ns / (static_cast<double>(state.iterations()) * static_cast<double>(n));
}

std::map<std::size_t, double>& naive_ns_per_object() {  // filled by BM_NaiveSelect
  static std::map<std::size_t, double> m;
  return m;
}

void BM_Select(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const Scene& sc = scene(n);
  std::vector<std::uint8_t> lod(n), why(n), s(n), e(n), v(n);
  const Decisions out{lod, why, s, e, v, {}, {}, {}};
  const Viewer vw = viewer();
  const ObjectSet os = sc.store.view();
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    benchmark::DoNotOptimize(select_lods(vw, os, out));
    benchmark::ClobberMemory();
  }
  const double ns = per_object_ns(state, n, thread_cpu_ns() - t0);
  std::size_t reduced = 0;
  for (auto l : lod) reduced += l > 0;
  state.counters["ns_per_object"] = ns;
  if (auto it = naive_ns_per_object().find(n); it != naive_ns_per_object().end())
    state.counters["speedup_vs_naive"] = it->second / ns;
  state.counters["reduced_pct"] = 100.0 * static_cast<double>(reduced) / static_cast<double>(n);
}

// The same rule, written the obvious way.
void naive_select(const Viewer& vw, const std::vector<NaiveObject>& objs, std::vector<std::uint8_t>& lod,
                  std::vector<std::uint8_t>& s_only, std::vector<std::uint8_t>& e_only,
                  std::vector<std::uint8_t>& v_only) {
  const glm::dvec3 g = glm::normalize(vw.gaze_direction);
  const glm::dvec3 w_gaze = vw.head_angular_velocity_rad_s + vw.gaze_angular_velocity_in_head_rad_s;
  const double a0 = vw.scale * std::min(60.0, vw.xi_cpd);
  for (std::size_t i = 0; i < objs.size(); ++i) {
    const NaiveObject& o = objs[i];
    const glm::dvec3 dc = o.c - vw.eye_position_m;
    const double d = glm::length(dc);
    const double alpha = d > o.r ? std::asin(o.r / d) : M_PI / 2;
    const double phi = std::acos(std::clamp(glm::dot(g, dc) / d, -1.0, 1.0));
    const double ecc = d > o.r ? std::max(0.0, phi - alpha) * 180 / M_PI - vw.tracker_error_deg : 0.0;
    const glm::dvec3 w = glm::cross(dc, o.v - vw.eye_velocity_m_s) / (d * d) - w_gaze;
    const double vel = glm::length(glm::cross(w, dc)) / d * 180 / M_PI;
    const double gv = vel <= 0.825 ? 60.0 : std::clamp(-27.78 * std::log10(vel) + 57.69, 0.0, 60.0);
    const double m = ecc <= 5.79 ? 1.0 : std::min(1.0, 7.49 / std::pow(0.3 * ecc + 1.0, 2));
    const double a_e = vw.scale * std::min(60.0 * m, vw.xi_cpd);
    const double a_v = vw.scale * std::min(gv, vw.xi_cpd);
    const double a_c = vw.scale * std::min(gv * m, vw.xi_cpd);
    const double alpha_deg = alpha * 180 / M_PI;
    auto freq = [&](const LodLevel& l) {
      return l.detail_kind == DetailKind::removed_cycles_per_diameter ? l.detail / (2.0 * alpha_deg)
                                                                      : 1.0 / (2.0 * (l.detail / d) * 180 / M_PI);
    };
    const double f1 = o.lods.size() > 1 ? freq(o.lods[1]) : 0.0;
    const double shrink = f1 > a0 ? a0 / f1 * (1.0 - 1e-15) : 1.0;  // size off
    unsigned ls = 0, le = 0, lv = 0, lc = 0;
    for (std::size_t k = 1; k < o.lods.size(); ++k) {
      const double f = freq(o.lods[k]);
      ls += f > a0;
      le += f * shrink > a_e;
      lv += f * shrink > a_v;
      lc += f > a_c;
    }
    lod[i] = static_cast<std::uint8_t>(lc);
    s_only[i] = static_cast<std::uint8_t>(ls);
    e_only[i] = static_cast<std::uint8_t>(le);
    v_only[i] = static_cast<std::uint8_t>(lv);
  }
}

void BM_NaiveSelect(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const Scene& sc = scene(n);
  std::vector<std::uint8_t> lod(n), s(n), e(n), v(n);
  const Viewer vw = viewer();
  const double t0 = thread_cpu_ns();
  for (auto _ : state) {
    naive_select(vw, sc.naive, lod, s, e, v);
    benchmark::ClobberMemory();
  }
  const double ns = per_object_ns(state, n, thread_cpu_ns() - t0);
  naive_ns_per_object()[n] = ns;
  // How often the naive answer differs from the fast one (acos loses small angles; otherwise
  // the two agree up to rounding at thresholds).
  std::vector<std::uint8_t> fl(n), fw(n), fs(n), fe(n), fv(n);
  if (const std::string err = select_lods(vw, sc.store.view(), Decisions{fl, fw, fs, fe, fv, {}, {}, {}}); !err.empty())
    state.SkipWithError(err.c_str());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n; ++i) differ += fl[i] != lod[i];
  state.counters["ns_per_object"] = ns;
  state.counters["differs_from_fast"] = static_cast<double>(differ);
}

BENCHMARK(BM_NaiveSelect)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Select)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gazelod::lod

BENCHMARK_MAIN();
