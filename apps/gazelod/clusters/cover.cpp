// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/cover.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace gazelod::cli {
namespace {

// A record's bits: groups share theirs exactly (written once per group, read back unchanged).
using RecordKey = std::array<std::uint32_t, 5>;

RecordKey key(float x, float y, float z, float r, float e) {
  return {std::bit_cast<std::uint32_t>(x), std::bit_cast<std::uint32_t>(y), std::bit_cast<std::uint32_t>(z),
          std::bit_cast<std::uint32_t>(r), std::bit_cast<std::uint32_t>(e)};
}

// The coarser of two covers: the larger error, on a tie the lower cluster index.
LeafCover coarser(const LeafCover& a, const LeafCover& b) {
  if (a.self_error_m != b.self_error_m) return a.self_error_m > b.self_error_m ? a : b;
  return a.cluster <= b.cluster ? a : b;
}

}  // namespace

ClusterCover::ClusterCover(const lod::ClusterHierarchy& h) {
  const std::size_t n = h.size();
  for (const auto* v :
       {&h.self_center_x_m, &h.self_center_y_m, &h.self_center_z_m, &h.self_radius_m, &h.parent_center_x_m,
        &h.parent_center_y_m, &h.parent_center_z_m, &h.parent_radius_m, &h.parent_error_m})
    if (v->size() != n) throw std::invalid_argument("cluster cover: the hierarchy's record arrays differ in length");
  if (h.depth.size() != n)
    throw std::invalid_argument("cluster cover: depth has " + std::to_string(h.depth.size()) + " entries for " +
                                std::to_string(n) + " clusters");
  if (n > static_cast<std::size_t>(INT32_MAX)) throw std::invalid_argument("cluster cover: too many clusters");
  self_error_ = h.self_error_m;
  parent_group_.assign(n, -1);

  std::map<RecordKey, std::uint32_t> groups;
  const auto group_of = [&](const RecordKey& k) {
    return groups.try_emplace(k, static_cast<std::uint32_t>(groups.size())).first->second;
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> produced;  // (group, output cluster)
  for (std::uint32_t c = 0; c < n; ++c) {
    const bool has_parent = std::isfinite(h.parent_error_m[c]);
    const RecordKey parent = key(h.parent_center_x_m[c], h.parent_center_y_m[c], h.parent_center_z_m[c],
                                 h.parent_radius_m[c], h.parent_error_m[c]);
    if (h.depth[c] == 0) {
      leaves_.push_back(c);
    } else {
      const RecordKey self =
          key(h.self_center_x_m[c], h.self_center_y_m[c], h.self_center_z_m[c], h.self_radius_m[c], h.self_error_m[c]);
      if (has_parent && self == parent) continue;  // passed through unchanged: never drawn, left out
      produced.emplace_back(group_of(self), c);
    }
    if (has_parent) parent_group_[c] = static_cast<std::int32_t>(group_of(parent));
  }
  const std::size_t g_count = groups.size();
  group_first_output_.assign(g_count + 1, 0);
  for (const auto& [g, c] : produced) ++group_first_output_[g + 1];
  for (std::size_t g = 0; g < g_count; ++g) group_first_output_[g + 1] += group_first_output_[g];
  outputs_.resize(produced.size());
  std::vector<std::uint32_t> fill(group_first_output_.begin(), group_first_output_.end() - 1);
  for (const auto& [g, c] : produced) outputs_[fill[g]++] = c;

  // Parents first: an iterative depth-first search that emits a group once every group above
  // it (a parent group of one of its outputs) has been emitted; a group met again while still
  // on the stack closes a cycle.
  std::vector<std::uint8_t> state(g_count, 0);                 // 0 new, 1 on the stack, 2 emitted
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;  // (group, next output)
  order_.reserve(g_count);
  for (std::uint32_t root = 0; root < g_count; ++root) {
    if (state[root] != 0) continue;
    stack.emplace_back(root, group_first_output_[root]);
    state[root] = 1;
    while (!stack.empty()) {
      auto& [g, next] = stack.back();
      if (next == group_first_output_[g + 1]) {
        state[g] = 2;
        order_.push_back(g);
        stack.pop_back();
        continue;
      }
      const std::uint32_t out = outputs_[next++];
      const std::int32_t up = parent_group_[out];
      if (up < 0 || state[static_cast<std::size_t>(up)] == 2) continue;
      if (state[static_cast<std::size_t>(up)] == 1)
        throw std::invalid_argument("cluster cover: cluster " + std::to_string(out) +
                                    "'s parent record lies below it (the records form a cycle)");
      state[static_cast<std::size_t>(up)] = 1;
      stack.emplace_back(static_cast<std::uint32_t>(up), group_first_output_[static_cast<std::size_t>(up)]);
    }
  }
  group_up_.resize(g_count);
}

ClusterCover::Up ClusterCover::above(std::uint32_t c, std::span<const std::uint8_t> drawn) const {
  Up up;
  if (const std::int32_t g = parent_group_[c]; g >= 0) up = group_up_[static_cast<std::size_t>(g)];
  if (drawn[c] != 0) {
    up.cover = coarser(up.cover, LeafCover{c, self_error_[c]});
    ++up.min_drawn;
    ++up.max_drawn;
  }
  return up;
}

std::size_t ClusterCover::evaluate(std::span<const std::uint8_t> drawn, std::span<LeafCover> covers) {
  if (drawn.size() != cluster_count() || covers.size() != leaves_.size()) return leaves_.size();
  for (const std::uint32_t g : order_) {
    const std::uint32_t first = group_first_output_[g], last = group_first_output_[g + 1];
    Up u;  // a group without outputs covers nothing above its members
    for (std::uint32_t k = first; k < last; ++k) {
      const Up o = above(outputs_[k], drawn);
      if (k == first) {
        u = o;
        continue;
      }
      u.cover = coarser(u.cover, o.cover);
      u.min_drawn = std::min(u.min_drawn, o.min_drawn);
      u.max_drawn = std::max(u.max_drawn, o.max_drawn);
    }
    group_up_[g] = u;
  }
  std::size_t bad = 0;
  for (std::size_t k = 0; k < leaves_.size(); ++k) {
    const Up u = above(leaves_[k], drawn);
    covers[k] = u.cover;
    if (u.min_drawn != 1 || u.max_drawn != 1) ++bad;
  }
  return bad;
}

}  // namespace gazelod::cli
