// SPDX-License-Identifier: Apache-2.0
// What a cluster cut's triangles cost on the offscreen device (lavapipe here), against the
// part of a frame that does not scale with triangles. One process, one scene: the default
// generated terrain (bake/terrain_mesh.hpp, 1,002,528 triangles), its cluster hierarchy
// (bake/cluster/cluster_build.hpp) and a cut chosen by lod/cluster/cluster_select.hpp for a viewer standing on
// the terrain's path, with Reddy's global scale s bisected so that the cut holds about
// kCutTriangles. A frame is both eyes of a Meta Quest Pro (1800 x 1920 each, 106 x 96 deg),
// each eye its own renderer and image, as `gazelod run` draws them (GAZELOD_BENCH_EYE_DIVISOR:
// fewer pixels, below). Cases, in this order:
//   Empty      clear only (arg 1: plus both eyes' readback), the fixed cost;
//   Coarse     the hierarchy's top clusters (tens of thousands of triangles per eye over the
//              same ground, the fewest any cut has): the fixed cost plus filling the terrain's
//              pixels, which no cut changes;
//   Whole      the terrain as one draw;
//   PerCluster the cut, one draw per cluster (FrameRenderer::set_merge_draws(false));
//   Merged     the same cut, runs of clusters merged into one draw, a loop of vkCmdDrawIndexed
//              (FrameRenderer::set_multi_draw(false); what `gazelod run` draws: the OpenXR
//              host's device has no multiDrawIndirect);
//   MergedIndirect  the same merged draws, one vkCmdDrawIndexedIndirect per tint (the default
//              where the device has multiDrawIndirect, as lavapipe's OffscreenDevice does);
//   Culled     MergedIndirect less the clusters whose own sphere is outside the eye's view
//              (FrameRenderer::set_cull_ranges, on by default: what `gazelod run` draws). The
//              cases before it cull by the terrain's sphere only, as before per-cluster culling.
// Before the cases it prints the left eye's triangles by screen size (outside the view, under
// one pixel, covering a pixel or more): what the triangles cost depends on which kind they are.
// Counters: ms_per_frame (real time per iteration), triangles, draws (indexed ranges) and
// commands (draw commands recorded) per frame (both eyes),
// covered_px (left eye pixels not background), x_whole = ms / Whole's ms, above_empty_x_whole
// = (ms - Empty's) / (Whole's - Empty's) and above_coarse_x_whole = (ms - Coarse's) / (Whole's
// - Coarse's): the part that scales with triangles (and draws) against Whole's. Ratios need the
// earlier cases run first with the same readback arg; 0 otherwise.
// BM_Interleaved draws the same cases one frame each in turn and prints medians, minima and
// ratios: on a shared machine, the figures to quote.
#include "bake/cluster/cluster_build.hpp"
#include "bake/terrain_mesh.hpp"
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "render/camera.hpp"
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
#include <cstdlib>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gr = gazelod::render;
namespace gl = gazelod::lod;

namespace {

constexpr std::uint64_t kCutTriangles = 240'000;
constexpr std::uint32_t kEyeWidth = 1800, kEyeHeight = 1920;

// GAZELOD_BENCH_EYE_DIVISOR = d (1, 2, 4 or 8; default 1): each eye drawn at 1/d of the Quest
// Pro's width and height, the same views, terrain and cut: how much of a frame is the fill.
std::uint32_t eye_divisor() {
  static const std::uint32_t d = [] {
    const char* v = std::getenv("GAZELOD_BENCH_EYE_DIVISOR");
    const std::string text = v ? v : "1";
    if (text != "1" && text != "2" && text != "4" && text != "8")
      throw std::invalid_argument("GAZELOD_BENCH_EYE_DIVISOR must be 1, 2, 4 or 8, got '" + text + "'");
    return static_cast<std::uint32_t>(std::stoul(text));
  }();
  return d;
}
std::uint32_t eye_width() {
  return kEyeWidth / eye_divisor();
}
std::uint32_t eye_height() {
  return kEyeHeight / eye_divisor();
}
constexpr double kHalfIpdM = 0.032, kEyeHeightM = 1.6, kPitchDownDeg = 15.0;

struct Scene {
  std::unique_ptr<gr::OffscreenDevice> device;
  gr::MeshLibrary meshes;
  std::array<std::unique_ptr<gr::OffscreenTarget>, 2> targets;
  std::array<std::unique_ptr<gr::FrameRenderer>, 2> eyes;
  std::array<gr::EyeView, 2> views;
  std::vector<gr::DrawItem> whole, cut, coarse;
  std::uint64_t whole_triangles = 0, cut_triangles = 0;
  double scale = 0.0;
};

// The viewer on the path (x = 0, height 0 there), gazing ahead and down the pitch.
gl::Viewer viewer(double scale) {
  gl::Viewer v;
  v.eye_position_m = {0.0, kEyeHeightM, 0.0};
  const double pitch = kPitchDownDeg * std::numbers::pi / 180.0;
  v.gaze_direction = {0.0, -std::sin(pitch), -std::cos(pitch)};
  // No display limit in the way and a 10 deg wider fovea: with xi = 60 cpd and no tracker error
  // even s = 1 cut fewer than kCutTriangles from this spot (222 k per eye when measured).
  v.xi_cpd = 240.0;
  v.tracker_error_deg = 10.0;
  v.scale = scale;
  return v;
}

std::uint64_t cut_triangles(const gl::ClusterHierarchy& h, const std::vector<std::uint8_t>& drawn) {
  std::uint64_t n = 0;
  for (std::size_t c = 0; c < h.size(); ++c)
    if (drawn[c]) n += h.index_count[c] / 3;
  return n;
}

// Selects the cut at Reddy's scale s into `drawn`; throws on a refused selection.
void select_cut(const gl::ClusterStore& store, double scale, std::vector<std::uint8_t>& drawn,
                std::vector<std::uint8_t>& limited_by) {
  gl::ClusterDecisions out;
  out.drawn = drawn;
  out.limited_by = limited_by;
  if (const std::string err = gl::select_clusters(viewer(scale), store.view(), out); !err.empty())
    throw std::runtime_error("select_clusters: " + err);
}

// Left-eye screen size of a triangle list's triangles: outside the view (every corner beyond
// one clip plane), under one pixel of area, or at least one pixel (what lavapipe rasterises
// into tiles and shades; the others end at triangle setup).
struct SizeClasses {
  std::uint64_t outside = 0, sub_pixel = 0, covering = 0;
};
SizeClasses size_classes(const gr::EyeView& view, const std::vector<float>& xyz,
                         const std::vector<std::uint32_t>& idx) {
  const glm::dmat4 vp = gr::projection_matrix(view.fov, view.near_m, view.far_m) * gr::view_matrix(view.pose);
  SizeClasses n;
  for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
    std::array<glm::dvec4, 3> c;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = idx[t + k];
      c[k] = vp * glm::dvec4(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0);
    }
    const auto all = [&](auto beyond) { return beyond(c[0]) && beyond(c[1]) && beyond(c[2]); };
    if (all([](const glm::dvec4& p) { return p.x < -p.w; }) || all([](const glm::dvec4& p) { return p.x > p.w; }) ||
        all([](const glm::dvec4& p) { return p.y < -p.w; }) || all([](const glm::dvec4& p) { return p.y > p.w; }) ||
        all([near = view.near_m](const glm::dvec4& p) { return p.w < near; })) {
      ++n.outside;
      continue;
    }
    if (c[0].w < view.near_m || c[1].w < view.near_m || c[2].w < view.near_m) {
      ++n.covering;  // crosses the near plane: clipped, and large on screen
      continue;
    }
    std::array<glm::dvec2, 3> px;
    for (int k = 0; k < 3; ++k) px[k] = {c[k].x / c[k].w * 0.5 * eye_width(), c[k].y / c[k].w * 0.5 * eye_height()};
    const glm::dvec2 u = px[1] - px[0], w = px[2] - px[0];
    (0.5 * std::abs(u.x * w.y - u.y * w.x) < 1.0 ? n.sub_pixel : n.covering) += 1;
  }
  return n;
}

std::vector<std::uint32_t> cut_indices(const gazelod::bake::ClusterBuildResult& built,
                                       const std::vector<std::uint8_t>& drawn) {
  std::vector<std::uint32_t> out;
  for (std::size_t c = 0; c < drawn.size(); ++c)
    if (drawn[c])
      out.insert(out.end(), built.indices.begin() + built.hierarchy.first_index[c],
                 built.indices.begin() + built.hierarchy.first_index[c] + built.hierarchy.index_count[c]);
  return out;
}

std::unique_ptr<Scene> build_scene() {
  auto s = std::make_unique<Scene>();
  const gazelod::bake::GeneratedMesh terrain = gazelod::bake::terrain_meshes({}).at(0);
  const gazelod::bake::ClusterBuildResult built =
      gazelod::bake::build_cluster_hierarchy(terrain.positions, terrain.indices);
  const gl::ClusterHierarchy& h = built.hierarchy;

  gl::ClusterStore store;
  store.add_mesh(h, {}, glm::dvec3(0.0), built.indices.size());
  std::vector<std::uint8_t> drawn(h.size()), limited_by(h.size());
  // Triangles grow with s (a larger s keeps finer detail): bisect for the target.
  double lo = 1e-4, hi = 1.0;
  for (int step = 0; step < 40; ++step) {
    const double mid = std::sqrt(lo * hi);
    select_cut(store, mid, drawn, limited_by);
    (cut_triangles(h, drawn) < kCutTriangles ? lo : hi) = mid;
  }
  // The hierarchy's top (every error visible at the smallest s): the same ground in the fewest
  // triangles, so the same pixels filled.
  select_cut(store, 1e-9, drawn, limited_by);
  const std::vector<std::uint8_t> top = drawn;
  s->scale = hi;
  select_cut(store, s->scale, drawn, limited_by);

  // Positions in their bounding sphere's unit frame (what a DrawItem places).
  const std::size_t nv = terrain.positions.size() / 3;
  glm::dvec3 lo_m(terrain.positions[0], terrain.positions[1], terrain.positions[2]), hi_m = lo_m;
  for (std::size_t v = 0; v < nv; ++v) {
    const glm::dvec3 p(terrain.positions[3 * v], terrain.positions[3 * v + 1], terrain.positions[3 * v + 2]);
    lo_m = glm::min(lo_m, p), hi_m = glm::max(hi_m, p);
  }
  const glm::dvec3 center = 0.5 * (lo_m + hi_m);
  double r2 = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    const glm::dvec3 p(terrain.positions[3 * v], terrain.positions[3 * v + 1], terrain.positions[3 * v + 2]);
    r2 = std::max(r2, glm::dot(p - center, p - center));
  }
  const double radius = std::sqrt(r2);
  std::vector<glm::vec3> unit(nv);
  for (std::size_t v = 0; v < nv; ++v)
    unit[v] = glm::vec3(
        (glm::dvec3(terrain.positions[3 * v], terrain.positions[3 * v + 1], terrain.positions[3 * v + 2]) - center) /
        radius);

  s->device = std::make_unique<gr::OffscreenDevice>(false);
  const std::uint32_t whole_mesh = s->meshes.add_mesh(unit, terrain.indices);
  const std::uint32_t first = s->meshes.add_cluster_mesh(unit, built.indices, h.first_index, h.index_count);
  s->meshes.upload(s->device->context());
  const glm::vec3 c(center);
  const auto r = static_cast<float>(radius);
  s->whole.push_back({c, r, whole_mesh, 0});
  s->whole_triangles = terrain.triangles();
  for (std::size_t k = 0; k < h.size(); ++k)
    if (drawn[k]) s->cut.push_back({c, r, first + static_cast<std::uint32_t>(k), h.depth[k]});
  s->cut_triangles = cut_triangles(h, drawn);
  for (std::size_t k = 0; k < h.size(); ++k)
    if (top[k]) s->coarse.push_back({c, r, first + static_cast<std::uint32_t>(k), h.depth[k]});

  const double half_h = 53.0 * std::numbers::pi / 180.0, half_v = 48.0 * std::numbers::pi / 180.0;
  const glm::dquat pitch = glm::angleAxis(-kPitchDownDeg * std::numbers::pi / 180.0, glm::dvec3(1, 0, 0));
  for (int e = 0; e < 2; ++e) {
    s->targets[e] = std::make_unique<gr::OffscreenTarget>(s->device->context(), eye_width(), eye_height());
    s->eyes[e] = std::make_unique<gr::FrameRenderer>(s->device->context(), s->meshes, s->targets[e]->target());
    s->views[e].fov = {-half_h, half_h, half_v, -half_v};
    s->views[e].pose.orientation = pitch;
    s->views[e].pose.position_m = {e == 0 ? -kHalfIpdM : kHalfIpdM, kEyeHeightM, 0.0};
  }
  std::printf("eyes %u x %u (GAZELOD_BENCH_EYE_DIVISOR %u)\n", eye_width(), eye_height(), eye_divisor());
  std::printf("terrain %llu triangles, %zu clusters, %u levels; cut at s = %.6g: %zu clusters, %llu triangles\n",
              static_cast<unsigned long long>(s->whole_triangles), h.size(), built.levels, s->scale, s->cut.size(),
              static_cast<unsigned long long>(s->cut_triangles));
  std::printf("left eye, triangles outside the view / under 1 px / covering >= 1 px:\n");
  const auto print = [&](const char* name, const std::vector<std::uint32_t>& idx) {
    const SizeClasses n = size_classes(s->views[0], terrain.positions, idx);
    std::printf("  %-6s %9llu %9llu %9llu\n", name, static_cast<unsigned long long>(n.outside),
                static_cast<unsigned long long>(n.sub_pixel), static_cast<unsigned long long>(n.covering));
  };
  print("Whole", terrain.indices);
  print("Coarse", cut_indices(built, top));
  print("Cut", cut_indices(built, drawn));
  return s;
}

Scene* scene() {
  static std::unique_ptr<Scene> s = build_scene();
  return s.get();
}

enum class Case { empty, coarse, whole, per_cluster, merged, merged_indirect, culled };
std::map<std::pair<Case, bool>, double> ms_of;  // what earlier cases measured, for the ratios

void run(benchmark::State& state, Case which) {
  Scene* s = nullptr;
  try {
    s = scene();
  } catch (const gr::RenderError& e) {
    state.SkipWithError(e.what());
    return;
  }
  const bool readback = state.range(0) != 0;
  const std::vector<gr::DrawItem> none;
  const std::vector<gr::DrawItem>& items = which == Case::empty    ? none
                                           : which == Case::coarse ? s->coarse
                                           : which == Case::whole  ? s->whole
                                                                   : s->cut;
  for (auto& eye : s->eyes) {
    eye->set_merge_draws(which != Case::per_cluster);
    eye->set_multi_draw(which == Case::merged_indirect || which == Case::culled);
    eye->set_cull_ranges(which == Case::culled);
  }
  const auto started = std::chrono::steady_clock::now();
  for (auto _ : state)
    for (int e = 0; e < 2; ++e) {
      s->eyes[e]->draw(0, s->views[e], items);
      if (readback) benchmark::DoNotOptimize(s->eyes[e]->read_back(0));
    }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count() /
                    static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
  ms_of[{which, readback}] = ms;
  std::uint64_t triangles = 0, draws = 0, commands = 0;
  for (const auto& eye : s->eyes) {
    triangles += eye->triangles_last_frame();
    draws += eye->draws_last_frame();
    commands += eye->draw_commands_last_frame();
  }
  const auto earlier = [&](Case c) {
    const auto it = ms_of.find({c, readback});
    return it == ms_of.end() ? 0.0 : it->second;
  };
  const double whole_ms = earlier(Case::whole);
  const auto above = [&](double base_ms) {
    return whole_ms > 0.0 && base_ms > 0.0 && whole_ms > base_ms ? (ms - base_ms) / (whole_ms - base_ms) : 0.0;
  };
  state.counters["ms_per_frame"] = ms;
  state.counters["x_whole"] = whole_ms > 0.0 ? ms / whole_ms : 0.0;
  state.counters["above_empty_x_whole"] = above(earlier(Case::empty));
  state.counters["above_coarse_x_whole"] = above(earlier(Case::coarse));
  // Pixels the scene covers in the left eye (outside the timing): fill differs only by these.
  const gr::RgbaImage img = s->eyes[0]->read_back(0);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 4)
    covered +=
        img.pixels[i] != img.pixels[0] || img.pixels[i + 1] != img.pixels[1] || img.pixels[i + 2] != img.pixels[2];
  state.counters["covered_px"] = static_cast<double>(covered);
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["draws"] = static_cast<double>(draws);
  state.counters["commands"] = static_cast<double>(commands);
}

// Real time: the work happens on lavapipe's threads, not the calling one.
void BM_Frame(benchmark::State& state, Case which) {
  run(state, which);
}

// The same cases one frame each in turn, the order rotating every round, medians per case:
// on a machine shared with other work the load drifts over a run of separate cases, and a
// drift then reads as a difference between them.
void BM_Interleaved(benchmark::State& state) {
  Scene* s = nullptr;
  try {
    s = scene();
  } catch (const gr::RenderError& e) {
    state.SkipWithError(e.what());
    return;
  }
  struct Entry {
    const char* name;
    Case which;
    bool readback;
  };
  const Entry entries[] = {{"Empty", Case::empty, false},
                           {"EmptyReadback", Case::empty, true},
                           {"Coarse", Case::coarse, false},
                           {"Whole", Case::whole, false},
                           {"PerCluster", Case::per_cluster, false},
                           {"Merged", Case::merged, false},
                           {"MergedIndirect", Case::merged_indirect, false},
                           {"Culled", Case::culled, false}};
  constexpr std::size_t kCases = std::size(entries);
  const auto rounds = static_cast<std::size_t>(state.range(0));
  std::array<std::vector<double>, kCases> ms;
  std::array<std::uint64_t, kCases> triangles{}, commands{};
  const std::vector<gr::DrawItem> none;
  for (auto _ : state)
    for (std::size_t round = 0; round < rounds; ++round)
      for (std::size_t k = 0; k < kCases; ++k) {
        const std::size_t i = (k + round) % kCases;
        const Entry& e = entries[i];
        const std::vector<gr::DrawItem>& items = e.which == Case::empty    ? none
                                                 : e.which == Case::coarse ? s->coarse
                                                 : e.which == Case::whole  ? s->whole
                                                                           : s->cut;
        for (auto& eye : s->eyes) {
          eye->set_merge_draws(e.which != Case::per_cluster);
          eye->set_multi_draw(e.which == Case::merged_indirect || e.which == Case::culled);
          eye->set_cull_ranges(e.which == Case::culled);
        }
        const auto started = std::chrono::steady_clock::now();
        for (int eye = 0; eye < 2; ++eye) {
          s->eyes[eye]->draw(0, s->views[eye], items);
          if (e.readback) benchmark::DoNotOptimize(s->eyes[eye]->read_back(0));
        }
        ms[i].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count());
        triangles[i] = s->eyes[0]->triangles_last_frame() + s->eyes[1]->triangles_last_frame();
        commands[i] = s->eyes[0]->draw_commands_last_frame() + s->eyes[1]->draw_commands_last_frame();
      }
  // Medians, and minima: other work on the machine only ever adds time, so the fastest frame
  // is the closest to the case's own cost.
  std::array<double, kCases> median{}, fastest{};
  for (std::size_t i = 0; i < kCases; ++i) {
    std::vector<double>& v = ms[i];
    std::sort(v.begin(), v.end());
    median[i] = v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    fastest[i] = v.empty() ? 0.0 : v.front();
    state.counters[std::string(entries[i].name) + "_ms"] = median[i];
  }
  for (const auto* stat : {&median, &fastest}) {
    const std::array<double, kCases>& t = *stat;
    const double empty = t[0], coarse = t[2], whole = t[3];
    std::printf("\n%zu rounds, %s ms per frame (both eyes):\n", rounds, stat == &median ? "median" : "fastest");
    std::printf("%-15s %10s %10s %10s %8s %12s %12s\n", "case", "ms", "triangles", "commands", "x_whole", "above_empty",
                "above_coarse");
    for (std::size_t i = 0; i < kCases; ++i)
      std::printf("%-15s %10.1f %10llu %10llu %8.3f %12.3f %12.3f\n", entries[i].name, t[i],
                  static_cast<unsigned long long>(triangles[i]), static_cast<unsigned long long>(commands[i]),
                  t[i] / whole, (t[i] - empty) / (whole - empty), (t[i] - coarse) / (whole - coarse));
  }
}

}  // namespace

#define GAZELOD_FRAME_CASE(name, which) \
  BENCHMARK_CAPTURE(BM_Frame, name, which)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0)
GAZELOD_FRAME_CASE(Empty, Case::empty);
GAZELOD_FRAME_CASE(Coarse, Case::coarse);
GAZELOD_FRAME_CASE(Whole, Case::whole);
GAZELOD_FRAME_CASE(PerCluster, Case::per_cluster);
GAZELOD_FRAME_CASE(Merged, Case::merged);
GAZELOD_FRAME_CASE(MergedIndirect, Case::merged_indirect);
GAZELOD_FRAME_CASE(Culled, Case::culled);
// Arg: rounds.
BENCHMARK(BM_Interleaved)->Arg(40)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
