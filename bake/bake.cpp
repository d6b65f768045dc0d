// SPDX-License-Identifier: Apache-2.0
// The bake driver: per-mesh chains from per-primitive chains, progress, timing (bake.hpp).
#include "bake/bake.hpp"

#include "auxiliary/text.hpp"

#include "bake/bake_error.hpp"
#include "bake/detail.hpp"
#include "bake/gltf_load.hpp"
#include "bake/gltf_pack.hpp"
#include "bake/glb_write.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/msft_lod_writer.hpp"
#include "bake/profile_render.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

namespace gazelod::bake {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Bounding sphere about the box centre (diameter) and the largest box side (meshopt's scale).
void bounds(const std::vector<PrimitiveGeometry>& prims, double& diameter_m, double& extent_m) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto& g : prims)
    for (std::size_t i = 0; i < g.positions_xyz.size(); ++i)
      lo[i % 3] = std::min(lo[i % 3], double(g.positions_xyz[i])),
             hi[i % 3] = std::max(hi[i % 3], double(g.positions_xyz[i]));
  diameter_m = extent_m = 0.0;
  if (!(lo[0] <= hi[0])) return;  // no vertices
  const double c[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  double r2 = 0.0;
  for (const auto& g : prims)
    for (std::size_t i = 0; i + 2 < g.positions_xyz.size(); i += 3) {
      const double dx = g.positions_xyz[i] - c[0], dy = g.positions_xyz[i + 1] - c[1],
                   dz = g.positions_xyz[i + 2] - c[2];
      r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
    }
  diameter_m = 2.0 * std::sqrt(r2);
  extent_m = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

// One mesh: simplify each primitive, then combine level by level; a level that does not get
// below the previous one in total, or loses every triangle, ends the chain.
// Renders the chain (all primitives as one mesh) and stores each level's rendered figure.
void profile_mesh(Profiler& profiler, const std::vector<PrimitiveGeometry>& geo, MeshChain& chain) {
  std::vector<float> xyz;
  std::vector<std::vector<std::uint32_t>> levels(chain.levels.size());
  std::vector<std::uint32_t> base;
  for (const auto& g : geo) {
    base.push_back(static_cast<std::uint32_t>(xyz.size() / 3));
    xyz.insert(xyz.end(), g.positions_xyz.begin(), g.positions_xyz.end());
    for (std::uint32_t i : g.indices) levels[0].push_back(base.back() + i);
  }
  for (std::size_t k = 1; k < chain.levels.size(); ++k)
    for (std::size_t p = 0; p < geo.size(); ++p)
      for (std::uint32_t i : chain.levels[k].primitive_indices[p]) levels[k].push_back(base[p] + i);
  const std::vector<LevelProfile> prof = profiler.profile(xyz, levels);
  for (std::size_t k = 0; k < chain.levels.size(); ++k)
    chain.levels[k].rendered_cycles_per_diameter = prof[k].rendered_cycles_per_diameter;
}

MeshChain bake_mesh(const tinygltf::Model& m, int mesh, const ChainOptions& o, Profiler* profiler, MeshReport& rep) {
  const auto& prims = m.meshes[static_cast<std::size_t>(mesh)].primitives;
  std::vector<PrimitiveGeometry> geo;
  for (std::size_t p = 0; p < prims.size(); ++p) geo.push_back(extract_primitive(m, mesh, static_cast<int>(p)));
  double extent_m = 0.0;
  MeshChain chain;
  bounds(geo, chain.diameter_m, extent_m);
  std::vector<PrimitiveChain> pc;
  for (const auto& g : geo) pc.push_back(simplify_chain(g.positions_xyz, g.indices, o));

  for (std::size_t k = 0; k <= o.ratios.size(); ++k) {
    MeshLevel l;
    for (std::size_t p = 0; p < pc.size(); ++p) {
      const SimplifiedLevel& s = pc[p].levels[k];
      l.triangles += static_cast<std::uint32_t>(s.indices.size() / 3);
      l.vertices += s.vertices;
      l.error_m = std::max(l.error_m, s.error_m);
      l.sloppy = l.sloppy || s.sloppy;
      if (k > 0) l.primitive_indices.push_back(s.indices);
    }
    if (k > 0) {
      const MeshLevel& prev = chain.levels.back();
      if (l.triangles == 0 || l.triangles >= prev.triangles) {
        rep.note = "stops at level " + std::to_string(k - 1) + ": cannot get below " + std::to_string(prev.triangles) +
                   " triangles" + (l.triangles == 0 ? " without losing every triangle" : "");
        break;
      }
      l.error_m = std::max(l.error_m, prev.error_m);
    }
    l.error_relative = extent_m > 0.0 ? l.error_m / extent_m : 0.0;
    chain.levels.push_back(std::move(l));
  }
  if (profiler != nullptr && chain.levels.size() > 1) {
    const auto tp = Clock::now();
    profile_mesh(*profiler, geo, chain);
    rep.profile_seconds = seconds_since(tp);
  }
  rep.primitives = prims.size();
  rep.diameter_m = chain.diameter_m;
  for (std::size_t k = 0; k < chain.levels.size(); ++k) {
    const MeshLevel& l = chain.levels[k];
    rep.levels.push_back({l.triangles, l.vertices, l.error_relative, l.error_m,
                          k == 0 ? 0.0 : detail_cycles_per_diameter(chain.diameter_m, l.error_m), l.sloppy,
                          l.rendered_cycles_per_diameter});
  }
  return chain;
}

}  // namespace

std::vector<double> ratios_for_levels(int levels) {
  std::vector<double> r;
  for (int k = 1; k < levels; ++k) r.push_back(std::pow(0.25, k));
  return r;
}

BakeReport bake_model(tinygltf::Model& m, const BakeOptions& o) {
  const auto t0 = Clock::now();
  if (std::string e = validate_chain_options(o.chain); !e.empty()) throw BakeError(e);
  BakeReport report;
  report.warnings = pack_single_buffer(m);

  std::vector<bool> used(m.meshes.size(), false);
  for (const tinygltf::Node& n : m.nodes)
    if (n.mesh >= 0 && static_cast<std::size_t>(n.mesh) < m.meshes.size())
      used[static_cast<std::size_t>(n.mesh)] = true;
  const auto total = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));

  if (o.profile_viewpoints != 0 && o.profile_viewpoints != 6 && o.profile_viewpoints != 18)
    throw BakeError("profile: viewpoints must be 0 (off), 6 or 18, got " + std::to_string(o.profile_viewpoints));
  std::unique_ptr<Profiler> profiler;
  if (o.profile_viewpoints != 0 && total > 0)
    profiler = std::make_unique<Profiler>(ProfileOptions{o.profile_viewpoints});
  // Every level of a file of degenerate triangles would be written (the cluster bake refuses it
  // and `run --scene` has nothing to draw): the same refusal here.
  std::size_t area = 0;
  for (std::size_t mi = 0; mi < m.meshes.size() && area == 0; ++mi)
    if (used[mi])
      for (std::size_t p = 0; p < m.meshes[mi].primitives.size() && area == 0; ++p)
        area += count_area_triangles(extract_primitive(m, static_cast<int>(mi), static_cast<int>(p)));
  if (area == 0) throw BakeError(kNothingLeftToBake);
  std::vector<MeshChain> chains(m.meshes.size());
  std::size_t done = 0;
  for (std::size_t mi = 0; mi < m.meshes.size(); ++mi) {
    if (!used[mi]) continue;
    const auto tm = Clock::now();
    MeshReport rep;
    rep.mesh = static_cast<int>(mi);
    rep.name = m.meshes[mi].name;
    if (o.progress)
      o.progress("bake: mesh " + std::to_string(done + 1) + "/" + std::to_string(total) + " " +
                 mesh_label(m, rep.mesh) + " (" +
                 aux::counted(m.meshes[mi].primitives.size(), "primitive", "primitives") + ") ...");
    chains[mi] = bake_mesh(m, rep.mesh, o.chain, profiler.get(), rep);
    rep.seconds = seconds_since(tm);
    report.input_triangles += rep.levels.empty() ? 0 : rep.levels[0].triangles;
    ++done;
    if (o.progress) {
      std::ostringstream s;
      s << "bake: mesh " << done << "/" << total << " done:";
      for (std::size_t k = 0; k < rep.levels.size(); ++k) s << (k ? " -> " : " ") << rep.levels[k].triangles;
      s << " triangles in " << std::lround(rep.seconds * 1000.0) << " ms; overall "
        << (100 * done / std::max<std::size_t>(total, 1)) << "%";
      if (!rep.note.empty()) s << " (" << rep.note << ")";
      o.progress(s.str());
    }
    report.meshes.push_back(std::move(rep));
  }
  write_msft_lod(m, chains);
  for (const tinygltf::Node& n : m.nodes) report.lod_nodes += n.extensions.count("MSFT_lod");
  report.seconds = seconds_since(t0);
  return report;
}

BakeReport bake_file(const std::string& in, const std::string& out, const BakeOptions& o) {
  const auto t0 = Clock::now();
  LoadedGltf loaded = load_gltf(in, o.load);
  refuse_output_over_input(in, loaded, out);  // before the bake, not after its minutes
  BakeReport report;
  try {
    report = bake_model(loaded.model, o);
  } catch (const BakeError& e) {
    throw BakeError(in + ": " + e.what());
  }
  report.warnings.insert(report.warnings.begin(), loaded.warnings.begin(), loaded.warnings.end());
  if (o.progress) o.progress("bake: writing " + out);
  write_glb_atomic(loaded.model, out);
  report.seconds = seconds_since(t0);
  return report;
}

}  // namespace gazelod::bake
