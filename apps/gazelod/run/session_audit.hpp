// SPDX-License-Identifier: Apache-2.0
// The visibility audit's part of a `gazelod run` session: the oracle at the simulator's true
// gaze (run/audit.hpp), the cluster meshes' oracle (clusters/audit.hpp), what the previous
// frame drew and the breakdown summed frame by frame. It reads the simulator only, never the
// plugin's inputs.
#pragma once

#include "apps/gazelod/clusters/audit.hpp"
#include "apps/gazelod/clusters/scene.hpp"
#include "apps/gazelod/run/audit.hpp"
#include "apps/gazelod/run/audit_breakdown.hpp"
#include "apps/gazelod/run/offline_bound.hpp"
#include "apps/gazelod/run/report.hpp"
#include "plugin/lod_plugin.hpp"
#include "sim/simulator.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gazelod::cli {

class SessionAudit {
 public:
  // plain[k]: the scenario index of plugin object k; the rest of the scenario's objects are
  // cluster meshes (clusters). `chains` are plugin object k's levels.
  // keep_for_bound: keep every frame's perceptual and oracle levels (3 bytes per object-frame,
  // up to kMaxOfflineObjectFrames) for the offline optimum computed by finish().
  SessionAudit(const sim::Scenario& scenario, const EnabledCriteria& criteria, std::vector<std::size_t> plain,
               const std::vector<std::vector<lod::LodLevel>>& chains, const ClusterScene& clusters,
               bool keep_for_bound = false);

  // At the first frame: whether the simulator's truth is on the runtime's clock (gazelod's
  // simulated runtime, its own gaze); audit = false (--no-audit) keeps the oracle off. Throws
  // UsageError when the cluster meshes cannot be audited.
  void start(bool ground_truth, bool audit);
  bool ground_truth() const { return ground_truth_; }
  bool on() const { return oracle_.has_value(); }
  // Object-frames kept for the offline optimum (0 when not asked for or past the limit).
  std::size_t kept_object_frames() const { return kept_oracle_.size(); }

  // A cluster mesh moved (the same pose and velocity the plugin got).
  void set_cluster_pose(std::size_t mesh, const lod::InstanceTransform& pose, const glm::dvec3& velocity_m_s);

  // One counted frame at scenario time t_ns (t_s in seconds): fills record.audit and
  // record.cluster_audit when the oracle is on, and remembers what was drawn.
  void frame(sim::Simulator& simulator, std::int64_t t_ns, double t_s, const FrameDecisions& d,
             const FrameDiagnostics& diag, const sim::HeadState& head, FrameRecord& record);

  // The summary's audit: the breakdown (and the offline optimum, when kept) when audited, else
  // why there is no audit.
  void finish(RunSummary& summary, const std::string& no_truth_reason) const;

 private:
  void keep_frame(const AuditFrameInput& in, std::span<const std::uint8_t> perceptual);

  const sim::Scenario& scenario_;
  EnabledCriteria criteria_;
  std::vector<std::size_t> plain_;
  std::vector<int> plugin_id_;  // per scenario object: its plugin object, -1 for a cluster mesh
  const std::vector<std::vector<lod::LodLevel>>& chains_;
  const ClusterScene& clusters_;
  bool ground_truth_ = false;
  bool first_frame_ = true;
  std::optional<AuditOracle> oracle_;
  std::optional<ClusterAuditOracle> cluster_oracle_;
  std::vector<std::uint8_t> previous_lod_, previous_oracle_;
  AuditBreakdown breakdown_;  // summed frame by frame (not kept per frame)
  double previous_t_s_ = 0.0;
  // For the offline optimum (run/offline_bound.hpp): frame-major levels, kept while they fit.
  bool keep_for_bound_ = false;
  std::string bound_reason_;  // why there is none ("" while kept)
  std::vector<std::uint8_t> kept_perceptual_, kept_oracle_, kept_in_view_, kept_suppressed_;
};

}  // namespace gazelod::cli
