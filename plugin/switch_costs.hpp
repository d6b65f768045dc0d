// SPDX-License-Identifier: Apache-2.0
// The triangle counts of every object's levels in the flat form the switch policy reads
// (lod::SwitchCosts, for release_regret_s). Rebuilt when objects come or go (registration time,
// linear in the levels); nothing per frame.
#pragma once

#include "lod/lod_chain.hpp"
#include "lod/switch_policy.hpp"

#include <cstdint>
#include <vector>

namespace gazelod::plugin {

class SwitchCostTable {
 public:
  void mark_stale() { stale_ = true; }
  // The costs of chains' levels, rebuilt first if objects came or went since the last call;
  // unit_triangles: the mean over the objects of their full-detail triangles.
  lod::SwitchCosts costs(const std::vector<std::vector<lod::LodLevel>>& chains);

 private:
  std::vector<std::uint32_t> triangles_, first_;
  double unit_triangles_ = 0.0;  // the mean full-detail triangles per object
  bool stale_ = true;
};

}  // namespace gazelod::plugin
