// SPDX-License-Identifier: Apache-2.0
// The cluster hierarchy build's steps: welding, source clusters, then level by level grouping, group
// simplification (in parallel) and re-splitting into new clusters.
#include "bake/cluster/cluster_builder.hpp"

namespace gazelod::bake::cluster_build {

ClusterBuildResult Builder::run(std::span<const std::uint32_t> source) {
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

// Splits s.local (a triangle list over s.local_xyz) into clusters, appended to `p` in
// global vertex ids.
void Builder::split(Scratch& s, std::span<const std::uint32_t> tris, Piece& p) const {
  const std::size_t at = p.indices.size();
  s.splitter.split(s.local_xyz, s.global_of.size(), tris, o_.max_vertices, o_.max_triangles, p.indices, p.index_count);
  for (std::size_t i = at; i < p.indices.size(); ++i) p.indices[i] = s.global_of[p.indices[i]];
}

// Each new cluster's distinct welded vertices, in the order its triangles use them (the
// grouping and the shared marks visit each once).
void Builder::list_welded(Scratch& s, Piece& p) const {
  std::size_t at = 0;
  for (std::uint32_t k : p.index_count) {
    if (++s.stamp == 0) std::fill(s.seen.begin(), s.seen.end(), 0u), s.stamp = 1;
    const std::size_t before = p.welded.size();
    for (std::size_t i = at; i < at + k; ++i)
      if (const std::uint32_t w = weld_[p.indices[i]]; s.seen[w] != s.stamp) s.seen[w] = s.stamp, p.welded.push_back(w);
    p.welded_count.push_back(static_cast<std::uint32_t>(p.welded.size() - before));
    at += k;
  }
}

// Source clusters of one chunk, each with its own sphere; degenerate triangles (two corners
// welded together) dropped and counted.
void Builder::split_chunk(std::span<const std::uint32_t> source, std::span<const std::uint32_t> chunk, Scratch& s,
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

void Builder::add_clusters(Piece& p, std::size_t depth, std::int32_t source_group) {
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

void Builder::set_parent(std::uint32_t c, const Sphere& s, float error_m, std::int32_t group) {
  lod::ClusterHierarchy& h = out_.hierarchy;
  h.parent_center_x_m[c] = s.x, h.parent_center_y_m[c] = s.y, h.parent_center_z_m[c] = s.z;
  h.parent_radius_m[c] = s.radius_m, h.parent_error_m[c] = error_m;
  out_.parent_group[c] = group;
}

std::vector<std::uint32_t> Builder::level(const std::vector<std::uint32_t>& pending, std::size_t depth,
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
    for (std::size_t k = 0; k < p.index_count.size(); ++k) next.push_back(static_cast<std::uint32_t>(self_.size() + k));
    add_clusters(p, depth + 1, id);
  }
  return next;
}

// shared_ per welded vertex: locked_, or used by two groups of this level. In parallel: the
// first group to claim a vertex owns it, any other that finds it claimed marks it shared
// (the same marks in any order). Claims carry ids from group_base_ up, so that an earlier
// level's (below it) reads as unclaimed and needs no reset.
void Builder::mark_shared(const std::vector<std::vector<std::uint32_t>>& groups) {
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

}  // namespace gazelod::bake::cluster_build
