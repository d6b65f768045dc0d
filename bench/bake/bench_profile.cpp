// SPDX-License-Identifier: Apache-2.0
// The rendered perceptual profile (bake --profile, Reddy 1998 section 3.3) against the plain bake:
// what 6 and 18 viewpoints cost, and what they change. Before the timings, main() bakes a few
// generated meshes with 6 and 18 viewpoints and prints (1) per level the geometric figure
// D / (2e), the rendered ones and their ratio, with the correlation of their logarithms, and
// (2) for a grid of distances x eccentricities (static viewer, lod::select_lods) how often the
// chosen LOD differs between geometric and rendered-18 figures, and between 6 and 18 viewpoints.
// Timings: BM_Bake/0 is the plain in-memory bake (same-process baseline), /6 and /18 add the
// profile (lavapipe device creation included, as in one `gazelod bake --profile` run).
#include "bake/bake.hpp"
#include "lod/object_set.hpp"
#include "lod/select.hpp"
#include "tests/bake/test_meshes.hpp"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace gazelod::bake {
namespace {

// An icosphere with radial bumps: r = R (1 + a sin(6x) sin(6y) sin(6z)) (as in profile_test).
testing::TestMesh bumpy(int subdivisions, double radius_m, double amplitude) {
  testing::TestMesh m = testing::icosphere(subdivisions, radius_m);
  for (std::size_t i = 0; i + 2 < m.positions.size(); i += 3) {
    const glm::dvec3 p = glm::dvec3(m.positions[i], m.positions[i + 1], m.positions[i + 2]) / radius_m;
    const double s = 1.0 + amplitude * std::sin(6 * p.x) * std::sin(6 * p.y) * std::sin(6 * p.z);
    for (int a = 0; a < 3; ++a) m.positions[i + a] = float(p[a] * s * radius_m);
  }
  return m;
}

BakeReport bake(const testing::TestMesh& m, int viewpoints) {
  tinygltf::Model model = testing::single_mesh_model(m);
  BakeOptions o;
  o.profile_viewpoints = viewpoints;
  return bake_model(model, o);
}

void BM_Bake(benchmark::State& state) {
  const tinygltf::Model model = testing::single_mesh_model(bumpy(int(state.range(1)), 0.5, 0.1));
  BakeOptions o;
  o.profile_viewpoints = int(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    tinygltf::Model copy = model;
    state.ResumeTiming();
    benchmark::DoNotOptimize(bake_model(copy, o));
  }
}
BENCHMARK(BM_Bake)->ArgsProduct({{0, 6, 18}, {4, 5}})->Unit(benchmark::kMillisecond)->UseRealTime();

enum Figure { kGeometric, kRendered6, kRendered18 };

std::vector<lod::LodLevel> chain_of(const MeshReport& g, const MeshReport& r6, const MeshReport& r18, Figure f) {
  std::vector<lod::LodLevel> levels;
  for (std::size_t k = 0; k < g.levels.size(); ++k) {
    lod::LodLevel l;
    l.triangles = g.levels[k].triangles;
    l.detail = k == 0            ? 0.0
               : f == kGeometric ? g.levels[k].detail_cycles_per_diameter
               : f == kRendered6 ? r6.levels[k].rendered_cycles_per_diameter
                                 : r18.levels[k].rendered_cycles_per_diameter;
    levels.push_back(l);
  }
  return levels;
}

// Chosen levels on the grid of distances (in radii) x eccentricities for one detail figure.
std::vector<std::uint8_t> choices(const std::vector<lod::LodLevel>& levels, double radius_m) {
  lod::ObjectStore store;
  const double dist_radii[] = {2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256};
  const double ecc_deg[] = {0, 2, 5, 8, 10, 15, 20, 25, 30, 40, 50, 60};
  for (double d : dist_radii)
    for (double e : ecc_deg) {
      const double a = e * std::numbers::pi / 180.0;
      store.add(glm::dvec3(std::sin(a), 0.0, -std::cos(a)) * d * radius_m, radius_m, glm::dvec3(0.0), levels);
    }
  const std::size_t n = store.size();
  std::vector<std::uint8_t> lod(n), by(n), s(n), e(n), v(n);
  const lod::Decisions out{lod, by, s, e, v};
  if (std::string err = lod::select_lods(lod::Viewer{}, store.view(), out); !err.empty())
    std::fprintf(stderr, "select_lods: %s\n", err.c_str());
  return lod;
}

int differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  int n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

void agreement_tables() {
  struct Named {
    const char* name;
    testing::TestMesh mesh;
  };
  const std::vector<Named> meshes{{"icosphere(4)", testing::icosphere(4, 0.5)},
                                  {"bumpy(4, a=0.05)", bumpy(4, 0.5, 0.05)},
                                  {"bumpy(4, a=0.15)", bumpy(4, 0.5, 0.15)},
                                  {"bumpy(5, a=0.10)", bumpy(5, 0.5, 0.10)},
                                  {"wavy grid 64", testing::grid(64, 1.0, 0.05)}};
  std::printf(
      "| mesh | level | triangles | geometric D/(2e) | rendered, 18 views | rendered, 6 views | rendered18 / geometric "
      "|\n|---|---|---|---|---|---|---|\n");
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  int pts = 0, cells = 0, diff_geo = 0, diff_6 = 0;
  for (const Named& m : meshes) {
    const MeshReport r6 = bake(m.mesh, 6).meshes.at(0), r18 = bake(m.mesh, 18).meshes.at(0);
    for (std::size_t k = 1; k < r18.levels.size(); ++k) {
      const double g = r18.levels[k].detail_cycles_per_diameter, r = r18.levels[k].rendered_cycles_per_diameter;
      std::printf("| %s | %zu | %u | %.2f | %.2f | %.2f | %.2f |\n", m.name, k, r18.levels[k].triangles, g, r,
                  r6.levels[k].rendered_cycles_per_diameter, r / g);
      const double x = std::log10(g), y = std::log10(r);
      sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, ++pts;
    }
    const double radius_m = r18.diameter_m / 2.0;
    const auto g = choices(chain_of(r18, r6, r18, kGeometric), radius_m);
    const auto c6 = choices(chain_of(r18, r6, r18, kRendered6), radius_m);
    const auto c18 = choices(chain_of(r18, r6, r18, kRendered18), radius_m);
    cells += int(g.size()), diff_geo += differing(g, c18), diff_6 += differing(c6, c18);
  }
  const double cov = sxy - sx * sy / pts, vx = sxx - sx * sx / pts, vy = syy - sy * sy / pts;
  std::printf("\nPearson r of log10(geometric) vs log10(rendered, 18 views): %.3f over %d levels\n",
              vx > 0 && vy > 0 ? cov / std::sqrt(vx * vy) : NAN, pts);
  std::printf(
      "LOD choices over %d object placements (15 distances x 12 eccentricities x %zu meshes):\n"
      "  geometric vs rendered-18 differ: %d (%.1f%%)\n  rendered-6 vs rendered-18 differ: %d (%.1f%%)\n\n",
      cells, meshes.size(), diff_geo, 100.0 * diff_geo / cells, diff_6, 100.0 * diff_6 / cells);
}

}  // namespace
}  // namespace gazelod::bake

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  gazelod::bake::agreement_tables();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
