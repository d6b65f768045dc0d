// SPDX-License-Identifier: Apache-2.0
// The family's distribution (family.hpp): each seed's figures, their spread over the seeds, and
// the seeds within the targets, as run and under the offline optimum.
#include "apps/gazelod/eval/family.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::cli {

double degraded_figure(const AuditSummary& a) {
  return a.degraded_share;
}
double triangle_figure(const AuditSummary& a) {
  return a.triangle_ratio;
}
double switch_figure(const AuditSummary& a) {
  return a.switches_fixation.per_object_s;
}
double bound_ratio(const OfflinePoint& p, const AuditSummary& a) {
  return a.oracle_triangles > 0 ? static_cast<double>(p.triangles) / static_cast<double>(a.oracle_triangles) : 0.0;
}

Spread spread(const std::vector<FamilyMember>& members, double (*value)(const AuditSummary&), double target) {
  std::vector<std::pair<std::uint64_t, double>> v;
  for (const FamilyMember& m : members) v.emplace_back(m.seed, value(m.audit));
  return spread_of(v, target);
}

int within_all_targets(const std::vector<FamilyMember>& members) {
  return static_cast<int>(std::count_if(members.begin(), members.end(), [](const FamilyMember& m) {
    return degraded_figure(m.audit) <= kTargetDegradedShare && triangle_figure(m.audit) <= kTargetTriangleRatio &&
           switch_figure(m.audit) <= kTargetSwitchesPerObjectS;
  }));
}

int within_all_targets_known(const std::vector<FamilyMember>& members, bool perfect_tracker) {
  // The sequences are never coarser than the oracle (no degradation) and keep to the switch
  // target's budget, so the triangle target decides.
  return static_cast<int>(std::count_if(members.begin(), members.end(), [&](const FamilyMember& m) {
    const OfflinePoint& p = perfect_tracker ? m.audit.bound_oracle_at_target : m.audit.bound_policy_at_target;
    return p.available && m.audit.bound_target_switches >= 0 && p.switches <= m.audit.bound_target_switches &&
           bound_ratio(p, m.audit) <= kTargetTriangleRatio;
  }));
}

Spread spread_of(const std::vector<std::pair<std::uint64_t, double>>& seed_values, double target) {
  Spread s;
  if (seed_values.empty()) return s;
  std::vector<double> v;
  for (const auto& [seed, x] : seed_values) {
    v.push_back(x);
    if (x <= target) ++s.within_target;
    if (v.size() == 1 || x > s.worst) s.worst = x, s.worst_seed = seed;
  }
  std::sort(v.begin(), v.end());
  // Nearest-rank percentiles: values a reader can find in the per-seed table.
  const auto rank = [&](double p) {
    const auto k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, k > 0 ? k - 1 : 0)];
  };
  s.median = rank(0.5);
  s.p90 = rank(0.9);
  return s;
}

}  // namespace gazelod::cli
