// SPDX-License-Identifier: Apache-2.0
// Greedy graph growing over the shared-vertex graph of clusters (cluster_group.hpp).
#include "bake/cluster/cluster_group.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace gazelod::bake {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

double distance_squared(const Sphere& a, const Sphere& b) {
  const double dx = double(a.x) - b.x, dy = double(a.y) - b.y, dz = double(a.z) - b.z;
  return dx * dx + dy * dy + dz * dz;
}

// 10 bits per axis of the centre within the box of all centres, interleaved.
std::uint32_t morton(const Sphere& s, const double lo[3], const double size[3]) {
  const double c[3] = {s.x, s.y, s.z};
  std::uint32_t code = 0;
  std::uint32_t q[3];
  for (int k = 0; k < 3; ++k) {
    const double t = size[k] > 0.0 ? (c[k] - lo[k]) / size[k] : 0.0;
    q[k] = static_cast<std::uint32_t>(std::clamp(t, 0.0, 1.0) * 1023.0);
  }
  for (int bit = 9; bit >= 0; --bit)
    for (int k = 0; k < 3; ++k) code = (code << 1) | ((q[k] >> bit) & 1u);
  return code;
}

}  // namespace

ClusterGrouper::ClusterGrouper(std::size_t vertex_count) : owner_(vertex_count, 0), seen_(vertex_count, 0) {}

void ClusterGrouper::build_adjacency(const GroupingInput& set) {
  const std::size_t n = set.first.size();
  adjacency_.assign(n, {});
  auto add = [&](std::uint32_t a, std::uint32_t b) {
    for (Neighbour& e : adjacency_[a])
      if (e.cluster == b) return void(++e.shared_vertices);
    adjacency_[a].push_back({b, 1});
  };
  // owner_ and seen_ hold base_ + cluster: anything below base_ is from an earlier call (unused).
  if (n >= kNone - base_) {
    std::fill(owner_.begin(), owner_.end(), 0u), std::fill(seen_.begin(), seen_.end(), 0u);
    base_ = 1;
  }
  const std::uint32_t base = base_;
  base_ += static_cast<std::uint32_t>(n);
  // One pass: the first cluster to use a welded vertex owns it; every later cluster using it
  // is linked to the owner (and to the cluster before it there, so a vertex shared by three
  // clusters links all of them along a chain); seen_: that cluster before.
  for (std::size_t c = 0; c < n; ++c) {
    const auto cc = static_cast<std::uint32_t>(base + c);
    for (std::uint32_t w : set.vertices.subspan(set.first[c], set.count[c])) {
      if (owner_[w] < base) {
        owner_[w] = seen_[w] = cc;
        continue;
      }
      const std::uint32_t owner = owner_[w] - base, me = cc - base, last = seen_[w] - base;
      add(owner, me), add(me, owner);
      if (last != owner) add(last, me), add(me, last);
      seen_[w] = cc;
    }
  }
}

std::vector<std::vector<std::uint32_t>> ClusterGrouper::group(const GroupingInput& set, std::size_t group_size) {
  const std::size_t n = set.first.size();
  std::vector<std::vector<std::uint32_t>> groups;
  if (n == 0) return groups;
  if (n <= group_size) {
    groups.emplace_back(n);
    std::iota(groups[0].begin(), groups[0].end(), 0u);
    return groups;
  }
  build_adjacency(set);
  std::vector<std::uint32_t> group_of(n, kNone), connection(n, 0);
  auto free_degree = [&](std::uint32_t c) {
    std::size_t d = 0;
    for (const Neighbour& e : adjacency_[c]) d += group_of[e.cluster] == kNone;
    return d;
  };
  std::size_t scan = 0;             // clusters before this one are all assigned
  std::uint32_t next_seed = kNone;  // an unassigned neighbour of the last group, if any
  while (true) {
    std::uint32_t seed = next_seed;
    if (seed == kNone) {
      while (scan < n && group_of[scan] != kNone) ++scan;
      if (scan == n) break;
      seed = static_cast<std::uint32_t>(scan);
    }
    const auto g = static_cast<std::uint32_t>(groups.size());
    std::vector<std::uint32_t>& members = groups.emplace_back();
    std::vector<std::uint32_t> touched;
    auto take = [&](std::uint32_t c) {
      group_of[c] = g;
      members.push_back(c);
      for (const Neighbour& e : adjacency_[c])
        if (group_of[e.cluster] == kNone) {
          if (connection[e.cluster] == 0) touched.push_back(e.cluster);
          connection[e.cluster] += e.shared_vertices;
        }
    };
    take(seed);
    while (members.size() < group_size) {
      std::uint32_t best = kNone;
      for (std::uint32_t c : touched) {
        if (group_of[c] != kNone) continue;
        if (best == kNone || connection[c] > connection[best] ||
            (connection[c] == connection[best] &&
             distance_squared(set.bounds[c], set.bounds[seed]) < distance_squared(set.bounds[best], set.bounds[seed])))
          best = c;
      }
      if (best == kNone) break;
      take(best);
    }
    for (std::uint32_t c : touched) connection[c] = 0;
    // Next seed: the unassigned neighbour most at risk of being left alone.
    next_seed = kNone;
    std::size_t fewest = kNone;
    for (std::uint32_t m : members)
      for (const Neighbour& e : adjacency_[m])
        if (group_of[e.cluster] == kNone && free_degree(e.cluster) < fewest)
          fewest = free_degree(e.cluster), next_seed = e.cluster;
  }

  // Small groups join the neighbouring group they share most vertices with, if it has room.
  const std::size_t small = std::max<std::size_t>(2, group_size / 2);
  const std::size_t room = group_size + group_size / 2;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].empty() || groups[g].size() >= small) continue;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> shared;  // (group, vertices)
    for (std::uint32_t m : groups[g])
      for (const Neighbour& e : adjacency_[m]) {
        const std::uint32_t h = group_of[e.cluster];
        if (h == g || groups[h].size() + groups[g].size() > room) continue;
        auto it = std::find_if(shared.begin(), shared.end(), [&](auto& p) { return p.first == h; });
        if (it == shared.end())
          shared.push_back({h, e.shared_vertices});
        else
          it->second += e.shared_vertices;
      }
    if (shared.empty()) continue;
    const auto best =
        *std::max_element(shared.begin(), shared.end(), [](auto& a, auto& b) { return a.second < b.second; });
    for (std::uint32_t m : groups[g]) group_of[m] = best.first, groups[best.first].push_back(m);
    groups[g].clear();
  }

  // Still small (no neighbour with room): chain them along a Morton curve of their centres.
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Sphere& s : set.bounds) {
    const double c[3] = {s.x, s.y, s.z};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  const double size[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  std::vector<std::pair<std::uint32_t, std::uint32_t>> lonely;  // (morton code, group)
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (!groups[g].empty() && groups[g].size() < small)
      lonely.push_back({morton(set.bounds[groups[g][0]], lo, size), static_cast<std::uint32_t>(g)});
  std::sort(lonely.begin(), lonely.end());
  std::uint32_t into = kNone;
  for (const auto& [code, g] : lonely) {
    if (into != kNone && groups[into].size() < group_size) {
      groups[into].insert(groups[into].end(), groups[g].begin(), groups[g].end());
      groups[g].clear();
    } else {
      into = g;
    }
  }
  std::erase_if(groups, [](const std::vector<std::uint32_t>& m) { return m.empty(); });
  return groups;
}

}  // namespace gazelod::bake
