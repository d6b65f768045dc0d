// SPDX-License-Identifier: Apache-2.0
// The GPU cluster-selection pass (render/cluster_select_pass.hpp) on a large scene, timed by its
// own timestamp queries: hundreds of instances of one baked terrain hierarchy (each a copy in
// the ClusterStore, world space) tiled into a square, about --clusters clusters in all, a viewer
// walking across the middle and looking around, one frame per step. Prints the dispatch's GPU
// ms per frame (median, fastest, slowest), the frame's wall time around run() (constants, submit,
// wait), select_clusters on the CPU for the same frames, and how many GPU decisions differ from
// the CPU's. bench/gpu/run_cluster_select_gpu.sh builds and runs it. It prefers a real GPU
// (OffscreenDevice's prefer_gpu) and falls back to lavapipe, a CPU rasteriser whose figures only
// show that the pass runs.
//   bench_cluster_select_gpu [--clusters N] [--frames F] [--triangles T] [--cpu]
#include "bake/cluster/cluster_build.hpp"
#include "bake/terrain_mesh.hpp"
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "render/camera.hpp"
#include "render/cluster_select_pass.hpp"
#include "render/device_context.hpp"
#include "render/render_error.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace gr = gazelod::render;
namespace gl = gazelod::lod;

namespace {

// Time since `start` on the steady clock: seconds for the setup steps, ms for the frames.
struct Stopwatch {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  double s() const { return ms() / 1000.0; }
};

struct Args {
  std::size_t clusters = 10'000'000, frames = 20;
  std::uint64_t triangles = 1'000'000;
  bool prefer_gpu = true;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--clusters" && has_value)
      a.clusters = std::stoull(argv[++i]);
    else if (arg == "--frames" && has_value)
      a.frames = std::stoull(argv[++i]);
    else if (arg == "--triangles" && has_value)
      a.triangles = std::stoull(argv[++i]);
    else if (arg == "--cpu")
      a.prefer_gpu = false;
    else
      throw std::invalid_argument(
          "usage: bench_cluster_select_gpu [--clusters N] [--frames F] [--triangles T] [--cpu]");
  }
  if (a.clusters == 0 || a.frames == 0) throw std::invalid_argument("--clusters and --frames must be positive");
  return a;
}

// Step k of the walk: across the square's middle at 1.4 m/s, the gaze and head turning.
gl::Viewer walk(std::size_t k, double side_m, gr::EyeView& view) {
  const double s = static_cast<double>(k), yaw = 1.5 * std::sin(0.4 * s), pitch = -0.1 - 0.05 * double(k % 5);
  gl::Viewer v;
  v.eye_position_m = {0.5 * side_m + 2.0 * s, 1.7, 0.5 * side_m};
  v.eye_velocity_m_s = {1.4, 0.0, 0.0};
  v.gaze_direction = {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
  v.head_angular_velocity_rad_s = {0.0, k % 3 == 0 ? 1.0 : 0.1, 0.0};
  v.xi_cpd = 30.0;
  v.tracker_error_deg = 1.0;
  view.pose.position_m = v.eye_position_m;
  view.pose.orientation = glm::angleAxis(yaw, glm::dvec3{0, 1, 0}) * glm::angleAxis(pitch, glm::dvec3{1, 0, 0});
  const double h = 53.0 * std::numbers::pi / 180.0, u = 48.0 * std::numbers::pi / 180.0;
  view.fov = {-h, h, u, -u};  // a Quest Pro eye
  view.far_m = 10'000.0;
  return v;
}

struct Stats {
  double median = 0, fastest = 0, slowest = 0;
};
Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]), v.front(), v.back()};
}

int run(const Args& a) {
  gazelod::bake::TerrainOptions terrain;
  terrain.triangles = a.triangles;
  Stopwatch watch;
  const gazelod::bake::GeneratedMesh mesh = gazelod::bake::terrain_meshes(terrain).at(0);
  const gazelod::bake::ClusterBuildResult built = gazelod::bake::build_cluster_hierarchy(mesh.positions, mesh.indices);
  const gl::ClusterHierarchy& h = built.hierarchy;
  const std::size_t tiles = (a.clusters + h.size() - 1) / h.size();
  const auto per_side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(tiles))));
  std::printf("hierarchy: %zu clusters from %llu triangles (%.1f s); %zu instances, %zu per side of %.0f m\n", h.size(),
              static_cast<unsigned long long>(mesh.triangles()), watch.s(), tiles, per_side, terrain.size_m);

  watch = {};
  gl::ClusterStore store;
  store.reserve(tiles, tiles * h.size());
  std::vector<gr::ClusterDrawRange> ranges;
  ranges.reserve(tiles * h.size());
  for (std::size_t t = 0; t < tiles; ++t) {
    gl::InstanceTransform xf;  // tile t's centre; every other one turned
    xf.translation_m = {terrain.size_m * (0.5 + double(t % per_side)), 0.0,
                        terrain.size_m * (0.5 + double(t / per_side))};
    xf.rotation = glm::angleAxis(0.5 * std::numbers::pi * double(t % 4), glm::dvec3{0, 1, 0});
    store.add_mesh(h, xf, glm::dvec3(0.0), built.indices.size());
    for (std::size_t c = 0; c < h.size(); ++c) ranges.push_back({h.first_index[c], h.index_count[c], 0});
  }
  const gl::ClusterSet cs = store.view();
  std::printf("store: %zu clusters, %zu distinct records (%.1f s)\n", cs.size(), cs.record_count(), watch.s());

  gr::OffscreenDevice device(false, a.prefer_gpu);
  watch = {};
  gr::ClusterSelectPass pass(device.context(), cs, ranges);
  std::printf("device: %s; upload %.1f s; %zu dispatch(es) per frame, %u commands at most\n",
              device.device_name().c_str(), watch.s(), pass.dispatch_count(), pass.command_capacity());

  std::vector<std::uint8_t> drawn(cs.size()), why(cs.size()), gpu(cs.size());
  std::vector<std::uint32_t> flags(cs.record_count());
  gl::ClusterDecisions out;
  out.drawn = drawn, out.limited_by = why, out.record_flags = flags;
  std::vector<double> dispatch_ms, wall_ms, cpu_ms;
  std::size_t differ = 0, decided = 0, commands = 0, in_cut = 0;
  const double side_m = terrain.size_m * double(per_side);
  for (std::size_t k = 0; k < a.frames + 2; ++k) {  // two warm-up frames
    gr::EyeView view;
    const gl::Viewer v = walk(k, side_m, view);
    watch = {};
    pass.run(v, &view);
    const double wall = watch.ms();
    watch = {};
    if (const std::string e = gl::select_clusters(v, cs, out); !e.empty()) throw std::runtime_error(e);
    const double cpu = watch.ms();
    if (k < 2) continue;
    dispatch_ms.push_back(pass.read_dispatch_ms());
    wall_ms.push_back(wall);
    cpu_ms.push_back(cpu);
    commands += pass.read_draw_count();
    if (k == 2 || k + 1 == a.frames + 2) {  // decisions checked on the first and last frame
      pass.read_drawn(gpu);
      for (std::size_t i = 0; i < cs.size(); ++i) differ += gpu[i] != drawn[i], in_cut += gpu[i];
      decided += cs.size();
    }
  }
  const Stats d = stats(dispatch_ms), w = stats(wall_ms), c = stats(cpu_ms);
  std::printf("frames: %zu; clusters in the cut (checked frames): %zu of %zu; commands per frame: %zu\n", a.frames,
              in_cut, decided, commands / a.frames);
  std::printf("GPU decisions differing from select_clusters: %zu of %zu\n", differ, decided);
  std::printf("dispatch (timestamp queries): median %.3f ms, fastest %.3f ms, slowest %.3f ms\n", d.median, d.fastest,
              d.slowest);
  std::printf("run() wall time (constants, submit, wait): median %.3f ms\n", w.median);
  std::printf("select_clusters on the CPU (one thread): median %.3f ms\n", c.median);
  return differ == 0 ? 0 : 2;
}

}  // namespace

// Exit status: 0, 2 where a GPU decision differs from the CPU's, 77 without a Vulkan device
// (the automake "skipped"), 1 on any other error.
int main(int argc, char** argv) {
  int status = 1;
  try {
    status = run(parse(argc, argv));
  } catch (const gr::NoVulkanDevice& e) {
    std::fprintf(stderr, "no Vulkan device: %s\n", e.what());
    status = 77;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_cluster_select_gpu: %s\n", e.what());
  }
  return status;
}
