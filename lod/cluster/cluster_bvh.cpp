// SPDX-License-Identifier: Apache-2.0
// Builds the bounding hierarchy over a cluster hierarchy's groups (see cluster_bvh.hpp).
#include "lod/cluster/cluster_bvh.hpp"

#include "lod/cluster/cluster_select.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <span>
#include <string>

namespace gazelod::lod {
namespace {

constexpr float kInfF = std::numeric_limits<float>::infinity();

float round_up(double x) {  // +inf stays +inf
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, kInfF) : f;
}

// A group: the clusters sharing one parent record (members[first, + count)), and that record.
struct Group {
  float x, y, z, r, e;
  std::uint32_t first, count;
};

class Builder {
 public:
  Builder(const ClusterHierarchy& h, ClusterBvh& b, std::size_t task_clusters)
      : h_(h), b_(b), task_clusters_(task_clusters) {}

  void run() {
    find_groups();
    // Bands of similar error: 0, then each power of two, then +inf (std::map: in that order).
    std::map<int, std::vector<std::uint32_t>> bands;
    for (std::uint32_t g = 0; g < groups_.size(); ++g) {
      const float e = groups_[g].e;
      int exponent = 0;
      std::frexp(e, &exponent);
      const int key =
          e == 0.0f ? std::numeric_limits<int>::min() : (std::isinf(e) ? std::numeric_limits<int>::max() : exponent);
      bands[key].push_back(g);
    }
    std::vector<std::uint32_t> all(groups_.size());
    std::iota(all.begin(), all.end(), 0u);
    add_nodes(1);
    set_bounds(0, all);
    b_.node_first_cluster[0] = 0;
    const auto first = static_cast<std::uint32_t>(b_.node_count());
    add_nodes(bands.size());
    b_.node_child_first[0] = first;
    b_.node_child_count[0] = static_cast<std::uint32_t>(bands.size());
    std::uint32_t child = first;
    for (auto& [key, members] : bands) build(child++, members);
    b_.node_cluster_count[0] = static_cast<std::uint32_t>(b_.cluster_id.size());
    b_.node_record_count[0] = static_cast<std::uint32_t>(b_.record_count());
    collect_task_roots(0);
  }

 private:
  using Key = std::array<std::uint32_t, 5>;
  // A record's bits: equal keys, equal records (and equal decisions).
  static Key key(const std::vector<float>* const f[5], std::uint32_t i) {
    return {std::bit_cast<std::uint32_t>((*f[0])[i]), std::bit_cast<std::uint32_t>((*f[1])[i]),
            std::bit_cast<std::uint32_t>((*f[2])[i]), std::bit_cast<std::uint32_t>((*f[3])[i]),
            std::bit_cast<std::uint32_t>((*f[4])[i])};
  }
  Key parent_key(std::uint32_t i) const { return key(parent_, i); }
  Key self_key(std::uint32_t i) const { return key(self_, i); }

  // Groups by sorting the clusters on their parent record's bits (deterministic, no hashing),
  // and within a group on their self record's, so that equal self records are adjacent.
  void find_groups() {
    const std::size_t n = h_.size();
    members_.resize(n);
    std::iota(members_.begin(), members_.end(), 0u);
    std::sort(members_.begin(), members_.end(), [&](std::uint32_t a, std::uint32_t b) {
      const Key pa = parent_key(a), pb = parent_key(b);
      if (pa != pb) return pa < pb;
      const Key sa = self_key(a), sb = self_key(b);
      return sa != sb ? sa < sb : a < b;
    });
    for (std::uint32_t i = 0; i < n;) {
      std::uint32_t j = i;
      while (j < n && parent_key(members_[j]) == parent_key(members_[i])) ++j;
      const std::uint32_t c = members_[i];
      groups_.push_back({h_.parent_center_x_m[c], h_.parent_center_y_m[c], h_.parent_center_z_m[c],
                         h_.parent_radius_m[c], h_.parent_error_m[c], i, j - i});
      i = j;
    }
  }

  void add_nodes(std::size_t k) {
    const std::size_t n = b_.node_count() + k;
    for (auto* v : {&b_.node_center_x_m, &b_.node_center_y_m, &b_.node_center_z_m, &b_.node_radius_m, &b_.node_error_m})
      v->resize(n, 0.0f);
    for (auto* v : {&b_.node_child_first, &b_.node_child_count, &b_.node_first_cluster, &b_.node_cluster_count,
                    &b_.node_first_record, &b_.node_record_count})
      v->resize(n, 0u);
  }

  // A sphere around the groups' spheres (centred in their box) and their largest error, with
  // the margins: the radius computed in double from the float centre, raised by 2^-30 (far
  // above double's rounding) and rounded up, so that it contains each sphere in exact arithmetic
  // on the stored floats (the monotonicity argument needs exact containment).
  void set_bounds(std::uint32_t node, std::span<const std::uint32_t> gs) {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    float error = 0.0f;
    for (std::uint32_t g : gs) {
      const Group& q = groups_[g];
      const double c[3] = {q.x, q.y, q.z};
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a] - q.r), hi[a] = std::max(hi[a], c[a] + q.r);
      error = std::max(error, q.e);
    }
    float centre[3];
    for (int a = 0; a < 3; ++a) centre[a] = static_cast<float>(0.5 * (lo[a] + hi[a]));
    double radius = 0.0;
    for (std::uint32_t g : gs) {
      const Group& q = groups_[g];
      radius = std::max(
          radius, std::hypot(double(q.x) - centre[0], double(q.y) - centre[1], double(q.z) - centre[2]) + double(q.r));
    }
    b_.node_center_x_m[node] = centre[0], b_.node_center_y_m[node] = centre[1], b_.node_center_z_m[node] = centre[2];
    b_.node_radius_m[node] = round_up(radius * (1.0 + 0x1p-30));
    b_.node_error_m[node] = round_up(static_cast<double>(error) * kBvhNodeErrorMargin);
  }

  // Median split of gs along the longest axis of its groups' centres.
  std::pair<std::span<std::uint32_t>, std::span<std::uint32_t>> bisect(std::span<std::uint32_t> gs) {
    float lo[3] = {kInfF, kInfF, kInfF}, hi[3] = {-kInfF, -kInfF, -kInfF};
    for (std::uint32_t g : gs) {
      const float c[3] = {groups_[g].x, groups_[g].y, groups_[g].z};
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    const auto coord = [&](std::uint32_t g) {
      return axis == 0 ? groups_[g].x : axis == 1 ? groups_[g].y : groups_[g].z;
    };
    const std::size_t mid = gs.size() / 2;
    std::nth_element(
        gs.begin(), gs.begin() + static_cast<std::ptrdiff_t>(mid), gs.end(),
        [&](std::uint32_t a, std::uint32_t b) { return coord(a) != coord(b) ? coord(a) < coord(b) : a < b; });
    return {gs.first(mid), gs.subspan(mid)};
  }

  // Node `node` over the groups gs: a leaf, or up to 8 children by three rounds of bisection.
  void build(std::uint32_t node, std::span<std::uint32_t> gs) {
    set_bounds(node, gs);
    b_.node_first_cluster[node] = static_cast<std::uint32_t>(b_.cluster_id.size());
    b_.node_first_record[node] = static_cast<std::uint32_t>(b_.record_count());
    if (gs.size() <= kBvhLeafGroups) {
      for (std::uint32_t g : gs) add_group(groups_[g]);
    } else {
      std::vector<std::span<std::uint32_t>> parts{gs};
      for (int round = 0; round < 3; ++round) {
        std::vector<std::span<std::uint32_t>> next;
        for (std::span<std::uint32_t> p : parts) {
          if (p.size() <= kBvhLeafGroups) {
            next.push_back(p);
            continue;
          }
          const auto [a, b] = bisect(p);
          next.push_back(a), next.push_back(b);
        }
        parts = std::move(next);
      }
      const auto first = static_cast<std::uint32_t>(b_.node_count());
      add_nodes(parts.size());
      b_.node_child_first[node] = first;
      b_.node_child_count[node] = static_cast<std::uint32_t>(parts.size());
      for (std::size_t k = 0; k < parts.size(); ++k) build(first + static_cast<std::uint32_t>(k), parts[k]);
    }
    b_.node_cluster_count[node] = static_cast<std::uint32_t>(b_.cluster_id.size()) - b_.node_first_cluster[node];
    b_.node_record_count[node] = static_cast<std::uint32_t>(b_.record_count()) - b_.node_first_record[node];
  }

  // A row of the table: cluster c's self (f = self_) or parent (f = parent_) record.
  std::uint32_t add_record(const std::vector<float>* const f[5], std::uint32_t c) {
    std::vector<float>* to[5] = {&b_.record_center_x_m, &b_.record_center_y_m, &b_.record_center_z_m,
                                 &b_.record_radius_m, &b_.record_error_m};
    for (int k = 0; k < 5; ++k) to[k]->push_back((*f[k])[c]);
    return static_cast<std::uint32_t>(b_.record_count() - 1);
  }

  // A group's members in leaf order, its parent record, then its members' distinct self records.
  void add_group(const Group& g) {
    const std::uint32_t parent = add_record(parent_, members_[g.first]);
    std::uint32_t self = 0;
    for (std::uint32_t k = 0; k < g.count; ++k) {
      const std::uint32_t c = members_[g.first + k];
      if (k == 0 || self_key(c) != self_key(members_[g.first + k - 1])) self = add_record(self_, c);
      b_.cluster_id.push_back(c);
      b_.self_record.push_back(self);
      b_.parent_record.push_back(parent);
    }
  }

  void collect_task_roots(std::uint32_t node) {
    if (b_.is_leaf(node) || b_.node_cluster_count[node] <= task_clusters_) {
      b_.task_roots.push_back(node);
      return;
    }
    for (std::uint32_t k = 0; k < b_.node_child_count[node]; ++k) collect_task_roots(b_.node_child_first[node] + k);
  }

  const ClusterHierarchy& h_;
  ClusterBvh& b_;
  std::size_t task_clusters_;
  const std::vector<float>* const self_[5] = {&h_.self_center_x_m, &h_.self_center_y_m, &h_.self_center_z_m,
                                              &h_.self_radius_m, &h_.self_error_m};
  const std::vector<float>* const parent_[5] = {&h_.parent_center_x_m, &h_.parent_center_y_m, &h_.parent_center_z_m,
                                                &h_.parent_radius_m, &h_.parent_error_m};
  std::vector<std::uint32_t> members_;  // clusters sorted by group
  std::vector<Group> groups_;
};

}  // namespace

std::size_t ClusterBvh::memory_bytes() const {
  std::size_t bytes = 0;
  for (const auto* v : {&record_center_x_m, &record_center_y_m, &record_center_z_m, &record_radius_m, &record_error_m,
                        &node_center_x_m, &node_center_y_m, &node_center_z_m, &node_radius_m, &node_error_m})
    bytes += v->capacity() * sizeof(float);
  for (const auto* v : {&cluster_id, &self_record, &parent_record, &node_child_first, &node_child_count,
                        &node_first_cluster, &node_cluster_count, &node_first_record, &node_record_count, &task_roots})
    bytes += v->capacity() * sizeof(std::uint32_t);
  return bytes;
}

ClusterBvh build_cluster_bvh(const ClusterHierarchy& hierarchy, std::size_t task_clusters) {
  ClusterBvh b;
  b.finest_error_m = finest_cluster_error_m(hierarchy.self_error_m, hierarchy.parent_error_m);
  if (hierarchy.size() == 0) return b;
  Builder(hierarchy, b, task_clusters).run();
  return b;
}

namespace {

// Whether table row r equals, bit for bit, cluster c's self (parent false) or parent record.
bool same_record(const ClusterBvh& b, std::uint32_t r, const ClusterHierarchy& h, bool parent, std::uint32_t c) {
  if (r >= b.record_count()) return false;
  const auto bits = [](float x) { return std::bit_cast<std::uint32_t>(x); };
  const std::array<float, 5> want =
      parent ? std::array<float, 5>{h.parent_center_x_m[c], h.parent_center_y_m[c], h.parent_center_z_m[c],
                                    h.parent_radius_m[c], h.parent_error_m[c]}
             : std::array<float, 5>{h.self_center_x_m[c], h.self_center_y_m[c], h.self_center_z_m[c],
                                    h.self_radius_m[c], h.self_error_m[c]};
  const std::array<float, 5> got{b.record_center_x_m[r], b.record_center_y_m[r], b.record_center_z_m[r],
                                 b.record_radius_m[r], b.record_error_m[r]};
  for (int k = 0; k < 5; ++k)
    if (bits(want[k]) != bits(got[k])) return false;
  return true;
}

// "" when node's sphere and error bound the parent records of its clusters and their records
// lie in its rows.
std::string check_node(const ClusterBvh& b, std::uint32_t node) {
  const std::uint32_t first = b.node_first_cluster[node], count = b.node_cluster_count[node];
  const std::uint32_t rows = b.node_first_record[node], rows_end = rows + b.node_record_count[node];
  for (std::uint32_t i = first; i < first + count; ++i) {
    const std::uint32_t p = b.parent_record[i], s = b.self_record[i];
    if (p < rows || p >= rows_end || s < rows || s >= rows_end)
      return "node " + std::to_string(node) + ": cluster " + std::to_string(b.cluster_id[i]) +
             "'s records lie outside the node's rows";
    const double reach = std::hypot(double(b.record_center_x_m[p]) - b.node_center_x_m[node],
                                    double(b.record_center_y_m[p]) - b.node_center_y_m[node],
                                    double(b.record_center_z_m[p]) - b.node_center_z_m[node]) +
                         double(b.record_radius_m[p]);
    if (!(reach <= double(b.node_radius_m[node])) || !(b.record_error_m[p] <= b.node_error_m[node]))
      return "node " + std::to_string(node) + ": does not bound cluster " + std::to_string(b.cluster_id[i]);
  }
  return {};
}

}  // namespace

std::string check_cluster_bvh(const ClusterBvh& b, const ClusterHierarchy& h) {
  const std::size_t n = h.size();
  if (b.size() != n || b.self_record.size() != n || b.parent_record.size() != n)
    return "the tree holds " + std::to_string(b.size()) + " clusters, the hierarchy " + std::to_string(n);
  if (n == 0) return {};
  std::vector<std::uint8_t> seen(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t c = b.cluster_id[i];
    if (c >= n || seen[c]) return "leaf order position " + std::to_string(i) + ": cluster repeated or out of range";
    seen[c] = 1;
    if (!same_record(b, b.self_record[i], h, false, c) || !same_record(b, b.parent_record[i], h, true, c))
      return "leaf order position " + std::to_string(i) + ": records differ from cluster " + std::to_string(c);
  }
  for (std::uint32_t node = 0; node < b.node_count(); ++node) {
    const std::uint32_t first = b.node_first_cluster[node], count = b.node_cluster_count[node];
    if (std::size_t{first} + count > n) return "node " + std::to_string(node) + ": cluster range out of bounds";
    std::uint32_t next = first, next_row = b.node_first_record[node];
    for (std::uint32_t k = 0; k < b.node_child_count[node]; ++k) {
      const std::uint32_t child = b.node_child_first[node] + k;
      if (child <= node || child >= b.node_count() || b.node_first_cluster[child] != next ||
          b.node_first_record[child] != next_row)
        return "node " + std::to_string(node) + ": children do not tile its clusters";
      next += b.node_cluster_count[child], next_row += b.node_record_count[child];
    }
    if (b.node_child_count[node] > 0 &&
        (next != first + count || next_row != b.node_first_record[node] + b.node_record_count[node]))
      return "node " + std::to_string(node) + ": children do not tile its clusters";
    if (std::string e = check_node(b, node); !e.empty()) return e;
  }
  std::size_t next = 0;
  for (std::uint32_t root : b.task_roots) {
    if (b.node_first_cluster[root] != next) return "task roots do not tile the clusters";
    next += b.node_cluster_count[root];
  }
  return next == n ? std::string() : "task roots do not tile the clusters";
}

}  // namespace gazelod::lod
