// SPDX-License-Identifier: Apache-2.0
// The visibility audit of `gazelod run` ("a saving counts only where it is invisible, and that
// is measured"): the plugin sees a late, noisy tracker; the simulator knows the true gaze. Per
// frame the oracle (AuditOracle) selects with lod::select_lods at the TRUE eye state (true head
// pose, true gaze in the world, its true angular velocity, tracker error 0, the run's xi and
// criteria): the coarsest level of each object that is invisible at the true gaze. The counting
// (audit_frame, summarize_audit) is pure and compares it with what was drawn, over the objects
// in view, outside and inside the suppression windows (saccades, blinks, and
// kSuppressionAfterSaccadeMs after each saccade ends, from the simulator's truth).
#pragma once

#include "apps/gazelod/run/audit_breakdown.hpp"
#include "apps/gazelod/run/offline_bound.hpp"
#include "auxiliary/time.hpp"
#include "lod/display.hpp"
#include "lod/lod_chain.hpp"
#include "lod/object_set.hpp"
#include "lod/select.hpp"
#include "plugin/plugin_config.hpp"
#include "sim/simulator.hpp"

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace gazelod::cli {

// The targets the audit's figures are held to (the issue's, for every scenario): the degraded
// share of fixation object-frames, drawn triangles over the oracle's, switches per
// object-second outside suppression.
inline constexpr double kTargetDegradedShare = 0.005;
inline constexpr double kTargetTriangleRatio = 1.35;
inline constexpr double kTargetSwitchesPerObjectS = 1.0;

// Visual sensitivity stays reduced for about this long after a saccade lands.
inline constexpr double kSuppressionAfterSaccadeMs = 50.0;

// Whether t lies in a suppression window: in a saccade or a blink, or less than
// `after_saccade_ns` after the latest saccade ended.
bool in_suppression(const sim::EyeTruth& truth, std::int64_t t_ns, std::int64_t after_saccade_ns);

// One frame's audit (a FrameRecord carries it; all zero when `available` is false).
struct AuditFrame {
  bool available = false;              // ground truth was computed for this frame
  bool suppressed = false;             // the frame lies in a suppression window
  bool pursuit = false;                // the truth says a pursuit is active
  std::int64_t in_view = 0;            // objects in view
  std::int64_t degraded = 0;           // in-view objects drawn coarser than the oracle's level
  std::uint64_t excess_levels = 0;     // sum over those of (drawn - oracle)
  std::uint32_t excess_max = 0;        // the largest (drawn - oracle) among them
  std::uint64_t drawn_triangles = 0;   // in view, per eye
  std::uint64_t oracle_triangles = 0;  // in view, per eye, every object at the oracle's level
  std::int64_t switches = 0;           // in-view objects whose drawn level differs from the previous frame's
  std::int64_t visible_switches = 0;   // of those, switches whose coarser level the oracle does not allow
  std::int64_t oracle_switches = 0;    // in-view objects whose oracle level differs from the previous frame's
  double object_s = 0.0;               // in-view objects x the time since the previous frame (0 on the first)
  int pursued = -1;                    // -1: no pursuit or its object not in view; 1: drawn coarser than
                                       // the oracle's level; 0: not coarser
};

struct AuditFrameInput {
  const std::vector<std::vector<lod::LodLevel>>* chains = nullptr;  // indexed like the spans
  std::span<const std::uint8_t> drawn;                              // FrameDecisions::lod
  std::span<const std::uint8_t> previous;         // the previous frame's drawn levels; empty on the first frame
  std::span<const std::uint8_t> oracle;           // the oracle's levels
  std::span<const std::uint8_t> previous_oracle;  // the previous frame's; empty on the first frame
  std::span<const std::uint8_t> in_view;          // 1: the object is in view
  bool suppressed = false;
  int pursuit_object = -1;  // sim::EyeTruth::pursuit_object
  double frame_s = 0.0;     // time since the previous frame (0 on the first)
};

// Counts one frame; objects beyond the shortest span are ignored. No allocation.
AuditFrame audit_frame(const AuditFrameInput& in);

struct SwitchRate {
  std::int64_t switches = 0;
  double object_s = 0.0;
  double per_object_s = 0.0;  // switches / object_s (0 when object_s is 0)
};

// The audit over a run. When `available` is false, `reason` says why and nothing else counts.
struct AuditSummary {
  bool available = false;
  std::string reason;  // "" when available
  double after_saccade_ms = kSuppressionAfterSaccadeMs;
  std::int64_t frames = 0;
  std::int64_t suppressed_frames = 0;
  // Visible degradations: over in-view object-frames outside suppression windows.
  std::int64_t object_frames = 0;
  std::int64_t degraded = 0;
  double degraded_share = 0.0;
  double excess_mean = 0.0;  // mean (drawn - oracle) over the degraded object-frames
  std::uint32_t excess_max = 0;
  std::int64_t degraded_suppressed = 0;  // the same inside suppression windows (invisible)
  std::int64_t object_frames_suppressed = 0;
  // Triangles in view over every frame, and drawn / oracle.
  std::uint64_t drawn_triangles = 0, oracle_triangles = 0;
  double triangle_ratio = 0.0;
  SwitchRate switches_fixation;    // outside suppression (fixation, pursuit)
  SwitchRate switches_suppressed;  // inside suppression windows
  // Outside suppression: the switches whose change is itself above threshold (the coarser of
  // the two levels is coarser than the oracle allows), and the oracle's own switches (the rate
  // the true gaze itself requires). The targets use the raw count, switches_fixation.
  SwitchRate visible_switches_fixation;
  SwitchRate oracle_switches_fixation;
  // Where the figures come from (run/audit_breakdown.hpp); summed by the caller frame by frame.
  AuditBreakdown breakdown;
  // The offline optimum (run/offline_bound.hpp) at the policy's own switches outside suppression
  // (bound_max_switches), the run's future known. bound_policy: never coarser than the plugin's
  // perceptual level nor the oracle's (what a better switch policy could draw, invisibly);
  // bound_oracle: never coarser than the oracle's (a perfect tracker too). Set by the session
  // when asked for (--breakdown, eval family --bound).
  std::int64_t bound_max_switches = -1;  // -1: not asked for
  OfflinePoint bound_policy, bound_oracle;
  // The same two at the switch target's pop rate instead (bound_target_switches: the most
  // switches within kTargetSwitchesPerObjectS over switches_fixation's object-seconds), which
  // may be more or fewer than the policy's own: whether any policy, knowing the future, could
  // have met the triangle and switch targets together on the plugin's perceptual levels.
  std::int64_t bound_target_switches = -1;  // -1: not asked for
  OfflinePoint bound_policy_at_target, bound_oracle_at_target;
  // The pursued object over pursuit frames where it is in view.
  std::int64_t pursuit_frames = 0;
  std::int64_t pursuit_degraded = 0;
  double pursuit_degraded_share = 0.0;
};

// Sums the frames that are `available`; the summary is available when at least one is.
AuditSummary summarize_audit(std::span<const AuditFrame> frames, double after_saccade_ms = kSuppressionAfterSaccadeMs);

// summary.json's "audit" object: {"available": false, "reason"} or the figures with the
// suppression window.
nlohmann::json audit_json(const AuditSummary& s);
// The terminal lines ("audit           ..."), with the breakdown's table when asked.
void print_audit(const AuditSummary& s, std::ostream& out, bool breakdown = false);

// The oracle: owns its object store and output arrays (allocated once), so a frame allocates
// nothing. Not thread-safe.
class AuditOracle {
 public:
  // `objects`: the scenario objects audited, in the order of levels() and in_view() (those the
  // plugin got as objects; cluster meshes have their own audit, clusters/audit.hpp); empty:
  // every object, in scenario order. Indices past the scenario's objects are ignored.
  AuditOracle(const sim::Scenario& scenario, const EnabledCriteria& criteria, std::vector<std::size_t> objects = {},
              std::int64_t after_saccade_ns = aux::ns_from_ms(kSuppressionAfterSaccadeMs));

  // The truth at scenario time t (ns): levels(), in_view(), truth() and suppressed() hold it
  // until the next call. xi_cpd: the run's display limit (FrameDiagnostics::xi_cpd).
  // Returns "" or select_lods' refusal (levels then all 0).
  std::string evaluate(sim::Simulator& simulator, std::int64_t t_ns, double xi_cpd);

  std::span<const std::uint8_t> levels() const { return lod_; }
  std::span<const std::uint8_t> limited_by() const { return limited_; }  // lod::Criterion
  std::span<const float> eccentricity_deg() const { return ecc_deg_; }   // nearest point, true gaze
  std::span<const float> distance_m() const { return distance_m_; }      // eye to the sphere's surface
  TrueGaze true_gaze() const { return true_gaze_; }
  std::span<const std::uint8_t> in_view() const { return in_view_; }
  const sim::EyeTruth& truth() const { return truth_; }
  bool suppressed() const { return suppressed_; }
  // The true eye-in-world angular velocity used (rad/s, world axes).
  const glm::dvec3& gaze_angular_velocity() const { return omega_; }
  // The viewer the last evaluate selected for (the truth), for the cluster audit's oracle.
  const lod::Viewer& viewer() const { return viewer_; }
  // The scenario index of audited object k.
  std::span<const std::size_t> objects() const { return objects_; }

 private:
  lod::ObjectStore store_;
  std::vector<std::size_t> objects_;
  lod::Viewer viewer_;
  std::vector<double> radii_;
  lod::FovRad fov_{};
  EnabledCriteria criteria_;
  std::int64_t after_saccade_ns_ = 0;
  std::vector<std::uint8_t> lod_, limited_, size_only_, ecc_only_, vel_only_, in_view_;
  std::vector<float> ecc_deg_, distance_m_;
  TrueGaze true_gaze_ = TrueGaze::fixation;
  sim::EyeTruth truth_;
  bool suppressed_ = false;
  glm::dvec3 omega_{0.0};
};

}  // namespace gazelod::cli
