// SPDX-License-Identifier: Apache-2.0
// Simulator steps per second (one step = head_at + tracker_at at a frame time, 90 Hz) with no
// effects, one, some and all of them, against a same-process baseline that only builds the
// still-head / centred-gaze answer. "Simulate only the effects a scene calls for": the
// no-effect step should cost about what the baseline does.
#include "sim/simulator.hpp"

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <cstdint>

namespace gazelod::sim {
namespace {

nlohmann::json scenario_with(nlohmann::json effects) {
  nlohmann::json objects = nlohmann::json::array();
  for (int i = 0; i < 200; ++i)
    objects.push_back({{"name", "o" + std::to_string(i)},
                       {"position_m", {i % 20 - 10.0, 0.0, -5.0 - i}},
                       {"lods", {{{"triangles", 100}}}}});
  return {{"version", 1}, {"display", "questpro"},           {"duration_s", 60},
          {"seed", 3},    {"scene", {{"objects", objects}}}, {"effects", std::move(effects)}};
}

const nlohmann::json kSome = {{{"type", "head_sweep"}, {"yaw_amplitude_deg", 20}},
                              {{"type", "saccades"}},
                              {{"type", "tracker_noise"}, {"std_deg", 0.5}}};
const nlohmann::json kAll = {{{"type", "head_sweep"}, {"yaw_amplitude_deg", 20}},
                             {{"type", "head_turn"}, {"rate_deg_s", 200}, {"start_s", 5}, {"duration_s", 0.5}},
                             {{"type", "saccades"}},
                             {{"type", "smooth_pursuit"}, {"object", "o3"}, {"start_s", 20}, {"end_s", 40}},
                             {{"type", "object_motion"}, {"object", "o3"}, {"velocity_m_s", {0.5, 0, 0}}},
                             {{"type", "tracker_rate"}, {"rate_hz", 120}},
                             {{"type", "tracker_latency"}, {"latency_ms", 10}},
                             {{"type", "tracker_noise"}, {"std_deg", 0.5}},
                             {{"type", "calibration_offset"}, {"yaw_deg", 1}, {"drift_yaw_deg_per_min", 0.5}},
                             {{"type", "dropouts"}, {"fraction", 0.05}},
                             {{"type", "blinks"}}};

constexpr std::int64_t kFrameNs = 11'111'111;
constexpr std::int64_t kWrapNs = 59'000'000'000;

void run_steps(benchmark::State& state, const nlohmann::json& effects) {
  Simulator sim(load_scenario_json(scenario_with(effects).dump(), "bench"));
  std::int64_t t = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sim.head_at(t));
    benchmark::DoNotOptimize(sim.tracker_at(t));
    t = t + kFrameNs < kWrapNs ? t + kFrameNs : 0;
  }
  state.counters["steps_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

// Baseline: what a simulator with nothing to simulate must return, built directly.
void BM_Baseline_StillHeadCentredGaze(benchmark::State& state) {
  std::int64_t t = 0;
  for (auto _ : state) {
    HeadState h;
    h.t_ns = t;
    gaze::GazeSample g;
    g.t_ns = t;
    g.valid = true;
    g.confidence = 1.0f;
    benchmark::DoNotOptimize(h);
    benchmark::DoNotOptimize(g);
    t = t + kFrameNs < kWrapNs ? t + kFrameNs : 0;
  }
  state.counters["steps_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Baseline_StillHeadCentredGaze);

void BM_Step_NoEffects(benchmark::State& s) {
  run_steps(s, nlohmann::json::array());
}
void BM_Step_TrackerNoiseOnly(benchmark::State& s) {
  run_steps(s, {{{"type", "tracker_noise"}, {"std_deg", 0.5}}});
}
void BM_Step_Some(benchmark::State& s) {
  run_steps(s, kSome);
}
void BM_Step_All(benchmark::State& s) {
  run_steps(s, kAll);
}
BENCHMARK(BM_Step_NoEffects);
BENCHMARK(BM_Step_TrackerNoiseOnly);
BENCHMARK(BM_Step_Some);
BENCHMARK(BM_Step_All);

// objects_at for 200 objects, without and with an object effect.
void run_objects(benchmark::State& state, const nlohmann::json& effects) {
  Simulator sim(load_scenario_json(scenario_with(effects).dump(), "bench"));
  std::int64_t t = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sim.objects_at(t).data());
    t = t + kFrameNs < kWrapNs ? t + kFrameNs : 0;
  }
}
void BM_Objects200_NoEffects(benchmark::State& s) {
  run_objects(s, nlohmann::json::array());
}
void BM_Objects200_ObjectMotion(benchmark::State& s) {
  run_objects(s, {{{"type", "object_motion"}, {"object", "*"}, {"amplitude_m", {0, 0.2, 0}}, {"frequency_hz", 1}}});
}
BENCHMARK(BM_Objects200_NoEffects);
BENCHMARK(BM_Objects200_ObjectMotion);

}  // namespace
}  // namespace gazelod::sim

BENCHMARK_MAIN();
