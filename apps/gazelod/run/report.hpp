// SPDX-License-Identifier: Apache-2.0
// What `gazelod run` reports: per-frame records in, a terminal summary, summary.json,
// frames.csv and an SVG plot (triangles and frame time over the run, gaze events marked) out.
#pragma once

#include "apps/gazelod/run/audit.hpp"
#include "apps/gazelod/run/shares.hpp"
#include "apps/gazelod/clusters/audit.hpp"
#include "apps/gazelod/plots/svg_plot.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gazelod::cli {

// Every level a chain can have (1 to 255 levels): nothing is folded. The reports list levels
// 0 to the coarsest that occurred in the run (at least 0-3), summary.json and frames.csv alike.
inline constexpr int kMaxReportedLods = 256;

struct FrameRecord {
  std::int64_t index = 0;
  double t_s = 0.0;                        // scenario time of the frame's predicted display time
  double frame_ms = 0.0;                   // measured: selection + rendering both eyes + submit
  double select_ms = 0.0;                  // measured: plugin begin_frame (gaze, head, selection)
  double predicted_ms = 0.0;               // budget's predicted frame time (0 when no budget)
  std::uint64_t triangles_drawn = 0;       // per eye
  std::uint64_t triangles_full = 0;        // every object at LOD 0
  std::uint64_t triangles_perceptual = 0;  // all criteria, this frame's perceptual choice
  std::uint64_t triangles_size_only = 0;   // criteria sets, for the shares
  std::uint64_t triangles_size_eccentricity = 0;
  std::uint64_t triangles_size_velocity = 0;
  std::array<std::uint32_t, kMaxReportedLods> lod_histogram{};
  std::string gaze_source;  // "openxr", "hid", "trace", "head-fixed"
  bool gaze_valid = false;
  bool saccade = false;  // a saccade began at this frame (for the plot)
  double head_speed_dps = 0.0;
  std::string eye_motion;          // the conditioner's reading (fixation, carried, saccade, pursuit, loss)
  bool plugin_suppressed = false;  // the plugin took vision as suppressed (its switch policy's flag)
  double gaze_error_deg = 0.0;     // the uncertainty that widened the foveal cone
  // For the evaluation (gazelod compare / eval): the object count, the summed levels of each
  // criteria set (average LOD = sum / objects), and the thesis's LOD map evaluated offline on
  // the same frame (apps/gazelod/eval/lod_map_frame.hpp; nothing it picks is drawn).
  std::int64_t objects = 0;
  std::uint64_t lod_sum_drawn = 0;
  std::uint64_t lod_sum_size_only = 0;
  std::uint64_t lod_sum_size_eccentricity = 0;
  std::uint64_t lod_sum_size_velocity = 0;
  std::uint64_t triangles_lod_map = 0;
  std::uint64_t lod_sum_lod_map = 0;
  // The same restricted to the objects in the view frustum this frame, per set in the order
  // none, size, size+eccentricity, size+velocity, drawn, lod map.
  std::int64_t objects_in_view = 0;
  std::array<std::uint64_t, 6> in_view_triangles{};
  std::array<std::uint64_t, 6> in_view_lod_sum{};
  // The visibility audit against the simulator's truth (run/audit.hpp); available = false
  // without ground truth or with --no-audit (its frames.csv cells are then empty).
  AuditFrame audit;
  // Cluster meshes (--scene with cluster hierarchies, clusters/scene.hpp), per eye: the
  // drawn cut's triangles, the perceptual cut's (before the switch policy), full detail; and
  // their audit (clusters/audit.hpp).
  std::uint64_t cluster_triangles_drawn = 0;
  std::uint64_t cluster_triangles_perceptual = 0;
  std::uint64_t cluster_triangles_full = 0;
  ClusterAuditFrame cluster_audit;
};

struct RunInfo {
  std::string scenario;
  std::string hmd;
  std::string runtime;
  std::string device;    // Vulkan device name
  std::string criteria;  // "size,eccentricity,velocity"
  double budget_ms = 0.0;
};

// One criteria set over a run: triangles summed over frames (per eye) and the mean level
// over every object of every frame.
struct SetTotals {
  std::uint64_t triangles = 0;
  double average_lod = 0.0;
};

struct RunSummary {
  std::int64_t frames = 0;
  std::string interrupted;  // "" = ran to its end; else the signal that stopped it ("SIGINT")
  double mean_frame_ms = 0.0;
  double p95_frame_ms = 0.0;
  double max_frame_ms = 0.0;
  double mean_select_ms = 0.0;
  std::uint64_t triangles_drawn = 0;  // summed over frames, per eye
  std::uint64_t triangles_full = 0;
  std::array<std::uint64_t, kMaxReportedLods> lod_histogram{};
  // Of the perceptual choice over every object (run/shares.hpp).
  ReductionShares shares;
  std::int64_t frames_over_budget = 0;
  std::int64_t gaze_valid_frames = 0;
  std::int64_t saccades = 0;
  // Gaze samples the plugin's conditioning refused (NaN, zero, backwards in time): never in a
  // decision, but said.
  std::int64_t gaze_bad_samples = 0;
  // Criteria sets ("none" = every object at level 0; "drawn" = the run's own --criteria).
  SetTotals set_none, set_size, set_size_eccentricity, set_size_velocity, set_drawn, set_lod_map;
  // Over the objects in view only (FrameRecord::in_view_*), same order; average_lod per
  // object in view.
  std::array<SetTotals, 6> in_view{};
  // Of what was drawn in view (the Reddy 1998 tables' definition: his renderer counted the
  // objects in view, as drawn).
  ReductionShares in_view_shares;
  // Whether the LOD-map thesis's policy was evaluated beside the plugin (RunOptions::lod_map);
  // its sets are zero otherwise and the reports leave them out.
  bool lod_map_evaluated = false;
  double objects_in_view_mean = 0.0;
  // summarize() sums the frames' audits; a caller without ground truth sets audit.reason.
  AuditSummary audit;
  // summarize() sums the cluster triangles and audits; the caller sets the scene's counts.
  ClusterRunSummary clusters;
};

RunSummary summarize(const std::vector<FrameRecord>& frames, double budget_ms);

void print_summary(const RunInfo& info, const RunSummary& s, std::ostream& out, bool breakdown = false);
// Writes summary.json, frames.csv, frames.svg and (when the audit is available) audit.svg into
// `dir` (created if missing). Throws std::runtime_error naming the file that could not be written.
void write_report_files(const std::filesystem::path& dir, const RunInfo& info, const RunSummary& s,
                        const std::vector<FrameRecord>& frames);

// audit.svg: in-view objects drawn coarser than the oracle (and the largest excess), LOD
// switches and triangles in view (drawn, oracle) over time, suppression windows shaded; with a
// cluster audit in any frame, the same per in-view leaf of the cluster meshes (coarser than
// the oracle's cut, largest excess depth, leaves not covered exactly once, switches, triangles).
Plot audit_plot(const RunInfo& info, const AuditSummary& s, const std::vector<FrameRecord>& frames);

}  // namespace gazelod::cli
