// SPDX-License-Identifier: Apache-2.0
// The --clusters bake driver: per primitive extract, build, store; progress, timing, summary
// (cluster_bake.hpp).
#include "bake/cluster/cluster_bake.hpp"

#include "auxiliary/text.hpp"

#include "bake/bake_error.hpp"
#include "bake/cluster/cluster_lod_gltf.hpp"
#include "bake/glb_write.hpp"
#include "bake/gltf_load.hpp"
#include "bake/gltf_pack.hpp"
#include "bake/mesh_extract.hpp"
#include "bake/node_world.hpp"
#include "bake/parallel_for.hpp"
#include "bake/cluster/shared_positions.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <optional>
#include <sstream>

namespace gazelod::bake {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double per_second(double n, double seconds) {
  return seconds > 0.0 ? n / seconds : 0.0;
}

// A primitive of at least this many triangles is built alone with every thread (its levels
// have groups enough for them); smaller ones are built side by side, one thread each, which on
// many small meshes (a city's blocks, a CAD model's parts) keeps the cores busy where a single
// mesh's top levels have too few groups.
constexpr std::size_t kAloneFromTriangles = std::size_t{1} << 17;

// One primitive's hierarchy and its report (all but the storing).
struct BuiltPrimitive {
  ClusterPrimitiveReport rep;
  ClusterBuildResult result;
};

BuiltPrimitive build_primitive(const tinygltf::Model& m, int mesh, int primitive, const PrimitiveGeometry& g,
                               std::span<const std::uint8_t> locked, ClusterBuildOptions b) {
  BuiltPrimitive out;
  ClusterPrimitiveReport& rep = out.rep;
  rep.mesh = mesh, rep.primitive = primitive;
  rep.label = primitive_label(m, mesh, primitive);
  b.label = rep.label;
  b.locked_vertices = locked;
  rep.shared_vertices =
      static_cast<std::size_t>(std::count_if(locked.begin(), locked.end(), [](std::uint8_t f) { return f != 0; }));
  const auto t0 = Clock::now();
  out.result = build_cluster_hierarchy(g.positions_xyz, g.indices, b);
  const ClusterBuildResult& r = out.result;
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
  return out;
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
  // Every used primitive's geometry first: where meshes meet is locked in each of them. Points
  // and lines stay as they are (no geometry, no task), said in a warning.
  std::vector<std::vector<PrimitiveGeometry>> geometry(m.meshes.size());
  for (std::size_t mi = 0; mi < m.meshes.size(); ++mi)
    if (used[mi])
      for (std::size_t p = 0; p < m.meshes[mi].primitives.size(); ++p) {
        const auto mesh = static_cast<int>(mi), prim = static_cast<int>(p);
        if (draws_triangles(m.meshes[mi].primitives[p])) {
          geometry[mi].push_back(extract_primitive(m, mesh, prim));
          continue;
        }
        check_carried_accessors(m, mesh, prim);
        geometry[mi].emplace_back();
        report.warnings.push_back(primitive_label(m, mesh, prim) + ": " + mode_label(m.meshes[mi].primitives[p].mode) +
                                  " kept as it is (only triangles get a cluster hierarchy)");
      }
  const auto shared = o.build.lock_open_borders ? std::vector<std::vector<std::vector<std::uint8_t>>>(m.meshes.size())
                                                : meeting_vertices(m, geometry);
  // The primitives to build, in mesh order; large ones first, alone, then the rest side by side.
  struct Task {
    std::size_t mesh, primitive;
  };
  std::vector<Task> tasks;
  for (std::size_t mi = 0; mi < m.meshes.size(); ++mi)
    for (std::size_t p = 0; p < geometry[mi].size(); ++p)
      if (draws_triangles(m.meshes[mi].primitives[p])) tasks.push_back({mi, p});
  if (tasks.empty())
    throw BakeError(report.meshes == 0 ? "nothing to bake: no node uses a mesh"
                                       : "nothing to bake: the meshes the nodes use have no triangle primitive");
  for (const Task& t : tasks) report.input_triangles += geometry[t.mesh][t.primitive].indices.size() / 3;
  const auto is_alone = [&](const Task& t) {
    return geometry[t.mesh][t.primitive].indices.size() / 3 >= kAloneFromTriangles;
  };
  std::vector<std::size_t> alone, side_by_side;
  for (std::size_t i = 0; i < tasks.size(); ++i) (is_alone(tasks[i]) ? alone : side_by_side).push_back(i);

  // Finished builds are stored in task order (so the file is the same for any thread count),
  // each as soon as every earlier one is; progress per mesh as its last primitive is built.
  std::vector<std::optional<BuiltPrimitive>> built(tasks.size());
  std::vector<ClusterPrimitiveReport> reps(tasks.size());  // for the progress lines
  std::vector<std::exception_ptr> failed(tasks.size());
  std::vector<std::size_t> left(m.meshes.size(), 0);
  for (const Task& t : tasks) ++left[t.mesh];
  const auto meshes_to_build =
      static_cast<std::size_t>(std::count_if(left.begin(), left.end(), [](std::size_t n) { return n > 0; }));
  std::size_t stored = 0, meshes_done = 0;
  std::mutex mutex;
  const auto store_ready = [&] {  // under mutex
    for (; stored < tasks.size() && built[stored]; ++stored) {
      BuiltPrimitive& b = *built[stored];
      ClusterPrimitiveReport& rep = b.rep;
      report.shared_vertices += rep.shared_vertices, report.folded_triangles += rep.folded_triangles;
      report.groups_across_seams += rep.groups_across_seams;
      if (rep.clusters == 0) {
        report.warnings.push_back(rep.label + ": no triangles left, no cluster hierarchy");
      } else {
        write_cluster_lod(m, rep.mesh, rep.primitive, b.result.hierarchy, b.result.indices,
                          geometry[tasks[stored].mesh][tasks[stored].primitive].positions_xyz.size() / 3);
        report.primitives.push_back(std::move(rep));
      }
      built[stored].reset();
      PrimitiveGeometry().positions_xyz.swap(geometry[tasks[stored].mesh][tasks[stored].primitive].positions_xyz);
      PrimitiveGeometry().indices.swap(geometry[tasks[stored].mesh][tasks[stored].primitive].indices);
    }
  };
  const auto mesh_done = [&](std::size_t mi) {  // under mutex
    ++meshes_done;
    if (!o.progress) return;
    std::size_t tris = 0, degenerate = 0, clusters = 0, top = 0;
    std::uint32_t levels = 0;
    double build_s = 0.0;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
      if (tasks[i].mesh != mi) continue;
      const ClusterPrimitiveReport& rep = reps[i];
      tris += rep.source_triangles + rep.degenerate_triangles, degenerate += rep.degenerate_triangles;
      clusters += rep.clusters, top += rep.top_triangles, levels = std::max(levels, rep.levels);
      build_s += rep.build_seconds;
    }
    char line[320];
    std::snprintf(line, sizeof line,
                  "bake: mesh %zu/%zu done: %s: %zu triangles -> %zu clusters in %u levels, top %zu "
                  "triangles%s in %ld ms (hierarchy %.3g input triangles/s); overall %zu%%",
                  meshes_done, meshes_to_build, mesh_label(m, static_cast<int>(mi)).c_str(), tris, clusters, levels,
                  top, degenerate ? (", " + std::to_string(degenerate) + " degenerate dropped").c_str() : "",
                  std::lround(build_s * 1000.0), per_second(double(tris), build_s),
                  100 * meshes_done / std::max<std::size_t>(meshes_to_build, 1));
    o.progress(line);
  };
  const auto run = [&](std::size_t i, unsigned threads) {
    const Task& t = tasks[i];
    const std::span<const std::uint8_t> locked =
        shared[t.mesh].empty() ? std::span<const std::uint8_t>{} : shared[t.mesh][t.primitive];
    ClusterBuildOptions b = o.build;
    b.threads = threads;
    std::optional<BuiltPrimitive> result;
    try {
      result = build_primitive(m, static_cast<int>(t.mesh), static_cast<int>(t.primitive),
                               geometry[t.mesh][t.primitive], locked, b);
    } catch (...) {
      failed[i] = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    if (failed[i]) return;
    reps[i] = result->rep;
    built[i] = std::move(result);
    if (--left[t.mesh] == 0) mesh_done(t.mesh);
    if (std::none_of(failed.begin(), failed.end(), [](const std::exception_ptr& e) { return bool(e); })) store_ready();
  };
  if (o.progress)
    o.progress("bake: building " + aux::counted(tasks.size(), "primitive", "primitives") + " of " +
               aux::counted(meshes_to_build, "mesh", "meshes") + " (" + std::to_string(alone.size()) +
               " large ones alone, the rest side by side on " +
               aux::counted(thread_count(o.build.threads), "thread", "threads") + ") ...");
  const auto tb = Clock::now();
  for (std::size_t i : alone) {
    if (o.progress)
      o.progress("bake: " + primitive_label(m, static_cast<int>(tasks[i].mesh), static_cast<int>(tasks[i].primitive)) +
                 ": " + std::to_string(geometry[tasks[i].mesh][tasks[i].primitive].indices.size() / 3) +
                 " triangles, alone on every thread ...");
    run(i, o.build.threads);
  }
  parallel_for(side_by_side.size(), thread_count(o.build.threads),
               [&](std::size_t k, unsigned) { run(side_by_side[k], 1); });
  report.build_seconds = seconds_since(tb);
  // The first failing primitive in mesh order, whichever thread met it first.
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  // A file whose every triangle primitive was left with none would be written unchanged, with
  // no hierarchy: a failure to say, not an output.
  if (report.primitives.empty()) throw BakeError(kNothingLeftToBake);
  std::size_t degenerate = 0, with = 0;
  for (const ClusterPrimitiveReport& p : report.primitives)
    degenerate += p.degenerate_triangles, with += p.degenerate_triangles > 0;
  if (degenerate > 0)
    report.warnings.push_back(aux::counted(degenerate, "degenerate triangle", "degenerate triangles") +
                              " (two corners at one position) dropped in " +
                              aux::counted(with, "primitive", "primitives") + " (column 'degenerate')");
  report.seconds = seconds_since(t0);
  return report;
}

ClusterBakeReport bake_clusters_file(const std::string& in, const std::string& out, const ClusterBakeOptions& o) {
  const auto t0 = Clock::now();
  LoadedGltf loaded = load_gltf(in, o.load);
  refuse_output_over_input(in, loaded, out);  // before the bake, not after its minutes
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
  std::snprintf(line, sizeof line, "%-34s %9s %10s %8s %6s %6s %8s %9s %9s %8s\n", "primitive", "triangles",
                "degenerate", "clusters", "levels", "groups", "top_tris", "stored", "build_ms", "tris/s");
  s << line;
  for (const ClusterPrimitiveReport& p : r.primitives) {
    std::string name = p.label;
    if (name.size() > 34) name = name.substr(0, 31) + "...";
    std::snprintf(line, sizeof line, "%-34s %9zu %10zu %8zu %6u %6zu %8zu %9zu %9.1f %8.3g\n", name.c_str(),
                  p.source_triangles, p.degenerate_triangles, p.clusters, p.levels, p.groups, p.top_triangles,
                  p.stored_triangles, p.build_seconds * 1000.0,
                  per_second(double(p.source_triangles + p.degenerate_triangles), p.build_seconds));
    s << line;
  }
  // Notes on how the hierarchy was made, then the warnings, then the total: a good run ends
  // with its result, not with a note that reads like a problem.
  if (r.shared_vertices > 0)
    s << "note: kept at every level: " << r.shared_vertices
      << " vertices where primitives meet (open borders elsewhere are simplified)\n";
  if (r.folded_triangles > 0)
    s << "note: " << r.folded_triangles
      << " of the stored simplified triangles face against the surface they replace (folded over by "
         "meshoptimizer 0.18's simplifier; their groups' error is raised to cover them)\n";
  if (r.groups_across_seams > 0)
    s << "note: " << r.groups_across_seams
      << " groups simplified across attribute seams (stuck with them kept; --keep-seams: never)\n";
  for (const std::string& w : r.warnings) s << "warning: " << w << "\n";
  std::snprintf(line, sizeof line,
                "total: %s, %s with GAZELOD_cluster_lod, %llu input triangles, "
                "hierarchy %.3f s (%.3g input triangles/s), %.3f s in all\n",
                aux::counted(r.meshes, "mesh", "meshes").c_str(),
                aux::counted(r.primitives.size(), "primitive", "primitives").c_str(),
                static_cast<unsigned long long>(r.input_triangles), r.build_seconds,
                per_second(double(r.input_triangles), r.build_seconds), r.seconds);
  s << line;
  return s.str();
}

}  // namespace gazelod::bake
