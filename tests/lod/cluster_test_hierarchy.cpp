// SPDX-License-Identifier: Apache-2.0
// Synthetic hierarchies (see cluster_test_hierarchy.hpp).
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gazelod::lod::test {
namespace {

struct Record {
  double x, y, z, r, e;
};

void push_cluster(ClusterHierarchy& h, const Record& self, const Record* parent, int depth) {
  h.self_center_x_m.push_back(static_cast<float>(self.x));
  h.self_center_y_m.push_back(static_cast<float>(self.y));
  h.self_center_z_m.push_back(static_cast<float>(self.z));
  h.self_radius_m.push_back(static_cast<float>(self.r));
  h.self_error_m.push_back(static_cast<float>(self.e));
  const Record& p = parent ? *parent : self;
  h.parent_center_x_m.push_back(static_cast<float>(p.x));
  h.parent_center_y_m.push_back(static_cast<float>(p.y));
  h.parent_center_z_m.push_back(static_cast<float>(p.z));
  h.parent_radius_m.push_back(static_cast<float>(p.r));
  h.parent_error_m.push_back(parent ? static_cast<float>(p.e) : kNoParentError);
  h.first_index.push_back(static_cast<std::uint32_t>(3 * h.index_count.size()));
  h.index_count.push_back(3);
  h.depth.push_back(static_cast<std::uint8_t>(depth));
}

}  // namespace

TestTree make_tree(const TreeSpec& spec, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int side = 1 << spec.levels;
  std::vector<std::vector<Record>> level(1);
  std::vector<std::vector<int>> parent_of(1);  // per level, each node's parent index above
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < (spec.grid ? side : 1); ++j)
      level[0].push_back(
          {i * spec.spacing_m + 0.2 * spec.spacing_m * (u(rng) - 0.5), 0.3 * spec.spacing_m * (u(rng) - 0.5),
           j * spec.spacing_m + 0.2 * spec.spacing_m * (u(rng) - 0.5), spec.spacing_m * (0.3 + 0.5 * u(rng)), 0.0});
  for (int k = 1, n = side / 2; k <= spec.levels; ++k, n /= 2) {
    const std::vector<Record>& below = level.back();
    const int below_n = 2 * n;
    std::vector<Record> up;
    std::vector<int> parents(below.size());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < (spec.grid ? n : 1); ++j) {
        std::vector<int> kids;
        for (int di = 0; di < 2; ++di)
          for (int dj = 0; dj < (spec.grid ? 2 : 1); ++dj)
            kids.push_back(spec.grid ? (2 * i + di) * below_n + 2 * j + dj : 2 * i + di);
        Record g{0, 0, 0, 0, 0};
        double e_max = 0.0;
        for (int c : kids) {
          g.x += below[c].x / double(kids.size()), g.y += below[c].y / double(kids.size());
          g.z += below[c].z / double(kids.size()), e_max = std::max(e_max, below[c].e);
          parents[c] = static_cast<int>(up.size());
        }
        g.y += 0.2 * spec.spacing_m * (u(rng) - 0.5);  // not the exact centroid
        for (int c : kids)
          g.r = std::max(g.r, std::hypot(below[c].x - g.x, below[c].y - g.y, below[c].z - g.z) + below[c].r);
        g.r = g.r * (1.0 + 1e-4 + 0.1 * u(rng) * u(rng)) + 1e-6;  // contains them in float too
        g.e = u(rng) < spec.equal_error_chance
                  ? e_max
                  : e_max * (1.2 + 1.3 * u(rng)) + spec.leaf_error_m * std::pow(2.0, k) * u(rng);
        up.push_back(g);
      }
    parent_of.push_back({});
    parent_of[k - 1] = parents;
    level.push_back(up);
  }
  parent_of.back().assign(level.back().size(), -1);

  TestTree t;
  std::vector<int> first_node(level.size() + 1, 0);
  for (std::size_t k = 0; k < level.size(); ++k) first_node[k + 1] = first_node[k] + static_cast<int>(level[k].size());
  t.node_parent.resize(first_node.back());
  t.node_clusters.resize(first_node.back());
  for (std::size_t k = 0; k < level.size(); ++k)
    for (std::size_t i = 0; i < level[k].size(); ++i) {
      const int node = first_node[k] + static_cast<int>(i);
      const int p = parent_of[k][i];
      t.node_parent[node] = p < 0 ? -1 : first_node[k + 1] + p;
      const Record* parent = p < 0 ? nullptr : &level[k + 1][p];
      const int outputs = k == 0 ? 1 : spec.outputs_per_group;
      for (int o = 0; o < outputs; ++o) {
        t.node_clusters[node].push_back(static_cast<std::uint32_t>(t.cluster_node.size()));
        t.cluster_node.push_back(node);
        push_cluster(t.h, level[k][i], parent, static_cast<int>(k));
      }
      if (k == 0) t.leaves.push_back(node);
    }
  return t;
}

std::string check_cut(const TestTree& t, std::span<const std::uint8_t> drawn) {
  for (std::size_t n = 0; n < t.node_clusters.size(); ++n)
    for (std::uint32_t c : t.node_clusters[n])
      if (drawn[c] != drawn[t.node_clusters[n][0]]) return "node " + std::to_string(n) + ": its clusters disagree";
  for (int leaf : t.leaves) {
    int count = 0;
    for (int n = leaf; n >= 0; n = t.node_parent[n]) count += drawn[t.node_clusters[n][0]];
    if (count != 1)
      return "leaf node " + std::to_string(leaf) + ": " + std::to_string(count) +
             " clusters drawn on its path (expected exactly 1)";
  }
  return {};
}

std::vector<int> cut_levels(const TestTree& t, std::span<const std::uint8_t> drawn) {
  std::vector<int> out;
  for (int leaf : t.leaves) {
    int lvl = -1;
    int k = 0;
    for (int n = leaf; n >= 0; n = t.node_parent[n], ++k)
      if (drawn[t.node_clusters[n][0]] && lvl < 0) lvl = k;
    out.push_back(lvl);
  }
  return out;
}

}  // namespace gazelod::lod::test
