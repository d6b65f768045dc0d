// SPDX-License-Identifier: Apache-2.0
// gazelod eval family: the visibility audit over a seeded family of scenarios
// (sim/scenario_family.hpp) instead of a few hand-made files. Each seed's scenario is run
// headless in this process (run_session as a function, no report files) and its audit kept;
// the report gives each figure's distribution over the seeds (median, 90th percentile, worst
// and its seed) beside the targets, and one row per seed. Tuning and reporting use disjoint
// seed ranges: the defaults were chosen on --seeds 1000-1039 and are reported on 2000-2099
// (docs/evaluation.md, "Scenario family"). --set overrides a switch-policy or conditioner
// setting for a tuning sweep.
#pragma once

#include "apps/gazelod/clusters/eval.hpp"
#include "apps/gazelod/eval/family_recording.hpp"
#include "apps/gazelod/run/audit.hpp"
#include "gaze/gaze_conditioner.hpp"
#include "lod/switch_policy.hpp"
#include "sim/scenario_family.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gazelod::cli {

// The audit figure each target bounds (kTarget..., run/audit.hpp), for the report and the
// comparison.
double degraded_figure(const AuditSummary& a);  // degraded_share
double triangle_figure(const AuditSummary& a);  // triangle_ratio
double switch_figure(const AuditSummary& a);    // switches_fixation.per_object_s
// An offline optimum's triangles (--bound) over the oracle's (0 without oracle triangles).
double bound_ratio(const OfflinePoint& p, const AuditSummary& a);

struct FamilyMember {
  std::uint64_t seed = 0;
  std::string summary;  // sim::FamilyScenario::summary
  AuditSummary audit;
};

struct FamilySettings {
  lod::SwitchPolicyConfig switching;
  gaze::ConditionerConfig conditioning;
  sim::IdealTracker ideal;          // --ideal: what each seed's tracker costs (its scenario with parts made ideal)
  double tracker_offset_deg = 0.0;  // --tracker-offset: each seed's tracker off by this much (a calibration error)
  bool offline_bound = false;       // --bound: each seed's offline optimum (run/offline_bound.hpp)
  std::optional<FamilyRecording> recording;  // --recording: its eyes and head instead (family_recording.hpp)
  EnabledCriteria criteria;                  // --criteria (all by default)
  std::vector<std::string> changed;          // "switch.coarsen_hold_s=0.3", as given
};

// Applies one "name=value" (names: `gazelod eval family --list-settings`). Throws UsageError
// for an unknown name or a value out of range.
void apply_setting(const std::string& assignment, FamilySettings& settings);
// The settings --set understands, one per line with its current (default) value.
std::string settings_list(const FamilySettings& settings);

// --recording (null: not given; "" is refused), --recording-format and --criteria ("": all, or
// size,eccentricity with a recording) into settings, each change named in settings.changed
// ("recording=" with the recording's absolute path). Throws UsageError for a bad format or
// criteria list, and (exit 1) for a recording read_family_recording refuses.
void apply_recording_flags(const std::string* recording, const std::string& format, const std::string& criteria,
                           FamilySettings& settings);

// Runs seeds [first, first + count) with `settings`; progress gets one line per seed. Settings
// the switch policy or the conditioner refuse throw UsageError (exit 2, naming the setting and
// its value) before any seed runs.
std::vector<FamilyMember> run_family(std::uint64_t first, int count, double duration_s, const FamilySettings& settings,
                                     const std::string& work_dir,
                                     const std::function<void(const std::string&)>& progress);

struct Spread {
  double median = 0.0, p90 = 0.0, worst = 0.0;
  std::uint64_t worst_seed = 0;
  int within_target = 0;  // members at or under the target
};
// Distribution of `value` over the members (larger is worse).
Spread spread(const std::vector<FamilyMember>& members, double (*value)(const AuditSummary&), double target);
// The same over (seed, value) pairs.
Spread spread_of(const std::vector<std::pair<std::uint64_t, double>>& seed_values, double target);
// The members within all three targets at once.
int within_all_targets(const std::vector<FamilyMember>& members);
// With --bound: the members whose offline optimum at the switch target's pop rate (a better
// policy, or with perfect_tracker a perfect tracker too) meets all three targets.
int within_all_targets_known(const std::vector<FamilyMember>& members, bool perfect_tracker = false);

// The report (markdown) and its JSON twin.
std::string family_markdown(const std::vector<FamilyMember>& members, const FamilySettings& settings,
                            const std::string& command, double duration_s);
std::string family_json(const std::vector<FamilyMember>& members, const FamilySettings& settings, double duration_s);

// Adds `family` to the `eval` command.
EvalSubcommand add_eval_family(CLI::App& eval);

}  // namespace gazelod::cli
