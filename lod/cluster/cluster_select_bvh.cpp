// SPDX-License-Identifier: Apache-2.0
// The bounding-hierarchy traversal for one instance (see cluster_select_bvh.hpp).
//
// Why a node the kernel calls invisible has no drawn cluster below it, in the float kernel too.
// Write R(S, e, viewer) for the exact rule in double (cluster_select.hpp) and K(...) for the
// kernel, which is conservative: K invisible implies R invisible. A node holds a sphere S that
// contains every parent sphere s below it and the error 1.01 E, E >= every parent error e below.
//  1. K(S, 1.01 E, viewer') invisible, viewer' the viewer with its velocities scaled by
//     kBvhNodeVelocityFactor (a valid viewer: the kernel's guarantee holds for it), so
//     R(S, 1.01 E, viewer') invisible: f(S) = d(S) / (K_deg 1.01 E) > A'(S).
//  2. The rule is monotone under containment (cluster_select.hpp), so for every parent record
//     (s, e) below, exactly: d(s) / (K_deg e) >= 1.01 f(S) > 1.01 A'(S) >= 1.01 A'(s): the record
//     is invisible under viewer' with 1 % to spare.
//  3. K(s, e, viewer) departs from R(s, e, viewer) by the kernel's slacks and roundings
//     (cluster_select_kernel.hpp): about 1e-4 relative in d, E, M and the products (each far
//     inside the 1 %), and in G an absolute 1e-4 cycles/deg plus the velocity's lowering (at most
//     1e-5 of |V|/d + |w|, which moves G by under 1 % of itself for angular rates below about
//     70 rad/s). Where G nears 0 an absolute error is not small against G: there viewer' has
//     G(v') >= G(v) + 0.047 cycles/deg on G's slope (v' = v (1 - 2^-8), slope 27.78 per decade),
//     hundreds of times the kernel's absolute error, and where G is 0 under viewer' the kernel's
//     v lies beyond G's zero by the same margin. So A'(s) >= the kernel's threshold for (s, e)
//     to within its relative slack, and K(s, e, viewer) is invisible.
// So every parent record below is invisible in the kernel and no cluster below is drawn: what
// select_clusters writes for them is drawn 0, Criterion::none and record bits 3 (without the
// per-criterion cuts it sets the self bit wherever the parent's is set, by the nesting).
// tests/lod/cluster_bvh_test.cpp checks the cut bit for bit against the linear pass on walks,
// fast head turns and saccades included.
// A detail scale s (a frame budget's step, ClusterMeshFrame::error_factor) divides the node's
// error and every parent error below it alike: the argument holds for the errors e / s (the
// node's 1.01 E / s still bounds every e / s below it), and the kernel rounds the factor as it
// rounds K (up), so its guarantee against the exact rule is the same.
// tests/budget/cluster_scale_test.cpp checks the scaled cut against the linear pass too.
#include "lod/cluster/cluster_select_bvh.hpp"

#include "lod/cluster/cluster_local_view.hpp"
#include "lod/criterion.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gazelod::lod::detail {

std::string make_bvh_frames(const Viewer& world, const ClusterInstance& instance, double finest_error_m, BvhFrames& out,
                            double detail_scale) {
  LocalView view;
  if (std::string e = local_view(world, instance, view); !e.empty()) return e;
  const LocalFrames own = local_frames(view, finest_error_m, detail_scale);
  LocalView harder = view;
  harder.viewer.eye_velocity_m_s *= kBvhNodeVelocityFactor;
  harder.viewer.head_angular_velocity_rad_s *= kBvhNodeVelocityFactor;
  harder.viewer.gaze_angular_velocity_in_head_rad_s *= kBvhNodeVelocityFactor;
  harder.mesh_velocity *= kBvhNodeVelocityFactor;
  const LocalFrames nodes = local_frames(harder, finest_error_m, detail_scale);
  out = {own.frame, nodes.frame, own.mesh, nodes.mesh};
  return {};
}

namespace {

constexpr std::uint8_t kSkippedBits = 3;  // both records invisible

// A skipped cluster's bytes over the leaf-order range [begin, end).
void write_skipped(const ClusterBvh& bvh, std::uint32_t first_cluster, std::uint32_t begin, std::uint32_t end,
                   const BvhBytes& bytes) {
  for (std::uint32_t i = begin; i < end; ++i) {
    const std::size_t id = std::size_t{first_cluster} + bvh.cluster_id[i];
    if (bytes.drawn) bytes.drawn[id] = 0;
    if (bytes.limited_by) bytes.limited_by[id] = static_cast<std::uint8_t>(Criterion::none);
    if (bytes.record_invisible) bytes.record_invisible[id] = kSkippedBits;
  }
}

// The frontier's nodes in blocks: a node of error +inf (a cluster below has no parent) is never
// invisible and is expanded untested; the others are tested together. A visible inner node's
// children go to the next level, a visible leaf to the leaves.
void walk(const ClusterBvh& bvh, std::uint32_t root, const BvhFrames& f, BvhScratch& s, BvhTaskOutput& out) {
  const auto expand = [&](std::uint32_t node) {
    if (bvh.is_leaf(node)) {
      s.leaves.push_back(node);
      return;
    }
    for (std::uint32_t k = 0; k < bvh.node_child_count[node]; ++k) s.next.push_back(bvh.node_child_first[node] + k);
  };
  s.frontier.assign(1, root);
  while (!s.frontier.empty()) {
    s.next.clear();
    std::size_t m = 0;
    const auto test = [&]() {
      const RecordInput in{s.node_x, s.node_y, s.node_z, s.node_r, s.node_e};
      evaluate_records(f.node_frame, f.node_mesh, in, 0, m, false, RecordScreen::by_size, nullptr, s.node_block);
      out.nodes_tested += m;
      for (std::size_t j = 0; j < m; ++j) {
        if (s.node_block.combined[j] < 0.5f) expand(s.tested[j]);  // else skipped, with all below it
      }
      m = 0;
    };
    for (std::uint32_t node : s.frontier) {
      if (std::isinf(bvh.node_error_m[node])) {
        expand(node);
        continue;
      }
      s.tested[m] = node;
      s.node_x[m] = bvh.node_center_x_m[node], s.node_y[m] = bvh.node_center_y_m[node];
      s.node_z[m] = bvh.node_center_z_m[node], s.node_r[m] = bvh.node_radius_m[node];
      s.node_e[m] = bvh.node_error_m[node];
      if (++m == kClusterBlock) test();
    }
    if (m > 0) test();
    std::swap(s.frontier, s.next);
  }
}

// The previous frame's ranges less this frame's (both ascending, disjoint): the clusters whose
// bytes go back to a skipped cluster's (those evaluated again are overwritten anyway).
void reset_stale(const ClusterBvh& bvh, std::uint32_t first_cluster, const std::vector<std::uint32_t>& previous,
                 const std::vector<std::uint32_t>& now, const BvhBytes& bytes) {
  std::size_t k = 0;
  for (std::size_t r = 0; r < previous.size(); r += 2) {
    std::uint32_t begin = previous[r];
    const std::uint32_t end = previous[r + 1];
    while (k < now.size() && now[k + 1] <= begin) k += 2;  // ranges of now wholly before
    for (std::size_t q = k; begin < end && q < now.size() && now[q] < end; q += 2) {
      if (now[q] > begin) write_skipped(bvh, first_cluster, begin, now[q], bytes);
      begin = std::max(begin, now[q + 1]);
    }
    if (begin < end) write_skipped(bvh, first_cluster, begin, end, bytes);
  }
}

// The visited leaves' clusters as maximal leaf-order ranges (leaves of one subtree are
// adjacent there), ascending, and their records' rows alike (s.rows).
void merge_runs(const ClusterBvh& bvh, BvhScratch& s, std::vector<std::uint32_t>& runs) {
  std::sort(s.leaves.begin(), s.leaves.end(),
            [&](std::uint32_t a, std::uint32_t b) { return bvh.node_first_cluster[a] < bvh.node_first_cluster[b]; });
  runs.clear(), s.rows.clear();
  for (std::uint32_t leaf : s.leaves) {
    const std::uint32_t begin = bvh.node_first_cluster[leaf], end = begin + bvh.node_cluster_count[leaf];
    const std::uint32_t row = bvh.node_first_record[leaf], row_end = row + bvh.node_record_count[leaf];
    if (!runs.empty() && runs.back() == begin) {
      runs.back() = end, s.rows.back() = row_end;
    } else {
      runs.push_back(begin), runs.push_back(end);
      s.rows.push_back(row), s.rows.push_back(row_end);
    }
  }
}

// The block's drawn clusters onto the list, without a branch per cluster (which is drawn is
// not predictable).
void append_drawn(const std::uint32_t* __restrict ids, std::size_t m, std::uint32_t first_cluster, const BvhScratch& s,
                  BvhTaskOutput& out) {
  const std::size_t at = out.drawn.size();
  out.drawn.resize(at + m), out.limited_by.resize(at + m);
  std::uint32_t* __restrict list = out.drawn.data() + at;
  std::uint8_t* __restrict why = out.limited_by.data() + at;
  std::size_t n = 0;
  for (std::size_t j = 0; j < m; ++j) {
    list[n] = first_cluster + ids[j];
    why[n] = s.why[j];
    n += s.drawn[j];
  }
  out.drawn.resize(at + n), out.limited_by.resize(at + n);
}

// The block's outputs into the per-cluster arrays (copied to locals: a byte store could alias
// the pointers otherwise, and they would be reloaded per cluster).
void write_bytes(const std::uint32_t* __restrict ids, std::size_t m, std::uint32_t first_cluster, const BvhScratch& s,
                 const BvhBytes& bytes) {
  std::uint8_t* const drawn = bytes.drawn;
  std::uint8_t* const why = bytes.limited_by;
  std::uint8_t* const bits = bytes.record_invisible;
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t id = std::size_t{first_cluster} + ids[j];
    if (drawn) drawn[id] = s.drawn[j];
    if (why) why[id] = s.why[j];
    if (bits) bits[id] = s.bits[j];
  }
}

}  // namespace

void select_bvh_subtree(const ClusterBvh& bvh, std::uint32_t root, const BvhFrames& f, std::uint32_t first_cluster,
                        const BvhBytes& bytes, bool previous_bytes, BvhScratch& s, BvhTaskOutput& out) {
  out.drawn.clear(), out.limited_by.clear();
  out.nodes_tested = out.clusters_evaluated = 0;
  s.leaves.clear();
  walk(bvh, root, f, s, out);
  std::swap(out.runs, s.previous_runs);
  merge_runs(bvh, s, out.runs);
  if (previous_bytes && bytes.any()) reset_stale(bvh, first_cluster, s.previous_runs, out.runs, bytes);
  if (s.flags.size() < bvh.record_count()) s.flags.resize(bvh.record_count());
  const RecordInput table{bvh.record_center_x_m.data(), bvh.record_center_y_m.data(), bvh.record_center_z_m.data(),
                          bvh.record_radius_m.data(), bvh.record_error_m.data()};
  for (std::size_t r = 0; r < out.runs.size(); r += 2) {
    // select_clusters' distinct-record pass without the per-criterion cuts, call for call: each
    // record of the run once, then every cluster from its two records' outcomes.
    const std::uint32_t row = s.rows[r], row_end = s.rows[r + 1];
    for (std::size_t base = row; base < row_end; base += kClusterBlock) {
      const std::size_t m = std::min<std::size_t>(kClusterBlock, row_end - base);
      evaluate_records(f.frame, f.mesh, table, base, m, true, RecordScreen::by_size, nullptr, s.record_block);
      pack_record_flags(m, s.record_block, s.flags.data() + base);
    }
    for (std::size_t base = out.runs[r]; base < out.runs[r + 1]; base += kClusterBlock) {
      const std::size_t m = std::min<std::size_t>(kClusterBlock, out.runs[r + 1] - base);
      combine_record_flags(m, s.flags.data(), bvh.self_record.data() + base, bvh.parent_record.data() + base, row,
                           row_end - 1, {s.drawn, s.why, nullptr, nullptr, nullptr, s.bits});
      out.clusters_evaluated += m;
      append_drawn(bvh.cluster_id.data() + base, m, first_cluster, s, out);
      if (bytes.any()) write_bytes(bvh.cluster_id.data() + base, m, first_cluster, s, bytes);
    }
  }
}

void fill_skipped(const BvhBytes& bytes, std::size_t begin, std::size_t end) {
  if (bytes.drawn) std::fill(bytes.drawn + begin, bytes.drawn + end, std::uint8_t{0});
  if (bytes.limited_by)
    std::fill(bytes.limited_by + begin, bytes.limited_by + end, static_cast<std::uint8_t>(Criterion::none));
  if (bytes.record_invisible) std::fill(bytes.record_invisible + begin, bytes.record_invisible + end, kSkippedBits);
}

}  // namespace gazelod::lod::detail
