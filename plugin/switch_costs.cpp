// SPDX-License-Identifier: Apache-2.0
#include "plugin/switch_costs.hpp"

namespace gazelod::plugin {

lod::SwitchCosts SwitchCostTable::costs(const std::vector<std::vector<lod::LodLevel>>& chains) {
  if (stale_ || first_.size() != chains.size()) {
    triangles_.clear(), first_.clear();
    double full_detail = 0.0;
    for (const std::vector<lod::LodLevel>& chain : chains) {
      first_.push_back(static_cast<std::uint32_t>(triangles_.size()));
      for (const lod::LodLevel& level : chain) triangles_.push_back(level.triangles);
      if (!chain.empty()) full_detail += chain.front().triangles;
    }
    unit_triangles_ = chains.empty() ? 0.0 : full_detail / static_cast<double>(chains.size());
    stale_ = false;
  }
  return lod::SwitchCosts{triangles_, first_, unit_triangles_};
}

}  // namespace gazelod::plugin
