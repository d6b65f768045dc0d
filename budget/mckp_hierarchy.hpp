// SPDX-License-Identifier: Apache-2.0
// The hierarchical MCKP as a tree of replacement sets (Mason 1999 Def. 4.2, 4.8): every item
// or group impostor is a node, and incrementing a selected node replaces it by its
// replacement set. A plain MCKP is the special case of one chain per subset.
#pragma once

#include "budget/mckp.hpp"

#include <span>
#include <string>
#include <vector>

namespace gazelod::budget {

struct HmckpNode {
  std::uint32_t parent = kNoItem;  // the node whose replacement set holds this one
  std::uint32_t first = 0;         // replacement set: HmckpTree::members[first, first+count)
  std::uint32_t count = 0;
  std::uint32_t source = 0;        // index into the frame's items (subset items), or
                                   // items.size() + running impostor index (group impostors)
  std::uint32_t subset = kNoItem;  // subset of a leaf item
  std::uint32_t group = kNoItem;   // group of an impostor
  std::uint32_t index = 0;         // index within its subset / its group's impostors
};

struct HmckpTree {
  std::vector<HmckpNode> nodes;                 // node 0: the root, "no representation"
  std::vector<std::uint32_t> members;           // concatenated replacement sets
  std::vector<std::uint32_t> stable_id;         // tie-break id per node (the node's `source`)
  std::vector<std::uint32_t> chain_pos;         // per input item: position of the kept item it maps to
  std::vector<std::uint32_t> subset_chain;      // per subset: node id of its cheapest kept item
  std::vector<std::uint32_t> subset_chain_len;  // per subset: kept items (chain nodes are
                                                // contiguous: subset_chain[k] + position)
};

// Empty when `instance.groups` is a forest over valid subset and group indices (each subset
// and group in at most one group); else what is wrong, naming the group ("groups[2].subsets[1]:
// subset 7 is already in groups[0]").
[[nodiscard]] std::string check_hierarchy(const MckpInstance& instance);

// Builds the tree: each subset's kept items (kept/kept_offsets as from reduce_ip_dominated,
// or every item in cost order) chained coarse to fine, each group's impostors chained before
// its members. The structure holds no profits: they are read from the frame's instance.
void build_hmckp_tree(const MckpInstance& instance, std::span<const std::uint32_t> kept,
                      std::span<const std::uint32_t> kept_offsets, HmckpTree& tree);

// Every input item in cost order (ties by index); no item dropped.
void cost_order(const MckpInstance& instance, std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& offsets);

// A valid level of detail: exactly one selected node on every root-to-leaf path (Def. 4.1).
bool is_valid_lod(const HmckpTree& tree, std::span<const std::uint8_t> selected);

}  // namespace gazelod::budget
