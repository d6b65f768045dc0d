// SPDX-License-Identifier: Apache-2.0
// The cluster hierarchy build's group simplification and its error, measured against the source
// vertices each group answers for (not summed per level).
#include "bake/cluster/cluster_builder.hpp"

namespace gazelod::bake::cluster_build {

// One group: merge, simplify with its shared border locked, split, then measure against the
// source; a group stuck at its attribute seams is tried again across them. Reads only the
// clusters' data.
void Builder::simplify_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p) const {
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

void Builder::simplify_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p, bool across_seams) const {
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
void Builder::set_error(double distance_m, Piece& p) {
  const double error_m = std::max(distance_m, p.fold_error_m);
  auto error_f = static_cast<float>(error_m);
  if (double(error_f) < error_m) error_f = std::nextafter(error_f, INFINITY);
  p.error_m = std::max(p.child_error_m, error_f);
}

// A simplified group's distance to the source, measured by one task.
void Builder::measure_group(const std::vector<std::uint32_t>& members, Scratch& s, Piece& p) const {
  prepare_measure(members, s, p);
  p.owned.assign(p.index_count.size(), {});
  set_error(measure(s.region, s, s.search, p.child_error_m, p.owned), p);
  finish_measure(s, p);
}

// The same, the source vertices cut into slices measured in parallel (for levels with few
// groups, each answering for many vertices). The slices' bounds do not depend on the thread
// count, so neither does the result.
void Builder::measure_group_sliced(const std::vector<std::uint32_t>& members, Piece& p) {
  Scratch& s = *shared_scratch_;
  prepare_measure(members, s, p);
  const std::size_t slices = (s.region.size() + kMeasureSlice - 1) / kMeasureSlice;
  std::vector<std::vector<std::vector<std::uint32_t>>> owned(slices);
  std::vector<double> distance_m(slices, 0.0);
  parallel_for(slices, [&](std::size_t i, Scratch& t) {
    const std::size_t at = i * kMeasureSlice;
    owned[i].assign(p.index_count.size(), {});
    distance_m[i] =
        measure(std::span<const std::uint32_t>(s.region).subspan(at, std::min(kMeasureSlice, s.region.size() - at)), s,
                t.search, p.child_error_m, owned[i]);
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
void Builder::prepare_measure(const std::vector<std::uint32_t>& members, Scratch& s, const Piece& p) const {
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

void Builder::finish_measure(Scratch& s, const Piece& p) const {
  for (std::uint32_t v : p.indices) s.cluster_of[weld_[v]] = kNone;
}

// The largest distance from the source vertices `region` to the group's new triangles (as
// prepared in `in`), at least floor_m; each vertex goes to owned[k] of the new cluster k
// holding its nearest triangle (or a corner at it). Vertices are only searched until a
// triangle within the largest distance so far (at least the members' error, which the group
// keeps anyway) is found: that bounds them as well. The distance comes out the same in any
// order (which cluster a vertex goes to may not).
double Builder::measure(std::span<const std::uint32_t> region, const Scratch& in, GridSearch& search, double floor_m,
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

}  // namespace gazelod::bake::cluster_build
