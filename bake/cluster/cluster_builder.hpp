// SPDX-License-Identifier: Apache-2.0
// The cluster hierarchy build's working state (bake/cluster/cluster_build.hpp is the interface):
// one Builder per build_cluster_hierarchy call. Its steps live in cluster_builder.cpp (welding,
// source clusters, levels of grouping and re-splitting) and cluster_measure.cpp (group
// simplification and the error measured against the source). Internal to bake/cluster/.
#pragma once

#include "bake/cluster/cluster_build.hpp"

#include "bake/bake_error.hpp"
#include "bake/cluster_distance.hpp"
#include "bake/cluster/cluster_group.hpp"
#include "bake/cluster/cluster_source.hpp"
#include "bake/cluster/cluster_sphere.hpp"
#include "bake/cluster/cluster_split.hpp"
#include "bake/cluster/group_simplify.hpp"
#include "bake/meshopt_lock.hpp"
#include "bake/parallel_for.hpp"
#include "bake/cluster/seam_copies.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>

namespace gazelod::bake::cluster_build {

inline constexpr std::uint32_t kNone = ~0u;

inline constexpr std::size_t kMaxDepth = 255;  // depth is stored as uint8
inline constexpr std::size_t kPrefetch = 16;   // measure(): queries ahead whose vertex data is fetched
// A level with fewer groups than this measures each group's source vertices in slices of
// kMeasureSlice in parallel (the top levels: few groups, each answering for many vertices).
inline constexpr std::size_t kSlicedBelowGroups = 8;
inline constexpr std::size_t kMeasureSlice = 16384;

// Adds the wall seconds since construction to `into` when destroyed.
class PhaseTimer {
 public:
  explicit PhaseTimer(double& into) : into_(into), start_(std::chrono::steady_clock::now()) {}
  ~PhaseTimer() { into_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double& into_;
  std::chrono::steady_clock::time_point start_;
};

// New clusters made by one parallel task: a chunk of the source mesh split into clusters
// (spheres: each cluster's own), or one group simplified and split (sphere, error: the group's).
struct Piece {
  std::vector<std::uint32_t> indices;      // the new clusters' triangles, global vertex ids
  std::vector<std::uint32_t> index_count;  // per new cluster
  std::vector<Sphere> spheres;
  // Per new cluster of a group: the source vertices (welded ids) it answers for (measure()).
  std::vector<std::vector<std::uint32_t>> owned;
  // Per new cluster: its distinct welded vertices (list_welded()), welded_count of them each.
  std::vector<std::uint32_t> welded, welded_count;
  Sphere sphere;
  float error_m = 0.0f;
  // Until measured: the largest member error and the width of the folds (the error's floors).
  float child_error_m = 0.0f;
  double fold_error_m = 0.0;
  bool simplified = false;
  bool across_seams = false;          // simplified on welded positions (stuck_across_seams)
  std::size_t folded_triangles = 0;   // in the result (cluster_flips.hpp)
  std::size_t dropped_triangles = 0;  // source chunks: degenerate triangles left out
};

// Per-thread buffers. A task works on a compact copy of its vertices, because meshopt 0.18's
// simplifier (and the splitter's per-vertex arrays) allocate and scan the whole vertex buffer.
struct Scratch {
  explicit Scratch(std::size_t vertex_count)
      : local_of(vertex_count, kNone), cluster_of(vertex_count, kNone), seen(vertex_count, 0) {}
  std::vector<std::uint32_t> local_of, global_of, local, simplified;
  std::vector<std::uint32_t> cluster_of, region, triangle_cluster;  // cluster_of: per welded vertex
  std::vector<std::uint32_t> seen;  // per welded vertex: the stamp of the last cluster listing it
  std::uint32_t stamp = 0;
  TriangleGrid grid;
  GridSearch search;
  ClusterSplitter splitter;
  std::vector<float> local_xyz;
  GroupSimplifyScratch simplify;
  // Across seams: the members' corners and the copies they use (seam_copies.hpp).
  std::vector<std::uint32_t> member_corners;
  std::vector<std::uint64_t> seam_pairs;
  std::vector<Sphere> spheres;

  // Appends global vertex v to the compact copy; returns its local id.
  std::uint32_t localise(std::uint32_t v, std::span<const float> pos) {
    if (local_of[v] == kNone) {
      local_of[v] = static_cast<std::uint32_t>(global_of.size());
      global_of.push_back(v);
      local_xyz.push_back(pos[3 * v]), local_xyz.push_back(pos[3 * v + 1]), local_xyz.push_back(pos[3 * v + 2]);
    }
    return local_of[v];
  }
  void clear() {
    for (std::uint32_t v : global_of) local_of[v] = kNone;
    global_of.clear(), local.clear(), local_xyz.clear();
  }
};
class Builder {
 public:
  Builder(std::span<const float> pos, const ClusterBuildOptions& o) : pos_(pos), o_(o) {}

  ClusterBuildResult run(std::span<const std::uint32_t> source);

 private:
  // Splits s.local (a triangle list over s.local_xyz) into clusters, appended to `p` in
  // global vertex ids.
  void split(Scratch& s, std::span<const std::uint32_t> tris, Piece& p) const;

  // Each new cluster's distinct welded vertices, in the order its triangles use them (the
  // grouping and the shared marks visit each once).
  void list_welded(Scratch& s, Piece& p) const;

  // Source clusters of one chunk, each with its own sphere; degenerate triangles (two corners
  // welded together) dropped and counted.
  void split_chunk(std::span<const std::uint32_t> source, std::span<const std::uint32_t> chunk, Scratch& s,
                   Piece& p) const;

  // One group: merge, simplify with its shared border locked, split, then measure against the
  // source; a group stuck at its attribute seams is tried again across them. Reads only the
  // clusters' data.
  void simplify_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p) const;

  void simplify_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p, bool across_seams) const;

  // The group's error from its largest distance to the source (measure()), rounded up to a
  // float at least as large, and never below a member's (monotone).
  static void set_error(double distance_m, Piece& p);

  // A simplified group's distance to the source, measured by one task.
  void measure_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p) const;

  // The same, the source vertices cut into slices measured in parallel (for levels with few
  // groups, each answering for many vertices). The slices' bounds do not depend on the thread
  // count, so neither does the result.
  void measure_group_sliced(const std::vector<std::uint32_t>& members, Piece& p);

  // In s: the source vertices the members own (region), which new cluster each new vertex is
  // in (cluster_of) and each new triangle's cluster, and the new triangles' grid.
  void prepare_measure(const std::vector<std::uint32_t>& members, Scratch& s, const Piece& p) const;

  void finish_measure(Scratch& s, const Piece& p) const;

  // The largest distance from the source vertices `region` to the group's new triangles (as
  // prepared in `in`), at least floor_m; each vertex goes to owned[k] of the new cluster k
  // holding its nearest triangle (or a corner at it). Vertices are only searched until a
  // triangle within the largest distance so far (at least the members' error, which the group
  // keeps anyway) is found: that bounds them as well. The distance comes out the same in any
  // order (which cluster a vertex goes to may not).
  double measure(std::span<const std::uint32_t> region, const Scratch& in, GridSearch& search, double floor_m,
                 std::vector<std::vector<std::uint32_t>>& owned) const;

  void add_clusters(Piece& p, std::size_t depth, std::int32_t source_group);

  void set_parent(std::uint32_t c, const Sphere& s, float error_m, std::int32_t group);

  std::vector<std::uint32_t> level(const std::vector<std::uint32_t>& pending, std::size_t depth,
                                   ClusterGrouper& grouper);

  // shared_ per welded vertex: locked_, or used by two groups of this level. In parallel: the
  // first group to claim a vertex owns it, any other that finds it claimed marks it shared
  // (the same marks in any order). Claims carry ids from group_base_ up, so that an earlier
  // level's (below it) reads as unclaimed and needs no reset.
  void mark_shared(const std::vector<std::vector<std::uint32_t>>& groups);

  // Runs task(i, scratch) for i < count on the configured threads (bake/parallel_for.hpp).
  template <typename Task>
  void parallel_for(std::size_t count, Task&& task) {
    const unsigned threads =
        static_cast<unsigned>(std::min<std::size_t>(thread_count(o_.threads), std::max<std::size_t>(count, 1)));
    while (scratch_.size() < threads) scratch_.push_back(std::make_unique<Scratch>(pos_.size() / 3));
    bake::parallel_for(count, threads, [&](std::size_t i, unsigned t) { task(i, *scratch_[t]); });
  }

  std::span<const float> pos_;
  const ClusterBuildOptions& o_;
  std::vector<std::uint32_t> weld_;
  std::unique_ptr<SeamCopies> seams_;  // stuck_across_seams: the copies of each seam position
  // Per welded vertex: locked by the caller or by a top cluster; locked at this level (also used
  // by two groups); the group claiming it (mark_shared()).
  std::vector<std::uint8_t> locked_, shared_;
  std::vector<std::uint32_t> group_of_;
  std::uint32_t group_base_ = 1;  // the first claim id of the next level
  std::vector<Sphere> self_;      // self spheres, as Sphere (hierarchy holds the same, split up)
  // Per cluster: its distinct welded vertices at welded_[welded_first_[c]] on (list_welded()).
  std::vector<std::uint32_t> welded_, welded_first_, welded_count_;
  std::span<const std::uint32_t> welded_of(std::uint32_t c) const {
    return std::span<const std::uint32_t>(welded_).subspan(welded_first_[c], welded_count_[c]);
  }
  // Per cluster not yet grouped: the source vertices it answers for (measure()).
  std::vector<std::vector<std::uint32_t>> owned_;
  std::vector<std::unique_ptr<Scratch>> scratch_;
  std::unique_ptr<Scratch> shared_scratch_;  // a sliced measure's (read by every slice)
  ClusterBuildResult out_;
};

}  // namespace gazelod::bake::cluster_build
