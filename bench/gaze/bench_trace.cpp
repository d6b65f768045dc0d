// SPDX-License-Identifier: Apache-2.0
// Trace reading and replay throughput on a generated one-hour 250 Hz trace (900 000 samples,
// with head pose), against a same-process baseline: counting the file's lines with getline.
// Peak memory: getrusage(RUSAGE_SELF).ru_maxrss after each benchmark (process high-water
// mark; benchmarks run in registration order, lightest first, so each figure is the peak up
// to and including that benchmark).
// Run: build/bench/gaze/bench_gaze_trace [--benchmark_filter=...]
// The trace goes to $TMPDIR (default /tmp) and is removed at exit.
#include "gaze/replay_source.hpp"
#include "gaze/trace_open.hpp"
#include "gaze/trace_reader.hpp"
#include "gaze/trace_writer.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace {

using namespace gazelod::gaze;

constexpr double kRateHz = 250.0;
constexpr std::size_t kSamples = 3600 * 250;

double maxrss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // ru_maxrss is KiB on Linux
}

// Generates the trace once per process: a random walk of fixations and saccades with noise.
const std::string& trace_path() {
  static const std::string path = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string p = std::string(tmp ? tmp : "/tmp") + "/gazelod_bench_1h_250hz.csv";
    std::ofstream f(p, std::ios::binary);
    TraceWriter w(f);
    std::mt19937_64 rng(42);
    std::normal_distribution<double> noise(0.0, 0.1);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    double yaw = 0, pitch = 0;
    TraceRecord r;
    r.has_head = true;
    r.head.valid = true;
    for (std::size_t i = 0; i < kSamples; ++i) {
      if (i % 100 == 0) {  // a new fixation target every 400 ms
        yaw = u(rng);
        pitch = u(rng) * 0.5;
      }
      r.gaze.t_ns = static_cast<std::int64_t>(i) * 4'000'000;
      r.gaze.valid = i % 1000 >= 25;  // a 100 ms blink every 4 s
      r.gaze.confidence = r.gaze.valid ? 0.9f : 0.0f;
      r.gaze.direction = direction_from_yaw_pitch_deg(yaw + noise(rng), pitch + noise(rng));
      const double a = static_cast<double>(i) * 1e-3;
      r.head.t_ns = r.gaze.t_ns;
      r.head.orientation = glm::dquat(std::cos(a), 0.0, std::sin(a), 0.0);
      r.head.position_m = {0.0, 1.6, 0.0};
      w.write(r);
    }
    std::atexit([] { std::remove(trace_path().c_str()); });
    return p;
  }();
  return path;
}

void finish(benchmark::State& state, std::size_t samples) {
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
  state.counters["peak_rss_MiB"] = maxrss_mib();
  state.counters["file_MiB"] = static_cast<double>(std::filesystem::file_size(trace_path())) / (1024.0 * 1024.0);
}

// Baseline: the cost of just getting the lines off the disk/page cache.
void BM_Baseline_LineCount(benchmark::State& state) {
  std::size_t total = 0;
  for (auto _ : state) {
    std::ifstream f(trace_path(), std::ios::binary);
    std::string line;
    std::size_t n = 0;
    while (std::getline(f, line)) ++n;
    benchmark::DoNotOptimize(n);
    total += n - 2;  // version line and header
  }
  finish(state, total);
}

// Streaming read: parse and check every row; memory stays flat.
void BM_StreamRead(benchmark::State& state) {
  std::size_t total = 0;
  for (auto _ : state) {
    auto s = open_trace(trace_path(), TraceFormat::gazelod);
    TraceRecord r;
    std::size_t n = 0;
    while (s->next(r)) ++n;
    benchmark::DoNotOptimize(n);
    total += n;
  }
  finish(state, total);
}

// Replay: load once (one copy in memory, plus I-VT labels), then query sample_at and head_at
// at every sample time and halfway between (interpolation), as a frame loop would.
void BM_ReplayLoadAndQuery(benchmark::State& state) {
  std::size_t total = 0;
  for (auto _ : state) {
    auto s = open_trace(trace_path(), TraceFormat::gazelod);
    ReplaySource replay(ReplaySource::load(*s));
    std::size_t available = 0;
    for (std::int64_t t = 0; t < static_cast<std::int64_t>(kSamples) * 4'000'000; t += 2'000'000) {
      available += replay.sample_at(t).has_value();
      available += replay.head_at(t).has_value();
    }
    benchmark::DoNotOptimize(available);
    total += replay.size();
  }
  finish(state, total);
}

// Query cost alone on a loaded source: queries per second.
void BM_ReplayQueryOnly(benchmark::State& state) {
  auto s = open_trace(trace_path(), TraceFormat::gazelod);
  ReplaySource replay(ReplaySource::load(*s));
  std::int64_t t = 0;
  const std::int64_t end = static_cast<std::int64_t>(kSamples) * 4'000'000;
  std::size_t queries = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(replay.sample_at(t));
    t += 1'111'111;  // ~900 Hz, off the sample grid
    if (t >= end) t = 0;
    ++queries;
  }
  finish(state, queries);
}

BENCHMARK(BM_Baseline_LineCount)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_StreamRead)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_ReplayLoadAndQuery)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ReplayQueryOnly);

}  // namespace

BENCHMARK_MAIN();
