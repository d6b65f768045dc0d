// SPDX-License-Identifier: Apache-2.0
// One draw per cluster against the GPU-driven path on the same cut, frame time on the offscreen
// device (lavapipe here). The scene of bench_render_clusters.cpp: the default generated terrain
// (1,002,528 triangles), its cluster hierarchy, a viewer on its path, Reddy's s bisected so that
// select_clusters' cut holds about 240 k triangles; both eyes of a Meta Quest Pro (1800 x 1920
// each; the benchmark's argument divides both sides). The GPU pass (ClusterSelectPass) selects
// the same cut (checked: the drawn clusters are the CPU's) and culls it per eye. Cases, one frame
// of each per round, the order rotating, medians and minima over the rounds:
//   PerCluster         the CPU's cut, one vkCmdDrawIndexed per cluster in view (merging off,
//                      each cluster culled by its own sphere on the CPU, tinted by depth);
//   IndirectCount      the commands the GPU pass wrote (run before the round), one
//                      vkCmdDrawIndexedIndirectCount per eye (one tint);
//   SelectAndIndirect  the pass run per eye (selection, culling, compaction; submitted and waited
//                      for) and then IndirectCount: the whole GPU-driven frame.
// Also per round: the pass's dispatch (timestamp queries) and select_clusters on the CPU.
#include "bake/cluster/cluster_build.hpp"
#include "bake/terrain_mesh.hpp"
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "render/camera.hpp"
#include "render/cluster_select_pass.hpp"
#include "render/device_context.hpp"
#include "render/frame_renderer.hpp"
#include "render/mesh_library.hpp"
#include "render/offscreen_target.hpp"
#include "render/render_error.hpp"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace gr = gazelod::render;
namespace gl = gazelod::lod;

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

gl::Viewer cut_viewer(double scale) {
  gl::Viewer v;  // on the path, 1.6 m up, looking 15 deg down; a wide fovea (bench_render_clusters)
  const double pitch = 15.0 * std::numbers::pi / 180.0;
  v.eye_position_m = {0.0, 1.6, 0.0};
  v.gaze_direction = {0.0, -std::sin(pitch), -std::cos(pitch)};
  v.xi_cpd = 240.0;
  v.tracker_error_deg = 10.0;
  v.scale = scale;
  return v;
}

struct Scene {
  gazelod::bake::ClusterBuildResult built;
  gl::ClusterStore store;
  std::unique_ptr<gr::OffscreenDevice> device;
  gr::MeshLibrary meshes;
  std::vector<std::unique_ptr<gr::OffscreenTarget>> targets;
  std::vector<std::unique_ptr<gr::FrameRenderer>> eyes;
  std::vector<std::unique_ptr<gr::ClusterSelectPass>> passes;  // one per eye: its own commands
  std::array<gr::EyeView, 2> views;
  std::vector<gr::DrawItem> cut;
  gr::IndirectCut indirect;  // the placement and tint; buffers per eye
  gl::Viewer viewer;
  std::uint64_t cut_triangles = 0;
};

// The CPU's cut at scale s: drawn flags and triangles.
std::uint64_t select_cut(const Scene& s, double scale, std::vector<std::uint8_t>& drawn) {
  std::vector<std::uint8_t> why(drawn.size());
  std::vector<std::uint32_t> flags(s.store.record_count());
  gl::ClusterDecisions out;
  out.drawn = drawn, out.limited_by = why, out.record_flags = flags;
  if (const std::string e = gl::select_clusters(cut_viewer(scale), s.store.view(), out); !e.empty())
    throw std::runtime_error(e);
  std::uint64_t triangles = 0;
  for (std::size_t c = 0; c < drawn.size(); ++c) triangles += drawn[c] ? s.built.hierarchy.index_count[c] / 3 : 0;
  return triangles;
}

std::unique_ptr<Scene> build(std::uint32_t divisor) {
  auto s = std::make_unique<Scene>();
  const gazelod::bake::GeneratedMesh terrain = gazelod::bake::terrain_meshes({}).at(0);
  s->built = gazelod::bake::build_cluster_hierarchy(terrain.positions, terrain.indices);
  const gl::ClusterHierarchy& h = s->built.hierarchy;
  s->store.add_mesh(h, {}, glm::dvec3(0.0), s->built.indices.size());
  std::vector<std::uint8_t> drawn(h.size());
  double lo = 1e-4, hi = 1.0;  // more triangles at a larger s
  for (int step = 0; step < 30; ++step) {
    const double mid = std::sqrt(lo * hi);
    (select_cut(*s, mid, drawn) < 240'000 ? lo : hi) = mid;
  }
  s->viewer = cut_viewer(hi);
  s->cut_triangles = select_cut(*s, hi, drawn);

  // The mesh in its bounding box's unit frame (centre, half diagonal), which a DrawItem places.
  glm::dvec3 box_lo(terrain.positions[0], terrain.positions[1], terrain.positions[2]), box_hi = box_lo;
  for (std::size_t v = 0; v < terrain.positions.size(); v += 3) {
    const glm::dvec3 p(terrain.positions[v], terrain.positions[v + 1], terrain.positions[v + 2]);
    box_lo = glm::min(box_lo, p), box_hi = glm::max(box_hi, p);
  }
  const glm::dvec3 centre = 0.5 * (box_lo + box_hi);
  const double radius = 0.5 * glm::length(box_hi - box_lo);
  std::vector<glm::vec3> unit;
  for (std::size_t v = 0; v < terrain.positions.size(); v += 3)
    unit.emplace_back((glm::dvec3(terrain.positions[v], terrain.positions[v + 1], terrain.positions[v + 2]) - centre) /
                      radius);
  s->device = std::make_unique<gr::OffscreenDevice>(false);
  const std::uint32_t first = s->meshes.add_cluster_mesh(unit, s->built.indices, h.first_index, h.index_count);
  s->meshes.upload(s->device->context());
  std::vector<gr::ClusterDrawRange> ranges;
  for (std::size_t c = 0; c < h.size(); ++c) {
    const gr::MeshRange& r = s->meshes.range(first + static_cast<std::uint32_t>(c));
    ranges.push_back({r.first_index, r.index_count, r.vertex_offset});
    if (drawn[c]) s->cut.push_back({glm::vec3(centre), float(radius), first + std::uint32_t(c), h.depth[c]});
  }
  s->indirect.center_m = glm::vec3(centre), s->indirect.radius_m = float(radius);

  const double half_h = 53.0 * std::numbers::pi / 180.0, half_v = 48.0 * std::numbers::pi / 180.0;
  for (int e = 0; e < 2; ++e) {
    s->targets.push_back(std::make_unique<gr::OffscreenTarget>(s->device->context(), 1800 / divisor, 1920 / divisor));
    s->eyes.push_back(std::make_unique<gr::FrameRenderer>(s->device->context(), s->meshes, s->targets[e]->target()));
    s->eyes[e]->set_merge_draws(false);
    s->passes.push_back(std::make_unique<gr::ClusterSelectPass>(s->device->context(), s->store.view(), ranges));
    s->views[e].fov = {-half_h, half_h, half_v, -half_v};
    s->views[e].pose.orientation = glm::angleAxis(-15.0 * std::numbers::pi / 180.0, glm::dvec3(1, 0, 0));
    s->views[e].pose.position_m = {e == 0 ? -0.032 : 0.032, 1.6, 0.0};
    s->passes[e]->run(s->viewer, &s->views[e]);
  }
  std::vector<std::uint8_t> gpu(h.size());
  s->passes[0]->read_drawn(gpu);
  std::size_t differ = 0;
  for (std::size_t c = 0; c < h.size(); ++c) differ += gpu[c] != drawn[c];
  std::printf(
      "device %s; eyes %u x %u; terrain %zu clusters; cut at s = %.6g: %zu clusters, %llu triangles; "
      "GPU decisions differing from the CPU's: %zu\n",
      s->device->device_name().c_str(), 1800 / divisor, 1920 / divisor, h.size(), hi, s->cut.size(),
      static_cast<unsigned long long>(s->cut_triangles), differ);
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Arg 0: eye divisor (1: the Quest Pro's pixels); arg 1: rounds.
void BM_PerClusterVsIndirectCount(benchmark::State& state) {
  std::unique_ptr<Scene> s;
  try {
    s = build(static_cast<std::uint32_t>(state.range(0)));
  } catch (const gr::RenderError& e) {
    state.SkipWithError(e.what());
    return;
  }
  if (!s->device->context().draw_indirect_count) {
    state.SkipWithError("the device lacks drawIndirectCount");
    return;
  }
  const auto per_cluster = [&] {
    for (int e = 0; e < 2; ++e) s->eyes[e]->draw(0, s->views[e], s->cut);
  };
  const auto indirect = [&] {
    for (int e = 0; e < 2; ++e) {
      gr::IndirectCut cut = s->indirect;
      cut.commands = s->passes[e]->commands_buffer(), cut.count = s->passes[e]->count_buffer();
      cut.max_draws = s->passes[e]->command_capacity();
      s->eyes[e]->draw_indirect_count(0, s->views[e], cut);
    }
  };
  const auto select_and_indirect = [&] {
    for (int e = 0; e < 2; ++e) s->passes[e]->run(s->viewer, &s->views[e]);
    indirect();
  };
  const char* names[] = {"PerCluster", "IndirectCount", "SelectAndIndirect"};
  const std::array<std::function<void()>, 3> cases{per_cluster, indirect, select_and_indirect};
  std::array<std::vector<double>, 3> ms;
  std::vector<double> dispatch_ms, cpu_select_ms;
  std::vector<std::uint8_t> drawn(s->built.hierarchy.size());
  for (auto _ : state)
    for (std::int64_t round = 0; round < state.range(1); ++round) {
      for (std::size_t k = 0; k < cases.size(); ++k) {
        const std::size_t i = (k + static_cast<std::size_t>(round)) % cases.size();
        const auto started = Clock::now();
        cases[i]();
        ms[i].push_back(ms_since(started));
      }
      dispatch_ms.push_back(s->passes[0]->read_dispatch_ms() + s->passes[1]->read_dispatch_ms());
      const auto started = Clock::now();
      select_cut(*s, s->viewer.scale, drawn);
      cpu_select_ms.push_back(ms_since(started));
    }
  std::uint64_t per_cluster_triangles = 0, indirect_triangles = 0, per_cluster_commands = 0, indirect_commands = 0;
  per_cluster();
  for (const auto& eye : s->eyes) per_cluster_triangles += eye->triangles_last_frame();
  for (const auto& eye : s->eyes) per_cluster_commands += eye->draw_commands_last_frame();
  for (const auto& pass : s->passes)
    for (const VkDrawIndexedIndirectCommand& c : pass->read_commands())
      indirect_triangles += c.indexCount / 3, ++indirect_commands;
  std::printf("\n%lld rounds, ms per frame (both eyes):\n%-18s %10s %10s %12s %12s\n",
              static_cast<long long>(state.range(1)), "case", "median", "fastest", "triangles", "draws");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::printf("%-18s %10.1f %10.1f %12llu %12llu\n", names[i], median(ms[i]),
                *std::min_element(ms[i].begin(), ms[i].end()),
                static_cast<unsigned long long>(i == 0 ? per_cluster_triangles : indirect_triangles),
                static_cast<unsigned long long>(i == 0 ? per_cluster_commands : indirect_commands));
    state.counters[std::string(names[i]) + "_ms"] = median(ms[i]);
  }
  std::printf("GPU pass dispatch (timestamps, both eyes): median %.3f ms; select_clusters on the CPU: median %.3f ms\n",
              median(dispatch_ms), median(cpu_select_ms));
  state.counters["dispatch_ms"] = median(dispatch_ms);
  state.counters["cpu_select_ms"] = median(cpu_select_ms);
}

}  // namespace

BENCHMARK(BM_PerClusterVsIndirectCount)
    ->Args({1, 20})
    ->Args({4, 40})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
