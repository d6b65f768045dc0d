// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/session_audit.hpp"

#include "apps/gazelod/commands/command.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gazelod::cli {

SessionAudit::SessionAudit(const sim::Scenario& scenario, const EnabledCriteria& criteria,
                           std::vector<std::size_t> plain, const std::vector<std::vector<lod::LodLevel>>& chains,
                           const ClusterScene& clusters, bool keep_for_bound)
    : scenario_(scenario),
      criteria_(criteria),
      plain_(std::move(plain)),
      plugin_id_(scenario.objects.size(), -1),
      chains_(chains),
      clusters_(clusters),
      previous_lod_(chains.size(), 0),
      previous_oracle_(chains.size(), 0),
      keep_for_bound_(keep_for_bound) {
  for (std::size_t k = 0; k < plain_.size(); ++k)
    if (plain_[k] < plugin_id_.size()) plugin_id_[plain_[k]] = static_cast<int>(k);
}

void SessionAudit::start(bool ground_truth, bool audit) {
  ground_truth_ = ground_truth;
  if (ground_truth && audit) oracle_.emplace(scenario_, criteria_, plain_);
  try {
    if (oracle_ && !clusters_.empty()) cluster_oracle_.emplace(clusters_);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--scene: ") + e.what());
  }
}

void SessionAudit::set_cluster_pose(std::size_t mesh, const lod::InstanceTransform& pose,
                                    const glm::dvec3& velocity_m_s) {
  if (cluster_oracle_) cluster_oracle_->set_pose(mesh, pose, velocity_m_s);
}

void SessionAudit::frame(sim::Simulator& simulator, std::int64_t t_ns, double t_s, const FrameDecisions& d,
                         const FrameDiagnostics& diag, const sim::HeadState& head, FrameRecord& r) {
  const bool first = first_frame_;
  first_frame_ = false;
  if (oracle_ && oracle_->evaluate(simulator, t_ns, diag.xi_cpd).empty()) {
    AuditFrameInput in;
    in.chains = &chains_;
    in.drawn = d.lod;
    if (!first) in.previous = previous_lod_, in.previous_oracle = previous_oracle_;
    in.oracle = oracle_->levels();
    in.in_view = oracle_->in_view();
    in.suppressed = oracle_->suppressed();
    // The truth names a scenario object; the audit counts plugin objects (-1: a cluster mesh).
    const int pursued = oracle_->truth().pursuit_object;
    const bool known = pursued >= 0 && static_cast<std::size_t>(pursued) < plugin_id_.size();
    in.pursuit_object = known ? plugin_id_[static_cast<std::size_t>(pursued)] : -1;
    in.frame_s = first ? 0.0 : t_s - previous_t_s_;
    r.audit = audit_frame(in);
    BreakdownFrameInput b;
    b.chains = &chains_;
    b.drawn = d.lod;
    b.previous = in.previous;
    b.perceptual = diag.lod_perceptual;
    b.oracle = in.oracle;
    b.previous_oracle = in.previous_oracle;
    b.oracle_limited_by = oracle_->limited_by();
    b.in_view = in.in_view;
    b.eccentricity_deg = oracle_->eccentricity_deg();
    b.distance_m = oracle_->distance_m();
    b.gaze = oracle_->true_gaze();
    b.estimate = static_cast<std::uint8_t>(diag.eye_motion);
    b.frame_s = in.frame_s;
    add_breakdown_frame(b, breakdown_);
    if (keep_for_bound_) keep_frame(in, diag.lod_perceptual);
    std::copy_n(in.oracle.begin(), std::min(in.oracle.size(), previous_oracle_.size()), previous_oracle_.begin());
    if (cluster_oracle_)
      r.cluster_audit =
          cluster_oracle_->audit(oracle_->viewer(), head.position_m, head.orientation, scenario_.display.views[0].fov,
                                 d.cluster_drawn, oracle_->suppressed(), in.frame_s);
  }
  std::copy_n(d.lod.begin(), std::min(d.lod.size(), previous_lod_.size()), previous_lod_.begin());
  previous_t_s_ = t_s;
}

void SessionAudit::keep_frame(const AuditFrameInput& in, std::span<const std::uint8_t> perceptual) {
  const std::size_t n = chains_.size();
  if (!bound_reason_.empty()) return;
  if (in.oracle.size() != n || in.in_view.size() != n || perceptual.size() != n) {
    bound_reason_ = "the frames' levels do not cover the objects";
  } else if (kept_oracle_.size() + n > kMaxOfflineObjectFrames) {
    bound_reason_ = "the run has more than " + std::to_string(kMaxOfflineObjectFrames) + " object-frames";
  } else {
    kept_perceptual_.insert(kept_perceptual_.end(), perceptual.begin(), perceptual.end());
    kept_oracle_.insert(kept_oracle_.end(), in.oracle.begin(), in.oracle.end());
    kept_in_view_.insert(kept_in_view_.end(), in.in_view.begin(), in.in_view.end());
    kept_suppressed_.push_back(in.suppressed ? 1 : 0);
    return;
  }
  // Past the limit or inconsistent: release what was kept, the bound is not computed.
  std::vector<std::uint8_t>().swap(kept_perceptual_);
  std::vector<std::uint8_t>().swap(kept_oracle_);
  std::vector<std::uint8_t>().swap(kept_in_view_);
  std::vector<std::uint8_t>().swap(kept_suppressed_);
}

void SessionAudit::finish(RunSummary& summary, const std::string& no_truth_reason) const {
  if (summary.audit.available) summary.audit.breakdown = breakdown_;
  if (summary.audit.available && keep_for_bound_) {
    // At the policy's own switches outside suppression: what a policy knowing the run's future
    // could have drawn with the same pops.
    const std::int64_t budget = summary.audit.switches_fixation.switches;
    // And at the switch target's pop rate: could a policy meet both targets at once?
    const double at_target = std::floor(kTargetSwitchesPerObjectS * summary.audit.switches_fixation.object_s);
    const std::int64_t target_budget =
        std::isfinite(at_target) && at_target > 0.0 ? static_cast<std::int64_t>(std::min(at_target, 9.0e18)) : 0;
    OfflineBoundInput in{chains_.size(), &chains_, kept_perceptual_, kept_in_view_, kept_suppressed_, kept_oracle_};
    AuditSummary& a = summary.audit;
    a.bound_max_switches = budget;
    a.bound_target_switches = target_budget;
    if (!bound_reason_.empty()) {
      a.bound_policy.reason = a.bound_oracle.reason = bound_reason_;
      a.bound_policy_at_target.reason = a.bound_oracle_at_target.reason = bound_reason_;
    } else {
      // A better policy: never coarser than the plugin allowed, and never visibly coarse (the
      // perceptual level is at times coarser than the truth; the plugin's hold hides much of
      // that, and a bound that drew it would buy triangles with degradations).
      std::vector<std::uint8_t> finer(kept_perceptual_.size());
      for (std::size_t j = 0; j < finer.size(); ++j) finer[j] = std::min(kept_perceptual_[j], kept_oracle_[j]);
      in.ceiling = finer;
      a.bound_policy = offline_bound(in, budget);
      a.bound_policy_at_target = offline_bound(in, target_budget);
      in.ceiling = kept_oracle_;
      a.bound_oracle = offline_bound(in, budget);
      a.bound_oracle_at_target = offline_bound(in, target_budget);
    }
  }
  if (!oracle_) {
    summary.audit = AuditSummary{};
    summary.audit.reason = no_truth_reason;
  }
}

}  // namespace gazelod::cli
