// SPDX-License-Identifier: Apache-2.0
#include "budget/mckp_hierarchy.hpp"

#include <algorithm>
#include <numeric>

namespace gazelod::budget {

std::string check_hierarchy(const MckpInstance& instance) {
  const std::size_t r = instance.subset_count();
  const std::size_t g_count = instance.groups.size();
  std::vector<std::uint32_t> subset_owner(r, kNoItem), group_owner(g_count, kNoItem);
  for (std::size_t g = 0; g < g_count; ++g) {
    const MckpGroup& grp = instance.groups[g];
    const std::string at = "groups[" + std::to_string(g) + "]";
    for (std::size_t a = 0; a < grp.subsets.size(); ++a) {
      const std::uint32_t s = grp.subsets[a];
      const std::string here = at + ".subsets[" + std::to_string(a) + "]";
      if (s >= r) return here + ": no subset " + std::to_string(s);
      if (subset_owner[s] != kNoItem)
        return here + ": subset " + std::to_string(s) + " is already in groups[" + std::to_string(subset_owner[s]) +
               "]";
      subset_owner[s] = static_cast<std::uint32_t>(g);
    }
    for (std::size_t a = 0; a < grp.groups.size(); ++a) {
      const std::uint32_t h = grp.groups[a];
      const std::string here = at + ".groups[" + std::to_string(a) + "]";
      if (h >= g_count) return here + ": no group " + std::to_string(h);
      if (h == g) return here + ": a group cannot contain itself";
      if (group_owner[h] != kNoItem)
        return here + ": group " + std::to_string(h) + " is already in groups[" + std::to_string(group_owner[h]) + "]";
      group_owner[h] = static_cast<std::uint32_t>(g);
    }
    if (grp.subsets.empty() && grp.groups.empty()) return at + ": a group needs members";
  }
  // Cycles: walking up owners from any group must reach a top-level group.
  for (std::size_t g = 0; g < g_count; ++g) {
    std::size_t steps = 0;
    for (std::uint32_t u = static_cast<std::uint32_t>(g); u != kNoItem; u = group_owner[u])
      if (++steps > g_count) return "groups[" + std::to_string(g) + "]: groups form a cycle";
  }
  return {};
}

void cost_order(const MckpInstance& instance, std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& offsets) {
  order.clear();
  offsets.assign(1, 0);
  for (std::size_t k = 0; k < instance.subset_count(); ++k) {
    const auto items = instance.subset(k);
    const std::size_t begin = order.size();
    for (std::uint32_t j = 0; j < items.size(); ++j) order.push_back(j);
    std::stable_sort(order.begin() + static_cast<std::ptrdiff_t>(begin), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return items[a].cost < items[b].cost; });
    offsets.push_back(static_cast<std::uint32_t>(order.size()));
  }
}

void build_hmckp_tree(const MckpInstance& instance, std::span<const std::uint32_t> kept,
                      std::span<const std::uint32_t> kept_offsets, HmckpTree& tree) {
  const std::size_t r = instance.subset_count();
  tree.nodes.assign(1, HmckpNode{});
  tree.members.clear();
  tree.subset_chain.assign(r, kNoItem);
  tree.subset_chain_len.assign(r, 0);
  tree.chain_pos.assign(instance.items.size(), 0);

  // Subset chains, coarse to fine.
  for (std::size_t k = 0; k < r; ++k) {
    const auto items = instance.subset(k);
    const std::uint32_t base = instance.subset_offsets[k];
    tree.subset_chain[k] = static_cast<std::uint32_t>(tree.nodes.size());
    tree.subset_chain_len[k] = kept_offsets[k + 1] - kept_offsets[k];
    for (std::uint32_t a = kept_offsets[k]; a < kept_offsets[k + 1]; ++a) {
      HmckpNode n;
      n.subset = static_cast<std::uint32_t>(k);
      n.index = kept[a];
      n.source = base + kept[a];
      tree.nodes.push_back(n);
    }
    // A kept item maps to itself; a dropped item to the costliest kept item that costs no
    // more (one always exists: the cheapest kept item is a cheapest item). The kept items are
    // in cost order, so that is a binary search (a scan per item was quadratic: 40 s for one
    // subset of 200k items with nothing dropped).
    const std::uint32_t first = kept_offsets[k], last = kept_offsets[k + 1];
    for (std::uint32_t a = first; a < last; ++a) tree.chain_pos[base + kept[a]] = a - first;
    std::vector<bool> is_kept(items.size(), false);
    for (std::uint32_t a = first; a < last; ++a) is_kept[kept[a]] = true;
    for (std::uint32_t j = 0; j < items.size(); ++j) {
      if (is_kept[j]) continue;
      const auto at = std::upper_bound(kept.begin() + first, kept.begin() + last, items[j].cost,
                                       [&](double cost, std::uint32_t i) { return cost < items[i].cost; });
      const auto above = static_cast<std::uint32_t>(at - (kept.begin() + first));
      tree.chain_pos[base + j] = above > 0 ? above - 1 : 0;
    }
  }
  // Group impostor chains.
  std::vector<std::uint32_t> group_chain(instance.groups.size(), kNoItem);
  std::uint32_t impostor_source = static_cast<std::uint32_t>(instance.items.size());
  for (std::size_t g = 0; g < instance.groups.size(); ++g) {
    const auto& imps = instance.groups[g].impostors;
    if (imps.empty()) continue;
    group_chain[g] = static_cast<std::uint32_t>(tree.nodes.size());
    for (std::uint32_t q = 0; q < imps.size(); ++q) {
      HmckpNode n;
      n.group = static_cast<std::uint32_t>(g);
      n.index = q;
      n.source = impostor_source++;
      tree.nodes.push_back(n);
    }
  }
  // Replacement sets. lowest(x): the coarsest representation of a subset or group
  // (a group without impostors is represented by its members' coarsest ones).
  std::vector<std::uint32_t> scratch;
  auto append_lowest = [&](auto&& self, bool is_group, std::uint32_t x) -> void {
    if (!is_group) {
      scratch.push_back(tree.subset_chain[x]);
      return;
    }
    if (group_chain[x] != kNoItem) {
      scratch.push_back(group_chain[x]);
      return;
    }
    for (std::uint32_t s : instance.groups[x].subsets) self(self, false, s);
    for (std::uint32_t h : instance.groups[x].groups) self(self, true, h);
  };
  auto set_members = [&](std::uint32_t node) {
    tree.nodes[node].first = static_cast<std::uint32_t>(tree.members.size());
    tree.nodes[node].count = static_cast<std::uint32_t>(scratch.size());
    for (std::uint32_t m : scratch) {
      tree.members.push_back(m);
      tree.nodes[m].parent = node;
    }
    scratch.clear();
  };
  // Root: the coarsest representation of every top-level subset and group.
  std::vector<std::uint8_t> owned_subset(r, 0), owned_group(instance.groups.size(), 0);
  for (const MckpGroup& grp : instance.groups) {
    for (std::uint32_t s : grp.subsets) owned_subset[s] = 1;
    for (std::uint32_t h : grp.groups) owned_group[h] = 1;
  }
  for (std::uint32_t k = 0; k < r; ++k)
    if (!owned_subset[k]) append_lowest(append_lowest, false, k);
  for (std::uint32_t g = 0; g < instance.groups.size(); ++g)
    if (!owned_group[g]) append_lowest(append_lowest, true, g);
  set_members(0);
  for (std::uint32_t k = 0; k < r; ++k) {
    const std::uint32_t first = tree.subset_chain[k];
    const std::uint32_t len = kept_offsets[k + 1] - kept_offsets[k];
    for (std::uint32_t q = 0; q + 1 < len; ++q) {
      scratch.push_back(first + q + 1);
      set_members(first + q);
    }
  }
  for (std::uint32_t g = 0; g < instance.groups.size(); ++g) {
    if (group_chain[g] == kNoItem) continue;
    const std::uint32_t first = group_chain[g];
    const auto len = static_cast<std::uint32_t>(instance.groups[g].impostors.size());
    for (std::uint32_t q = 0; q + 1 < len; ++q) {
      scratch.push_back(first + q + 1);
      set_members(first + q);
    }
    for (std::uint32_t s : instance.groups[g].subsets) append_lowest(append_lowest, false, s);
    for (std::uint32_t h : instance.groups[g].groups) append_lowest(append_lowest, true, h);
    set_members(first + len - 1);
  }
  tree.stable_id.resize(tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) tree.stable_id[i] = tree.nodes[i].source;
  tree.stable_id[0] = kNoItem;
}

bool is_valid_lod(const HmckpTree& tree, std::span<const std::uint8_t> selected) {
  if (selected.size() != tree.nodes.size() || selected[0]) return false;
  // Every leaf path ends at the finest item of a subset chain: walk up from each.
  for (std::uint32_t first : tree.subset_chain) {
    std::uint32_t last = first;
    while (tree.nodes[last].count == 1 &&
           tree.nodes[tree.members[tree.nodes[last].first]].subset == tree.nodes[first].subset)
      last = tree.members[tree.nodes[last].first];
    int on_path = 0;
    for (std::uint32_t u = last; u != kNoItem; u = tree.nodes[u].parent) on_path += selected[u];
    if (on_path != 1) return false;
  }
  return true;
}

}  // namespace gazelod::budget
