// SPDX-License-Identifier: Apache-2.0
// `gazelod compare`'s data: for one HMD, one headless `gazelod run` with every criterion on
// (the plugin's breakdown also selects with size only, size+eccentricity and size+velocity
// each frame), called as a function; its summary gives the five criteria sets, the LOD-map
// thesis's policy, the shares of the reduction and the display's figures.
#pragma once

#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/run/audit.hpp"
#include "apps/gazelod/run/report.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gazelod::cli {

// The criteria sets, in report order; each later set adds criteria to an earlier one.
inline constexpr std::array<const char*, 5> kCriteriaSets{"none", "size", "size+eccentricity", "size+velocity",
                                                          "size+eccentricity+velocity"};

struct SetResult {
  std::uint64_t triangles = 0;  // summed over the run's frames, per eye
  double average_lod = 0.0;     // over every object of every frame
};

struct HmdComparison {
  std::string hmd;
  double xi_cpd = 0.0;
  double eccentricity_threshold_deg = 0.0;  // v = 0
  double velocity_threshold_dps = 0.0;      // E = 0
  std::int64_t frames = 0;
  // The preset has an eye tracker; without one the run has no eye gaze and the plugin draws
  // with its head-fixed fallback. gaze_valid_share: the run's frames with a valid gaze.
  bool eye_tracker = true;
  double gaze_valid_share = 0.0;
  std::array<SetResult, kCriteriaSets.size()> sets{};  // indexed like kCriteriaSets
  SetResult lod_map;                                   // the LOD-map thesis's policy, same frames
  // Shares of the reduction (none -> all three criteria): the run's own (run/shares.hpp).
  ReductionShares shares;
  // The run's visibility audit; not available without ground truth.
  AuditSummary audit;
};

struct CompareOptions {
  std::vector<std::string> hmds;
  std::string scenario_path;  // "" = the embedded default scenario
  std::int64_t frames = 0;    // 0 = the scenario's duration
  std::filesystem::path out_dir = "gazelod-compare";
  bool render = false;
  bool breakdown = false;  // print each audit's breakdown (run/audit_breakdown.hpp)
};

// Throws UsageError when `hmd` is not a display preset.
void check_hmd(const std::string& hmd);

// The figures of `hmd` (a preset) and of its run. Throws UsageError when `hmd` is not a preset.
HmdComparison comparison_from_run(const std::string& hmd, const RunSummary& run);

// Runs the session in this process for `hmd` (run_for_summary), its report in out_dir / hmd.
// Throws UsageError with the run's own message when it fails.
HmdComparison run_comparison(const std::string& hmd, const CompareOptions& options);

}  // namespace gazelod::cli
