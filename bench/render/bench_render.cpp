// SPDX-License-Identifier: Apache-2.0
// Renderer throughput on the offscreen device (lavapipe here): the same field of objects
// drawn at full detail (baseline), LOD-reduced the way the gaze-contingent selection tends to
// (finest near the gaze, coarser with eccentricity), and with nothing but the clear.
// Counters: fps (frames per second) and triangles per frame.
#include "render/device_context.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_error.hpp"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace gr = gazelod::render;

namespace {

// A four-level chain like the default scenario's (full detail, then about 1/4 each step).
constexpr std::array<std::uint32_t, 4> kChainTriangles{20000, 5000, 1250, 300};
constexpr std::uint32_t kSide = 720;  // square eye image

struct Scene {
  std::unique_ptr<gr::OffscreenDevice> device;
  gr::MeshLibrary meshes;
  std::array<std::uint32_t, 4> mesh_ids{};
  std::unique_ptr<gr::OffscreenTarget> target;
  std::unique_ptr<gr::FrameRenderer> renderer;
  gr::EyeView view;
  std::vector<gr::DrawItem> full, reduced;
};

// A grid of spheres 2..20 m ahead filling a 100-degree view; the reduced field picks the level
// by angle from the view axis (gaze straight ahead): < 5 deg L0, < 15 L1, < 30 L2, else L3.
Scene* scene(std::size_t objects) {
  static std::unique_ptr<Scene> s;
  static std::size_t built_for = 0;
  if (s && built_for == objects) return s.get();
  s.reset();
  auto sc = std::make_unique<Scene>();
  sc->device = std::make_unique<gr::OffscreenDevice>(false);
  for (std::size_t l = 0; l < kChainTriangles.size(); ++l) sc->mesh_ids[l] = sc->meshes.add_sphere(kChainTriangles[l]);
  sc->meshes.upload(sc->device->context());
  sc->target = std::make_unique<gr::OffscreenTarget>(sc->device->context(), kSide, kSide);
  sc->renderer = std::make_unique<gr::FrameRenderer>(sc->device->context(), sc->meshes, sc->target->target());
  const double half = 50.0 * std::numbers::pi / 180.0;
  sc->view.fov = {-half, half, half, -half};
  const auto per_side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(objects))));
  const auto side_d = static_cast<double>(per_side);
  const auto count_d = static_cast<double>(objects);
  for (std::size_t i = 0; i < objects; ++i) {
    const double u = (static_cast<double>(i % per_side) + 0.5) / side_d * 2.0 - 1.0;  // -1..1
    const double v = (static_cast<double>(i / per_side) + 0.5) / side_d * 2.0 - 1.0;
    // Depths scrambled over 2..20 m (7919 is prime, so i -> i * 7919 mod n is a permutation).
    const double depth = 2.0 + 18.0 * static_cast<double>((i * 7919) % objects) / count_d;
    const glm::dvec3 c(u * depth * std::tan(half) * 0.9, v * depth * std::tan(half) * 0.9, -depth);
    const float radius = static_cast<float>(0.35 * depth * std::tan(half) / side_d);
    const double ecc_deg = std::atan2(glm::length(glm::cross(glm::normalize(c), glm::dvec3(0, 0, -1))),
                                      glm::dot(glm::normalize(c), glm::dvec3(0, 0, -1))) *
                           180.0 / std::numbers::pi;
    const std::uint32_t level = ecc_deg < 5.0 ? 0u : ecc_deg < 15.0 ? 1u : ecc_deg < 30.0 ? 2u : 3u;
    sc->full.push_back({glm::vec3(c), radius, sc->mesh_ids[0], 0});
    sc->reduced.push_back({glm::vec3(c), radius, sc->mesh_ids[level], level});
  }
  s = std::move(sc);
  built_for = objects;
  return s.get();
}

void run(benchmark::State& state, bool reduced, bool empty) {
  Scene* s = nullptr;
  try {
    s = scene(static_cast<std::size_t>(state.range(0)));
  } catch (const gr::RenderError& e) {
    state.SkipWithError(e.what());
    return;
  }
  const std::vector<gr::DrawItem> none;
  const auto& items = empty ? none : reduced ? s->reduced : s->full;
  for (auto _ : state) s->renderer->draw(0, s->view, items);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(s->renderer->triangles_last_frame());
}

void BM_RenderFullDetail(benchmark::State& state) {
  run(state, false, false);
}
void BM_RenderLodReduced(benchmark::State& state) {
  run(state, true, false);
}
void BM_RenderClearOnly(benchmark::State& state) {
  run(state, false, true);
}

}  // namespace

// Real time: the work happens on lavapipe's threads, not the calling one.
BENCHMARK(BM_RenderFullDetail)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_RenderLodReduced)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_RenderClearOnly)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

BENCHMARK_MAIN();
