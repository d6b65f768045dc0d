// The --clusters bake driver: per primitive extract, build, store; progress, timing, summary
// (cluster_bake.hpp).
#include "bake/cluster_bake.hpp"

#include "bake/bake_error.hpp"
#include "bake/cluster_lod_gltf.hpp"
#include "bake/glb_write.hpp"
#include "bake/gltf_load.hpp"
#include "bake/gltf_pack.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/node_world.hpp"
#include "bake/shared_positions.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gazelod::bake {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double per_second(double n, double seconds) { return seconds > 0.0 ? n / seconds : 0.0; }

ClusterPrimitiveReport bake_primitive(tinygltf::Model& m, int mesh, int primitive, const PrimitiveGeometry& g,
                                      std::span<const std::uint8_t> locked, const ClusterBakeOptions& o,
                                      std::uint64_t& input_triangles) {
  ClusterPrimitiveReport rep;
  rep.mesh = mesh, rep.primitive = primitive;
  rep.label = primitive_label(m, mesh, primitive);
  input_triangles += g.indices.size() / 3;
  ClusterBuildOptions b = o.build;
  b.label = rep.label;
  b.locked_vertices = locked;
  rep.shared_vertices = static_cast<std::size_t>(std::count_if(locked.begin(), locked.end(), [](std::uint8_t f) { return f != 0; }));
  const auto t0 = Clock::now();
  const ClusterBuildResult r = build_cluster_hierarchy(g.positions_xyz, g.indices, b);
  rep.build_seconds = seconds_since(t0);
  rep.source_triangles = r.source_triangles;
  rep.degenerate_triangles = r.degenerate_triangles;
  rep.folded_triangles = r.folded_triangles;
  rep.groups_across_seams = r.groups_across_seams;
  rep.clusters = r.hierarchy.size();
  rep.groups = r.groups;
  rep.levels = r.levels;
  rep.stored_triangles = r.indices.size() / 3;
  for (std::size_t c = 0; c < r.hierarchy.size(); ++c)
    if (r.hierarchy.parent_error_m[c] == lod::kNoParentError)
      ++rep.top_clusters, rep.top_triangles += r.hierarchy.index_count[c] / 3;
  if (rep.clusters > 0)
    write_cluster_lod(m, mesh, primitive, r.hierarchy, r.indices, g.positions_xyz.size() / 3);
  return rep;
}

}  // namespace

std::vector<std::vector<std::vector<std::uint8_t>>> meeting_vertices(
    const tinygltf::Model& m, const std::vector<std::vector<PrimitiveGeometry>>& geometry) {
  const std::vector<MeshInstance> instances = mesh_instances(m);
  std::vector<PlacedPrimitive> placed;
  for (std::size_t mi = 0; mi < geometry.size(); ++mi)
    for (const PrimitiveGeometry& g : geometry[mi]) {
      PlacedPrimitive pp{g.positions_xyz, g.indices, {}};
      for (const MeshInstance& i : instances)
        if (i.mesh == static_cast<int>(mi)) pp.world.push_back(i.world);
      placed.push_back(std::move(pp));
    }
  std::vector<std::vector<std::uint8_t>> flat = shared_positions(placed);
  std::vector<std::vector<std::vector<std::uint8_t>>> out(geometry.size());
  std::size_t at = 0;
  for (std::size_t mi = 0; mi < geometry.size(); ++mi)
    for (std::size_t p = 0; p < geometry[mi].size(); ++p) out[mi].push_back(std::move(flat[at++]));
  return out;
}

ClusterBakeReport bake_clusters_model(tinygltf::Model& m, const ClusterBakeOptions& o) {
  const auto t0 = Clock::now();
  if (std::string e = validate_cluster_options(o.build); !e.empty()) throw BakeError(e);
  ClusterBakeReport report;
  report.warnings = pack_single_buffer(m);
  std::vector<bool> used(m.meshes.size(), false);
  for (const tinygltf::Node& n : m.nodes)
    if (n.mesh >= 0 && static_cast<std::size_t>(n.mesh) < m.meshes.size())
      used[static_cast<std::size_t>(n.mesh)] = true;
  report.meshes = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  // Every used primitive's geometry first: where meshes meet is locked in each of them.
  std::vector<std::vector<PrimitiveGeometry>> geometry(m.meshes.size());
  for (std::size_t mi = 0; mi < m.meshes.size(); ++mi)
    if (used[mi])
      for (std::size_t p = 0; p < m.meshes[mi].primitives.size(); ++p)
        geometry[mi].push_back(extract_primitive(m, static_cast<int>(mi), static_cast<int>(p)));
  const auto shared = o.build.lock_open_borders ? std::vector<std::vector<std::vector<std::uint8_t>>>(m.meshes.size())
                                                : meeting_vertices(m, geometry);
  std::size_t done = 0;
  for (std::size_t mi = 0; mi < m.meshes.size(); ++mi) {
    if (!used[mi]) continue;
    const auto mesh = static_cast<int>(mi);
    const std::size_t prims = m.meshes[mi].primitives.size();
    if (o.progress)
      o.progress("bake: mesh " + std::to_string(done + 1) + "/" + std::to_string(report.meshes) + " " +
                 mesh_label(m, mesh) + " (" + std::to_string(prims) + " primitives) ...");
    const auto tm = Clock::now();
    std::size_t tris = 0, degenerate = 0, clusters = 0, top = 0;
    std::uint32_t levels = 0;
    double build_s = 0.0;
    for (std::size_t p = 0; p < prims; ++p) {
      const std::span<const std::uint8_t> locked = shared[mi].empty() ? std::span<const std::uint8_t>{} : shared[mi][p];
      ClusterPrimitiveReport rep =
          bake_primitive(m, mesh, static_cast<int>(p), geometry[mi][p], locked, o, report.input_triangles);
      report.shared_vertices += rep.shared_vertices, report.folded_triangles += rep.folded_triangles;
      report.groups_across_seams += rep.groups_across_seams;
      tris += rep.source_triangles + rep.degenerate_triangles, degenerate += rep.degenerate_triangles;
      clusters += rep.clusters, top += rep.top_triangles, levels = std::max(levels, rep.levels);
      build_s += rep.build_seconds;
      if (rep.clusters == 0)
        report.warnings.push_back(rep.label + ": no triangles left, no cluster hierarchy");
      else
        report.primitives.push_back(std::move(rep));
    }
    report.build_seconds += build_s;
    std::vector<PrimitiveGeometry>().swap(geometry[mi]);
    ++done;
    if (o.progress) {
      char line[320];
      std::snprintf(line, sizeof line,
                    "bake: mesh %zu/%zu done: %zu triangles -> %zu clusters in %u levels, top %zu "
                    "triangles%s in %ld ms (hierarchy %.3g input triangles/s); overall %zu%%",
                    done, report.meshes, tris, clusters, levels, top,
                    degenerate ? (", " + std::to_string(degenerate) + " degenerate dropped").c_str() : "",
                    std::lround(seconds_since(tm) * 1000.0), per_second(double(tris), build_s),
                    100 * done / std::max<std::size_t>(report.meshes, 1));
      o.progress(line);
    }
  }
  std::size_t degenerate = 0, with = 0;
  for (const ClusterPrimitiveReport& p : report.primitives)
    degenerate += p.degenerate_triangles, with += p.degenerate_triangles > 0;
  if (degenerate > 0)
    report.warnings.push_back(std::to_string(degenerate) + " degenerate triangles (two corners at one "
                              "position) dropped in " + std::to_string(with) +
                              " primitives (column 'degenerate')");
  report.seconds = seconds_since(t0);
  return report;
}

ClusterBakeReport bake_clusters_file(const std::string& in, const std::string& out,
                                     const ClusterBakeOptions& o) {
  const auto t0 = Clock::now();
  LoadedGltf loaded = load_gltf(in);
  ClusterBakeReport report;
  try {
    report = bake_clusters_model(loaded.model, o);
  } catch (const BakeError& e) {
    throw BakeError(in + ": " + e.what());
  }
  report.warnings.insert(report.warnings.begin(), loaded.warnings.begin(), loaded.warnings.end());
  if (o.progress) o.progress("bake: writing " + out);
  write_glb_atomic(loaded.model, out);
  report.seconds = seconds_since(t0);
  return report;
}

std::string format_cluster_summary(const ClusterBakeReport& r) {
  std::ostringstream s;
  char line[256];
  std::snprintf(line, sizeof line, "%-34s %9s %10s %8s %6s %6s %8s %9s %9s %8s\n", "primitive",
                "triangles", "degenerate", "clusters", "levels", "groups", "top_tris", "stored",
                "build_ms", "tris/s");
  s << line;
  for (const ClusterPrimitiveReport& p : r.primitives) {
    std::string name = p.label;
    if (name.size() > 34) name = name.substr(0, 31) + "...";
    std::snprintf(line, sizeof line, "%-34s %9zu %10zu %8zu %6u %6zu %8zu %9zu %9.1f %8.3g\n",
                  name.c_str(), p.source_triangles, p.degenerate_triangles, p.clusters, p.levels,
                  p.groups, p.top_triangles, p.stored_triangles, p.build_seconds * 1000.0,
                  per_second(double(p.source_triangles + p.degenerate_triangles), p.build_seconds));
    s << line;
  }
  std::snprintf(line, sizeof line,
                "total: %zu meshes, %zu primitives with GAZELOD_cluster_lod, %llu input triangles, "
                "hierarchy %.3f s (%.3g input triangles/s), %.3f s in all\n",
                r.meshes, r.primitives.size(), static_cast<unsigned long long>(r.input_triangles),
                r.build_seconds, per_second(double(r.input_triangles), r.build_seconds), r.seconds);
  s << line;
  if (r.shared_vertices > 0)
    s << "kept at every level: " << r.shared_vertices
      << " vertices where primitives meet (open borders elsewhere are simplified)\n";
  if (r.folded_triangles > 0)
    s << "folded over by meshoptimizer 0.18's simplifier (facing against the surface they replace): "
      << r.folded_triangles << " of the stored simplified triangles\n";
  if (r.groups_across_seams > 0)
    s << "simplified across attribute seams (stuck with them kept; --keep-seams: never): " << r.groups_across_seams
      << " groups\n";
  for (const std::string& w : r.warnings) s << "warning: " << w << "\n";
  return s.str();
}

}  // namespace gazelod::bake
