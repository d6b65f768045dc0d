// SPDX-License-Identifier: Apache-2.0
// The cluster hierarchy build (cluster_build.hpp): input checks, position welding, source
// clusters, then level by level grouping, group simplification (in parallel) and re-splitting.
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

namespace gazelod::bake {
namespace {

constexpr std::uint32_t kNone = ~0u;

constexpr std::size_t kMaxDepth = 255;  // depth is stored as uint8
constexpr std::size_t kPrefetch = 16;   // measure(): queries ahead whose vertex data is fetched
// A level with fewer groups than this measures each group's source vertices in slices of
// kMeasureSlice in parallel (the top levels: few groups, each answering for many vertices).
constexpr std::size_t kSlicedBelowGroups = 8;
constexpr std::size_t kMeasureSlice = 16384;

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

  ClusterBuildResult run(std::span<const std::uint32_t> source) {
    // The weld and the source chunks (which degenerate triangles do not disturb) side by side.
    std::vector<std::vector<std::uint32_t>> chunks;
    ClusterBuildResult::Phases& time = out_.phases;
    {
      PhaseTimer timer(time.weld_s);
      parallel_for(2, [&](std::size_t i, Scratch&) {
        if (i == 0) {
          weld_ = weld_positions(pos_);
          if (o_.stuck_across_seams) seams_ = std::make_unique<SeamCopies>(pos_, weld_, source);
          if (seams_ && seams_->seam_positions() == 0) seams_.reset();  // nothing to cross
        } else
          chunks = source_chunks(pos_, source);
      });
    }
    locked_.assign(pos_.size() / 3, 0);  // per welded vertex
    for (std::size_t v = 0; v < o_.locked_vertices.size(); ++v)
      if (o_.locked_vertices[v]) locked_[weld_[v]] = 1;
    group_of_.assign(pos_.size() / 3, 0);
    // All levels hold about twice the source's triangles (each level about half the last).
    out_.indices.reserve(2 * source.size() + 3 * o_.max_triangles);

    std::vector<Piece> pieces(chunks.size());
    {
      PhaseTimer timer(time.source_clusters_s);
      parallel_for(chunks.size(), [&](std::size_t i, Scratch& s) { split_chunk(source, chunks[i], s, pieces[i]); });
    }
    for (Piece& p : pieces) {
      out_.degenerate_triangles += p.dropped_triangles;
      add_clusters(p, 0, -1);
    }
    out_.source_triangles = source.size() / 3 - out_.degenerate_triangles;
    if (out_.source_triangles == 0) return std::move(out_);
    // Each source vertex is owned by the first source cluster using it (distance 0).
    {
      std::vector<bool> taken(pos_.size() / 3, false);
      const lod::ClusterHierarchy& h = out_.hierarchy;
      for (std::size_t c = 0; c < h.size(); ++c)
        for (std::uint32_t i = h.first_index[c]; i < h.first_index[c] + h.index_count[c]; ++i)
          if (const std::uint32_t w = weld_[out_.indices[i]]; !taken[w]) taken[w] = true, owned_[c].push_back(w);
    }

    std::vector<std::uint32_t> pending(self_.size());
    for (std::size_t c = 0; c < pending.size(); ++c) pending[c] = static_cast<std::uint32_t>(c);
    ClusterGrouper grouper(pos_.size() / 3);
    for (std::size_t depth = 0; pending.size() > 1 && depth < kMaxDepth; ++depth)
      pending = level(pending, depth, grouper);
    return std::move(out_);
  }

 private:
  // Splits s.local (a triangle list over s.local_xyz) into clusters, appended to `p` in
  // global vertex ids.
  void split(Scratch& s, std::span<const std::uint32_t> tris, Piece& p) const {
    const std::size_t at = p.indices.size();
    s.splitter.split(s.local_xyz, s.global_of.size(), tris, o_.max_vertices, o_.max_triangles, p.indices,
                     p.index_count);
    for (std::size_t i = at; i < p.indices.size(); ++i) p.indices[i] = s.global_of[p.indices[i]];
  }

  // Each new cluster's distinct welded vertices, in the order its triangles use them (the
  // grouping and the shared marks visit each once).
  void list_welded(Scratch& s, Piece& p) const {
    std::size_t at = 0;
    for (std::uint32_t k : p.index_count) {
      if (++s.stamp == 0) std::fill(s.seen.begin(), s.seen.end(), 0u), s.stamp = 1;
      const std::size_t before = p.welded.size();
      for (std::size_t i = at; i < at + k; ++i)
        if (const std::uint32_t w = weld_[p.indices[i]]; s.seen[w] != s.stamp)
          s.seen[w] = s.stamp, p.welded.push_back(w);
      p.welded_count.push_back(static_cast<std::uint32_t>(p.welded.size() - before));
      at += k;
    }
  }

  // Source clusters of one chunk, each with its own sphere; degenerate triangles (two corners
  // welded together) dropped and counted.
  void split_chunk(std::span<const std::uint32_t> source, std::span<const std::uint32_t> chunk, Scratch& s,
                   Piece& p) const {
    for (std::uint32_t t : chunk) {
      const std::uint32_t* v = &source[3 * std::size_t{t}];
      if (weld_[v[0]] == weld_[v[1]] || weld_[v[1]] == weld_[v[2]] || weld_[v[2]] == weld_[v[0]]) {
        ++p.dropped_triangles;
        continue;
      }
      for (int k = 0; k < 3; ++k) s.local.push_back(s.localise(v[k], pos_));
    }
    if (s.local.empty()) return;
    split(s, s.local, p);
    s.clear();
    list_welded(s, p);
    // Each cluster's sphere around its positions, each once (in the order its triangles use them).
    std::size_t at = 0;
    for (std::uint32_t k : p.welded_count) {
      s.spheres.clear();
      for (std::size_t i = at; i < at + k; ++i) {
        const std::uint32_t w = p.welded[i];
        s.spheres.push_back({pos_[3 * w], pos_[3 * w + 1], pos_[3 * w + 2], 0.0f});
      }
      p.spheres.push_back(enclosing_sphere(s.spheres));
      at += k;
    }
  }

  // One group: merge, simplify with its shared border locked, split, then measure against the
  // source; a group stuck at its attribute seams is tried again across them. Reads only the
  // clusters' data.
  void simplify_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p) const {
    simplify_group(members, s, p, false);
    const auto seam = [&](std::uint32_t c) {
      const auto w = welded_of(c);
      return std::any_of(w.begin(), w.end(), [&](std::uint32_t v) { return seams_->copies(v) > 1; });
    };
    if (!p.simplified && seams_ && std::any_of(members.begin(), members.end(), seam)) {
      p = Piece{};
      simplify_group(members, s, p, true);
      p.across_seams = p.simplified;
    }
  }

  void simplify_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p, bool across_seams) const {
    const lod::ClusterHierarchy& h = out_.hierarchy;
    float child_error_m = 0.0f;
    s.spheres.clear();
    for (std::uint32_t c : members) {
      s.spheres.push_back(self_[c]);
      child_error_m = std::max(child_error_m, h.self_error_m[c]);
      for (std::uint32_t i = h.first_index[c]; i < h.first_index[c] + h.index_count[c]; ++i)
        s.local.push_back(s.localise(across_seams ? weld_[out_.indices[i]] : out_.indices[i], pos_));
    }
    p.sphere = enclosing_sphere(s.spheres);
    const std::size_t vcount = s.global_of.size();
    // The shared positions locked (meshopt_lock.hpp).
    if (!o_.lock_open_borders)
      for (std::size_t l = 0; l < vcount; ++l)
        if (shared_[weld_[s.global_of[l]]]) lock_position(s.local_xyz, l);
    // Simplified on the compact copy (group_simplify.hpp); its folds raise the group's error.
    const GroupSimplified r = simplify_group_triangles(
        s.local_xyz, vcount, s.local, {o_.simplify_ratio, o_.stuck_ratio, o_.fold_retries, o_.lock_open_borders},
        s.simplified, s.simplify);
    const std::size_t n = r.index_count;
    p.folded_triangles = r.folds.triangles;
    p.fold_error_m = r.folds.width_m;
    p.child_error_m = child_error_m;
    s.local_xyz.resize(3 * vcount);  // the copies go before the split
    if (n > 0 && double(n) <= o_.stuck_ratio * double(s.local.size())) {
      p.simplified = true;
      if (across_seams) {  // each corner gets a copy back; the split sees those (its vertex limit)
        for (std::size_t i = 0; i < n; ++i) s.simplified[i] = s.global_of[s.simplified[i]];
        s.member_corners.clear();  // the members' triangles: their copies are the candidates
        for (std::uint32_t c : members)
          s.member_corners.insert(s.member_corners.end(), out_.indices.begin() + h.first_index[c],
                                  out_.indices.begin() + h.first_index[c] + h.index_count[c]);
        seams_->collect(s.member_corners, s.seam_pairs);
        seams_->choose(std::span<std::uint32_t>(s.simplified.data(), n), s.seam_pairs);
        s.clear();
        for (std::size_t i = 0; i < n; ++i) s.simplified[i] = s.localise(s.simplified[i], pos_);
      }
      split(s, std::span<const std::uint32_t>(s.simplified.data(), n), p);
      list_welded(s, p);
    }
    s.clear();
  }

  // The group's error from its largest distance to the source (measure()), rounded up to a
  // float at least as large, and never below a member's (monotone).
  static void set_error(double distance_m, Piece& p) {
    const double error_m = std::max(distance_m, p.fold_error_m);
    auto error_f = static_cast<float>(error_m);
    if (double(error_f) < error_m) error_f = std::nextafter(error_f, INFINITY);
    p.error_m = std::max(p.child_error_m, error_f);
  }

  // A simplified group's distance to the source, measured by one task.
  void measure_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p) const {
    prepare_measure(members, s, p);
    p.owned.assign(p.index_count.size(), {});
    set_error(measure(s.region, s, s.search, p.child_error_m, p.owned), p);
    finish_measure(s, p);
  }

  // The same, the source vertices cut into slices measured in parallel (for levels with few
  // groups, each answering for many vertices). The slices' bounds do not depend on the thread
  // count, so neither does the result.
  void measure_group_sliced(const std::vector<std::uint32_t>& members, Piece& p) {
    Scratch& s = *shared_scratch_;
    prepare_measure(members, s, p);
    const std::size_t slices = (s.region.size() + kMeasureSlice - 1) / kMeasureSlice;
    std::vector<std::vector<std::vector<std::uint32_t>>> owned(slices);
    std::vector<double> distance_m(slices, 0.0);
    parallel_for(slices, [&](std::size_t i, Scratch& t) {
      const std::size_t at = i * kMeasureSlice;
      owned[i].assign(p.index_count.size(), {});
      distance_m[i] =
          measure(std::span<const std::uint32_t>(s.region).subspan(at, std::min(kMeasureSlice, s.region.size() - at)),
                  s, t.search, p.child_error_m, owned[i]);
    });
    p.owned.assign(p.index_count.size(), {});
    for (std::size_t k = 0; k < p.index_count.size(); ++k)
      for (std::size_t i = 0; i < slices; ++i)
        p.owned[k].insert(p.owned[k].end(), owned[i][k].begin(), owned[i][k].end());
    set_error(slices ? *std::max_element(distance_m.begin(), distance_m.end()) : 0.0, p);
    finish_measure(s, p);
  }

  // In s: the source vertices the members own (region), which new cluster each new vertex is
  // in (cluster_of) and each new triangle's cluster, and the new triangles' grid.
  void prepare_measure(const std::vector<std::uint32_t>& members, Scratch& s, const Piece& p) const {
    s.region.clear();
    for (std::uint32_t c : members) s.region.insert(s.region.end(), owned_[c].begin(), owned_[c].end());
    s.triangle_cluster.clear();
    for (std::uint32_t k = 0, at = 0; k < p.index_count.size(); at += p.index_count[k++]) {
      for (std::uint32_t i = at; i < at + p.index_count[k]; ++i) {
        std::uint32_t& c = s.cluster_of[weld_[p.indices[i]]];
        if (c == kNone) c = k;
      }
      s.triangle_cluster.insert(s.triangle_cluster.end(), p.index_count[k] / 3, k);
    }
    s.grid.build(pos_, p.indices);
  }

  void finish_measure(Scratch& s, const Piece& p) const {
    for (std::uint32_t v : p.indices) s.cluster_of[weld_[v]] = kNone;
  }

  // The largest distance from the source vertices `region` to the group's new triangles (as
  // prepared in `in`), at least floor_m; each vertex goes to owned[k] of the new cluster k
  // holding its nearest triangle (or a corner at it). Vertices are only searched until a
  // triangle within the largest distance so far (at least the members' error, which the group
  // keeps anyway) is found: that bounds them as well. The distance comes out the same in any
  // order (which cluster a vertex goes to may not).
  double measure(std::span<const std::uint32_t> region, const Scratch& in, GridSearch& search, double floor_m,
                 std::vector<std::vector<std::uint32_t>>& owned) const {
    double error_m = floor_m;
    std::uint32_t hint = kNone;
    search.restart();  // what a slice finds must not depend on the slices its thread did before
    const std::size_t count = region.size();
    for (std::size_t i = 0; i < count; ++i) {
      // The region's vertices are scattered over the mesh: fetch a few queries ahead.
      if (i + kPrefetch < count) {
        const std::uint32_t ahead = region[i + kPrefetch];
        __builtin_prefetch(&in.cluster_of[ahead]);
        __builtin_prefetch(&pos_[3 * std::size_t{ahead}]);
      }
      const std::uint32_t v = region[i];
      if (in.cluster_of[v] != kNone) {
        owned[in.cluster_of[v]].push_back(v);
        continue;
      }
      const NearestTriangle t = search.nearest(in.grid, &pos_[3 * std::size_t{v}], error_m, hint);
      hint = t.triangle;
      owned[in.triangle_cluster[t.triangle]].push_back(v);
      error_m = std::max(error_m, t.distance_m);
    }
    return error_m;
  }

  void add_clusters(Piece& p, std::size_t depth, std::int32_t source_group) {
    std::uint32_t at = 0, welded_at = 0;
    for (std::size_t c = 0; c < p.index_count.size(); ++c) {
      welded_first_.push_back(static_cast<std::uint32_t>(welded_.size()));
      welded_count_.push_back(p.welded_count[c]);
      welded_.insert(welded_.end(), p.welded.begin() + welded_at, p.welded.begin() + welded_at + p.welded_count[c]);
      welded_at += p.welded_count[c];
      const Sphere& self = p.spheres.empty() ? p.sphere : p.spheres[c];
      const float self_error_m = p.spheres.empty() ? p.error_m : 0.0f;
      lod::ClusterHierarchy& h = out_.hierarchy;
      if (out_.indices.size() + p.index_count[c] > kNone)
        throw BakeError(o_.label + ": the clusters of all levels need more than 2^32 - 1 indices");
      h.first_index.push_back(static_cast<std::uint32_t>(out_.indices.size()));
      h.index_count.push_back(p.index_count[c]);
      out_.indices.insert(out_.indices.end(), p.indices.begin() + at, p.indices.begin() + at + p.index_count[c]);
      at += p.index_count[c];
      h.self_center_x_m.push_back(self.x), h.self_center_y_m.push_back(self.y);
      h.self_center_z_m.push_back(self.z), h.self_radius_m.push_back(self.radius_m);
      h.self_error_m.push_back(self_error_m);
      h.parent_center_x_m.push_back(self.x), h.parent_center_y_m.push_back(self.y);
      h.parent_center_z_m.push_back(self.z), h.parent_radius_m.push_back(self.radius_m);
      h.parent_error_m.push_back(lod::kNoParentError);
      h.depth.push_back(static_cast<std::uint8_t>(depth));
      out_.parent_group.push_back(-1);
      out_.source_group.push_back(source_group);
      out_.levels = std::max(out_.levels, static_cast<std::uint32_t>(depth + 1));
      self_.push_back(self);
      owned_.emplace_back(c < p.owned.size() ? std::move(p.owned[c]) : std::vector<std::uint32_t>{});
    }
  }

  void set_parent(std::uint32_t c, const Sphere& s, float error_m, std::int32_t group) {
    lod::ClusterHierarchy& h = out_.hierarchy;
    h.parent_center_x_m[c] = s.x, h.parent_center_y_m[c] = s.y, h.parent_center_z_m[c] = s.z;
    h.parent_radius_m[c] = s.radius_m, h.parent_error_m[c] = error_m;
    out_.parent_group[c] = group;
  }

  std::vector<std::uint32_t> level(const std::vector<std::uint32_t>& pending, std::size_t depth,
                                   ClusterGrouper& grouper) {
    std::vector<std::uint32_t> first, count;
    std::vector<Sphere> bounds;
    for (std::uint32_t c : pending)
      first.push_back(welded_first_[c]), count.push_back(welded_count_[c]), bounds.push_back(self_[c]);
    std::vector<std::vector<std::uint32_t>> groups;
    {
      PhaseTimer timer(out_.phases.grouping_s);
      groups = grouper.group({welded_, first, count, bounds}, o_.group_size);
    }
    for (auto& g : groups)
      for (std::uint32_t& m : g) m = pending[m];
    {
      PhaseTimer timer(out_.phases.shared_s);
      mark_shared(groups);
    }

    std::vector<Piece> pieces(groups.size());
    {
      PhaseTimer timer(out_.phases.groups_s);
      const bool sliced = groups.size() < kSlicedBelowGroups;
      parallel_for(groups.size(), [&](std::size_t g, Scratch& s) {
        simplify_group(groups[g], s, pieces[g]);
        if (!sliced && pieces[g].simplified) measure_group(groups[g], s, pieces[g]);
      });
      if (sliced) {
        PhaseTimer sliced_timer(out_.phases.sliced_measure_s);
        if (!shared_scratch_) shared_scratch_ = std::make_unique<Scratch>(pos_.size() / 3);
        for (std::size_t g = 0; g < groups.size(); ++g)
          if (pieces[g].simplified) measure_group_sliced(groups[g], pieces[g]);
      }
    }

    std::vector<std::uint32_t> next;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      Piece& p = pieces[g];
      if (p.simplified) out_.folded_triangles += p.folded_triangles, out_.groups_across_seams += p.across_seams;
      for (std::uint32_t c : groups[g]) std::vector<std::uint32_t>().swap(owned_[c]);  // passed on
      if (!p.simplified) {  // stuck: these clusters are the top here
        for (std::uint32_t c : groups[g]) {
          set_parent(c, p.sphere, lod::kNoParentError, -1);
          // Drawn beside every later level: whatever touches them there must stay.
          for (std::uint32_t w : welded_of(c)) locked_[w] = 1;
        }
        continue;
      }
      // The group's record (sphere, error) must differ from each member's self record: a
      // reader derives the groups from record equality (docs/bake.md). A group whose members
      // share one sphere (one output, or outputs of one group) and whose simplification added
      // no error would repeat it: its radius grows by one float step (still enclosing).
      for (std::uint32_t c : groups[g])
        if (std::memcmp(&self_[c], &p.sphere, sizeof(Sphere)) == 0 && out_.hierarchy.self_error_m[c] == p.error_m) {
          p.sphere.radius_m = std::nextafter(p.sphere.radius_m, INFINITY);
          break;
        }
      const auto id = static_cast<std::int32_t>(out_.groups++);
      for (std::uint32_t c : groups[g]) set_parent(c, p.sphere, p.error_m, id);
      for (std::size_t k = 0; k < p.index_count.size(); ++k)
        next.push_back(static_cast<std::uint32_t>(self_.size() + k));
      add_clusters(p, depth + 1, id);
    }
    return next;
  }

  // shared_ per welded vertex: locked_, or used by two groups of this level. In parallel: the
  // first group to claim a vertex owns it, any other that finds it claimed marks it shared
  // (the same marks in any order). Claims carry ids from group_base_ up, so that an earlier
  // level's (below it) reads as unclaimed and needs no reset.
  void mark_shared(const std::vector<std::vector<std::uint32_t>>& groups) {
    shared_ = locked_;
    if (groups.size() >= kNone - group_base_) throw BakeError(o_.label + ": more than 2^32 - 2 groups in all levels");
    const std::uint32_t base = group_base_;
    parallel_for(groups.size(), [&](std::size_t g, Scratch&) {
      const auto me = static_cast<std::uint32_t>(base + g);
      for (std::uint32_t c : groups[g])
        for (std::uint32_t w : welded_of(c)) {
          std::atomic_ref<std::uint32_t> owner_of(group_of_[w]);
          // A plain load first: a vertex inside the group is visited by each member using it.
          std::uint32_t owner = owner_of.load(std::memory_order_relaxed);
          if (owner == me) continue;
          // A failed claim leaves the claiming group's id (this level's, not ours) in `owner`.
          if (owner < base && owner_of.compare_exchange_strong(owner, me, std::memory_order_relaxed)) continue;
          std::atomic_ref<std::uint8_t>(shared_[w]).store(1, std::memory_order_relaxed);
        }
    });
    group_base_ += static_cast<std::uint32_t>(groups.size());
  }

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

}  // namespace

std::string validate_cluster_options(const ClusterBuildOptions& o) {
  std::ostringstream m;
  if (o.max_vertices < 3 || o.max_vertices > 255)
    m << "max vertices per cluster must be in [3, 255], got " << o.max_vertices;
  else if (o.max_triangles < 4 || o.max_triangles > 512 || o.max_triangles % 4 != 0)
    m << "max triangles per cluster must be a multiple of 4 in [4, 512], got " << o.max_triangles;
  else if (o.group_size < 2 || o.group_size > 64)
    m << "clusters per group must be in [2, 64], got " << o.group_size;
  else if (!(o.simplify_ratio > 0.0 && o.simplify_ratio < 1.0))
    m << "simplify ratio must be in (0, 1), got " << o.simplify_ratio;
  else if (!(o.stuck_ratio >= o.simplify_ratio && o.stuck_ratio < 1.0))
    m << "stuck ratio must be in [simplify ratio, 1), got " << o.stuck_ratio;
  else if (o.fold_retries > kMaxFoldRetries)
    m << "fold retries must be in [0, " << kMaxFoldRetries << "], got " << o.fold_retries;
  return m.str();
}

ClusterBuildResult build_cluster_hierarchy(std::span<const float> pos, std::span<const std::uint32_t> indices,
                                           const ClusterBuildOptions& o) {
  if (std::string e = validate_cluster_options(o); !e.empty()) throw BakeError(o.label + ": " + e);
  if (pos.size() % 3 != 0)
    throw BakeError(o.label + ": " + std::to_string(pos.size()) + " position floats is not a whole number of vertices");
  if (indices.size() % 3 != 0)
    throw BakeError(o.label + ": " + std::to_string(indices.size()) + " indices is not a whole number of triangles");
  const std::size_t vcount = pos.size() / 3;
  if (vcount > kNone) throw BakeError(o.label + ": more than 2^32 - 1 vertices");
  // All levels together hold about twice the source; first_index is 32-bit.
  if (indices.size() > (std::size_t{1} << 30))
    throw BakeError(o.label + ": " + std::to_string(indices.size() / 3) +
                    " triangles; a cluster hierarchy takes at most 2^30 indices (357913941 triangles)");
  for (std::size_t v = 0; v < vcount; ++v)
    if (!std::isfinite(pos[3 * v]) || !std::isfinite(pos[3 * v + 1]) || !std::isfinite(pos[3 * v + 2])) {
      std::ostringstream m;
      m << o.label << ": vertex " << v << " position (" << pos[3 * v] << ", " << pos[3 * v + 1] << ", "
        << pos[3 * v + 2] << ") is not finite";
      throw BakeError(m.str());
    }
  if (!o.locked_vertices.empty() && o.locked_vertices.size() != vcount)
    throw BakeError(o.label + ": " + std::to_string(o.locked_vertices.size()) + " locked-vertex flags for " +
                    std::to_string(vcount) + " vertices");
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= vcount)
      throw BakeError(o.label + ": index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                      ", but there are only " + std::to_string(vcount) + " vertices");
  return Builder(pos, o).run(indices);
}

}  // namespace gazelod::bake
