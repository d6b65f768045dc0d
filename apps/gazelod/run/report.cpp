// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/run/report.hpp"

#include "auxiliary/text.hpp"

#include "apps/gazelod/run/signals.hpp"
#include "auxiliary/atomic_file.hpp"

#include "apps/gazelod/plots/svg_plot.hpp"
#include "auxiliary/json_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace gazelod::cli {
namespace {

double safe_ratio(double num, double den) {
  return den > 0.0 ? num / den : 0.0;
}

// Levels 0 to the coarsest that occurred (at least 0-3): what the reports list.
int reported_levels(const RunSummary& s) {
  int n = 4;
  for (int i = 0; i < kMaxReportedLods; ++i)
    if (s.lod_histogram[i] != 0) n = std::max(n, i + 1);
  return n;
}

}  // namespace

RunSummary summarize(const std::vector<FrameRecord>& frames, double budget_ms) {
  RunSummary s;
  s.frames = static_cast<std::int64_t>(frames.size());
  if (frames.empty()) {
    s.audit.reason = "no frame was audited";
    return s;
  }
  std::vector<double> ms;
  ms.reserve(frames.size());
  double perceptual = 0.0;
  std::uint64_t lods_drawn = 0, lods_size = 0, lods_se = 0, lods_sv = 0, lods_map = 0;
  double object_frames = 0.0, view_object_frames = 0.0;
  std::array<std::uint64_t, 6> view_lods{};
  for (const FrameRecord& f : frames) {
    ms.push_back(f.frame_ms);
    s.mean_frame_ms += f.frame_ms;
    s.mean_select_ms += f.select_ms;
    s.triangles_drawn += f.triangles_drawn;
    s.triangles_full += f.triangles_full;
    for (int i = 0; i < kMaxReportedLods; ++i) s.lod_histogram[i] += f.lod_histogram[i];
    // The shares compare like with like: every criteria set as the perceptual choice of the
    // frame (before the switch policy and the budget, which apply to the drawn set only).
    perceptual += static_cast<double>(f.triangles_perceptual);
    s.set_size.triangles += f.triangles_size_only;
    s.set_size_eccentricity.triangles += f.triangles_size_eccentricity;
    s.set_size_velocity.triangles += f.triangles_size_velocity;
    s.set_lod_map.triangles += f.triangles_lod_map;
    lods_drawn += f.lod_sum_drawn;
    lods_size += f.lod_sum_size_only;
    lods_se += f.lod_sum_size_eccentricity;
    lods_sv += f.lod_sum_size_velocity;
    lods_map += f.lod_sum_lod_map;
    object_frames += static_cast<double>(std::max<std::int64_t>(f.objects, 0));
    view_object_frames += static_cast<double>(std::max<std::int64_t>(f.objects_in_view, 0));
    for (std::size_t k = 0; k < s.in_view.size(); ++k) {
      s.in_view[k].triangles += f.in_view_triangles[k];
      view_lods[k] += f.in_view_lod_sum[k];
    }
    s.clusters.triangles_drawn += f.cluster_triangles_drawn;
    s.clusters.triangles_perceptual += f.cluster_triangles_perceptual;
    s.clusters.triangles_full += f.cluster_triangles_full;
    if (budget_ms > 0.0 && f.frame_ms > budget_ms) ++s.frames_over_budget;
    if (f.gaze_valid) ++s.gaze_valid_frames;
    if (f.saccade) ++s.saccades;
  }
  const double n = static_cast<double>(frames.size());
  s.mean_frame_ms /= n;
  s.mean_select_ms /= n;
  std::sort(ms.begin(), ms.end());
  // Nearest-rank 95th percentile.
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * n));
  s.p95_frame_ms = ms[std::clamp<size_t>(rank, 1, ms.size()) - 1];
  s.max_frame_ms = ms.back();
  s.set_none.triangles = s.triangles_full;
  s.set_drawn.triangles = s.triangles_drawn;
  s.set_drawn.average_lod = safe_ratio(static_cast<double>(lods_drawn), object_frames);
  s.set_size.average_lod = safe_ratio(static_cast<double>(lods_size), object_frames);
  s.set_size_eccentricity.average_lod = safe_ratio(static_cast<double>(lods_se), object_frames);
  s.set_size_velocity.average_lod = safe_ratio(static_cast<double>(lods_sv), object_frames);
  s.set_lod_map.average_lod = safe_ratio(static_cast<double>(lods_map), object_frames);
  for (std::size_t k = 0; k < s.in_view.size(); ++k)
    s.in_view[k].average_lod = safe_ratio(static_cast<double>(view_lods[k]), view_object_frames);
  s.objects_in_view_mean = view_object_frames / n;
  const auto as_double = [](std::uint64_t v) { return static_cast<double>(v); };
  s.shares = reduction_shares({as_double(s.set_none.triangles), as_double(s.set_size.triangles),
                               as_double(s.set_size_eccentricity.triangles), as_double(s.set_size_velocity.triangles),
                               perceptual});
  // in_view: none, size, size+eccentricity, size+velocity, drawn (FrameRecord::in_view_triangles).
  s.in_view_shares = reduction_shares({as_double(s.in_view[0].triangles), as_double(s.in_view[1].triangles),
                                       as_double(s.in_view[2].triangles), as_double(s.in_view[3].triangles),
                                       as_double(s.in_view[4].triangles)});
  std::vector<AuditFrame> audits;
  std::vector<ClusterAuditFrame> cluster_audits;
  audits.reserve(frames.size());
  cluster_audits.reserve(frames.size());
  for (const FrameRecord& f : frames) audits.push_back(f.audit), cluster_audits.push_back(f.cluster_audit);
  s.audit = summarize_audit(audits);
  s.clusters.audit = summarize_cluster_audit(cluster_audits);
  if (!s.audit.available) s.audit.reason = "no frame was audited";
  return s;
}

namespace {
void print_per_object(const RunSummary& s, std::ostream& out);
}  // namespace

void print_summary(const RunInfo& info, const RunSummary& s, std::ostream& out, bool breakdown) {
  char line[256];
  out << "\n== gazelod run: " << info.scenario << " ==\n";
  out << "hmd " << info.hmd << ", runtime " << info.runtime << ", device " << info.device << ", criteria "
      << info.criteria << "\n";
  std::snprintf(line, sizeof line, "frames          %lld%s\n", static_cast<long long>(s.frames),
                s.interrupted.empty() ? "" : (" (interrupted by " + s.interrupted + ")").c_str());
  out << line;
  std::snprintf(line, sizeof line, "frame time      mean %.3f ms, p95 %.3f ms, max %.3f ms (selection mean %.3f ms)\n",
                s.mean_frame_ms, s.p95_frame_ms, s.max_frame_ms, s.mean_select_ms);
  out << line;
  // A scene of cluster meshes only has no per-object lines to show (they would all read 0).
  const bool per_object = s.triangles_full > 0 || s.clusters.meshes == 0;
  if (!per_object) {
    out << "objects         every object is a cluster mesh (no per-object LOD)\n";
    print_cluster_run(s.clusters, s.frames, out);
  } else {
    print_per_object(s, out);
  }
  std::snprintf(
      line, sizeof line, "gaze            valid in %.1f%% of frames, %s",
      100.0 * safe_ratio(static_cast<double>(s.gaze_valid_frames), static_cast<double>(s.frames)),
      aux::counted(static_cast<std::uint64_t>(std::max<std::int64_t>(0, s.saccades)), "saccade", "saccades").c_str());
  out << line;
  if (s.gaze_bad_samples > 0) out << ", " << s.gaze_bad_samples << " bad samples refused (NaN, zero or backwards)";
  out << "\n";
  if (info.budget_ms > 0.0) {
    std::snprintf(line, sizeof line, "budget          %.3f ms, exceeded in %lld frames (%.1f%%)\n", info.budget_ms,
                  static_cast<long long>(s.frames_over_budget),
                  100.0 * safe_ratio(static_cast<double>(s.frames_over_budget), static_cast<double>(s.frames)));
    out << line;
  }
  if (per_object) print_audit(s.audit, out, breakdown);
  if (s.clusters.meshes > 0) print_cluster_audit(s.clusters.audit, out);
}

namespace {

// The per-object lines: triangles, the cluster meshes beside them, levels, the shares.
void print_per_object(const RunSummary& s, std::ostream& out) {
  char line[256];
  const double drawn_pct =
      100.0 * safe_ratio(static_cast<double>(s.triangles_drawn), static_cast<double>(s.triangles_full));
  std::snprintf(line, sizeof line, "triangles       %llu drawn of %llu at full detail (%.1f%%, per eye)\n",
                static_cast<unsigned long long>(s.triangles_drawn), static_cast<unsigned long long>(s.triangles_full),
                drawn_pct);
  out << line;
  print_cluster_run(s.clusters, s.frames, out);
  std::uint64_t total = 0;
  for (auto c : s.lod_histogram) total += c;
  out << "LOD histogram   ";
  for (int i = 0; i < reported_levels(s); ++i) {
    std::snprintf(line, sizeof line, "L%d %.1f%%  ", i,
                  100.0 * safe_ratio(static_cast<double>(s.lod_histogram[i]), static_cast<double>(total)));
    out << line;
  }
  out << "\n";
  std::snprintf(line, sizeof line,
                "reduction owed  size %.1f%%, eccentricity %.1f%%, velocity %.1f%%, interaction %.1f%%\n",
                100 * s.shares.size, 100 * s.shares.eccentricity, 100 * s.shares.velocity, 100 * s.shares.interaction);
  out << line;
}

}  // namespace

void write_report_files(const std::filesystem::path& dir, const RunInfo& info, const RunSummary& s,
                        const std::vector<FrameRecord>& frames) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create output folder " + dir.string() + ": " + ec.message());

  nlohmann::json j;
  j["scenario"] = info.scenario;
  j["hmd"] = info.hmd;
  j["runtime"] = info.runtime;
  j["device"] = info.device;
  j["criteria"] = info.criteria;
  j["frames"] = s.frames;
  j["interrupted"] = s.interrupted.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.interrupted);
  j["triangles_drawn"] = s.triangles_drawn;
  j["triangles_full"] = s.triangles_full;
  j["frame_time_ms"] = {{"mean", s.mean_frame_ms}, {"p95", s.p95_frame_ms}, {"max", s.max_frame_ms}};
  j["selection_time_ms"] = {{"mean", s.mean_select_ms}};
  j["lod_histogram"] =
      std::vector<std::uint64_t>(s.lod_histogram.begin(), s.lod_histogram.begin() + reported_levels(s));
  j["shares"] = {{"size", s.shares.size},
                 {"eccentricity", s.shares.eccentricity},
                 {"velocity", s.shares.velocity},
                 {"interaction", s.shares.interaction}};
  const auto set_json = [](const SetTotals& t) {
    return nlohmann::json{{"triangles", t.triangles}, {"average_lod", t.average_lod}};
  };
  j["criteria_sets"] = {{"none", set_json(s.set_none)},
                        {"size", set_json(s.set_size)},
                        {"size+eccentricity", set_json(s.set_size_eccentricity)},
                        {"size+velocity", set_json(s.set_size_velocity)},
                        {"drawn", set_json(s.set_drawn)}};
  // The LOD-map thesis's policy only when the run evaluated it (RunOptions::lod_map).
  if (s.lod_map_evaluated) j["lod_map"] = set_json(s.set_lod_map);
  j["in_view"] = {{"objects_per_frame", s.objects_in_view_mean}};
  static const char* view_names[] = {"none", "size", "size+eccentricity", "size+velocity", "drawn", "lod_map"};
  for (std::size_t k = 0; k < s.in_view.size(); ++k)
    if (k + 1 < s.in_view.size() || s.lod_map_evaluated) j["in_view"][view_names[k]] = set_json(s.in_view[k]);
  j["gaze_valid_frames"] = s.gaze_valid_frames;
  j["saccades"] = s.saccades;
  j["gaze_bad_samples"] = s.gaze_bad_samples;
  if (info.budget_ms > 0.0) {
    j["budget_ms"] = info.budget_ms;
    j["frames_over_budget"] = s.frames_over_budget;
  }
  j["audit"] = audit_json(s.audit);
  j["clusters"] = cluster_run_json(s.clusters);
  // Every file goes to a temporary beside it and replaces the old one only when complete
  // (auxiliary/atomic_file.hpp): a full disk leaves no cut file, and the error says why. The
  // largest first and the summary last, so a run that fails leaves no summary of it. A second
  // Ctrl-C, which ends the process at once, removes the temporary too (AtomicRunFile).
  AtomicRunFile csv_file((dir / "frames.csv").string());
  std::ostream& csv = csv_file.stream();
  csv << "frame,t_s,frame_ms,select_ms,predicted_ms,triangles_drawn,triangles_full,"
         "triangles_size_only,triangles_size_eccentricity,triangles_size_velocity,"
         "gaze_source,gaze_valid,saccade,head_speed_dps,eye_motion,plugin_suppressed,gaze_error_deg";
  const int levels = reported_levels(s);
  for (int i = 0; i < levels; ++i) csv << ",lod" << i;
  // The audit's columns (empty cells without ground truth): see run/audit.hpp's AuditFrame.
  csv << ",objects_in_view,audit_suppressed,audit_pursuit,audit_degraded,audit_excess_levels,"
         "audit_excess_max,audit_drawn_triangles,audit_oracle_triangles,audit_switches,audit_pursued";
  write_cluster_csv_header(csv);  // 0 and empty cells without cluster meshes
  csv << "\n";
  for (const FrameRecord& f : frames) {
    csv << f.index << ',' << f.t_s << ',' << f.frame_ms << ',' << f.select_ms << ',' << f.predicted_ms << ','
        << f.triangles_drawn << ',' << f.triangles_full << ',' << f.triangles_size_only << ','
        << f.triangles_size_eccentricity << ',' << f.triangles_size_velocity << ',' << f.gaze_source << ','
        << (f.gaze_valid ? 1 : 0) << ',' << (f.saccade ? 1 : 0) << ',' << f.head_speed_dps << ',' << f.eye_motion << ','
        << (f.plugin_suppressed ? 1 : 0) << ',' << f.gaze_error_deg;
    for (int i = 0; i < levels; ++i) csv << ',' << f.lod_histogram[i];
    csv << ',' << f.objects_in_view;
    const AuditFrame& a = f.audit;
    if (a.available)
      csv << ',' << (a.suppressed ? 1 : 0) << ',' << (a.pursuit ? 1 : 0) << ',' << a.degraded << ',' << a.excess_levels
          << ',' << a.excess_max << ',' << a.drawn_triangles << ',' << a.oracle_triangles << ',' << a.switches << ','
          << a.pursued;
    else
      csv << ",,,,,,,,,";
    write_cluster_csv_cells(csv, f.cluster_triangles_drawn, f.cluster_triangles_perceptual, f.cluster_audit);
    csv << "\n";
  }
  csv_file.commit();

  Plot plot;
  plot.title = "gazelod run: " + info.scenario + " on " + info.hmd;
  plot.x_label = "time (s)";
  PlotSeries drawn{"drawn", "#d62728", {}}, full{"full detail", "#1f77b4", {}};
  PlotSeries frame{"frame", "#2ca02c", {}}, select{"selection", "#9467bd", {}};
  PlotSeries head{"head speed", "#ff7f0e", {}};
  PlotSeries cluster_drawn{"cluster meshes drawn", "#8c564b", {}}, cluster_full{"cluster meshes full", "#17becf", {}};
  for (const FrameRecord& f : frames) {
    plot.x.push_back(f.t_s);
    drawn.y.push_back(static_cast<double>(f.triangles_drawn));
    full.y.push_back(static_cast<double>(f.triangles_full));
    cluster_drawn.y.push_back(static_cast<double>(f.cluster_triangles_drawn));
    cluster_full.y.push_back(static_cast<double>(f.cluster_triangles_full));
    frame.y.push_back(f.frame_ms);
    select.y.push_back(f.select_ms);
    head.y.push_back(f.head_speed_dps);
    if (f.saccade) plot.markers.push_back({f.t_s, "#7f7f7f"});
  }
  plot.panels.push_back({"triangles per eye", {drawn, full}});
  if (s.clusters.meshes > 0) plot.panels.push_back({"cluster triangles per eye", {cluster_drawn, cluster_full}});
  plot.panels.push_back({"time (ms)", {frame, select}});
  plot.panels.push_back({"head speed (deg/s)", {head}});
  plot.marker_legend = "saccade";
  AtomicRunFile svg((dir / "frames.svg").string());
  write_svg(plot, svg.stream());
  svg.commit();

  std::filesystem::remove(dir / "audit.svg", ec);  // never leave an older run's plot behind
  if (s.audit.available) {
    AtomicRunFile audit_svg((dir / "audit.svg").string());
    write_svg(audit_plot(info, s.audit, frames), audit_svg.stream());
    audit_svg.commit();
  }

  AtomicRunFile summary((dir / "summary.json").string());
  summary.stream() << aux::json_text(j, 2) << "\n";
  summary.commit();
}

Plot audit_plot(const RunInfo& info, const AuditSummary& s, const std::vector<FrameRecord>& frames) {
  Plot plot;
  char title[160];
  std::snprintf(title, sizeof title, " (suppression windows shaded: saccades, blinks, %.0f ms after a saccade)",
                s.after_saccade_ms);
  plot.title = "gazelod run audit: " + info.scenario + " on " + info.hmd + title;
  plot.x_label = "time (s)";
  PlotSeries degraded{"coarser than oracle", "#d62728", {}}, excess{"max excess (levels)", "#ff7f0e", {}};
  PlotSeries switches{"LOD switches", "#1f77b4", {}};
  PlotSeries drawn{"drawn", "#d62728", {}}, oracle{"oracle", "#2ca02c", {}};
  // Cluster meshes: the same per leaf (source cluster) in view, from the cluster audit.
  PlotSeries leaf_degraded{"coarser than oracle", "#d62728", {}}, leaf_excess{"max excess (depth)", "#ff7f0e", {}};
  PlotSeries leaf_switches{"cluster switches", "#1f77b4", {}}, leaf_miscovered{"not covered once", "#9467bd", {}};
  PlotSeries cluster_drawn{"drawn", "#d62728", {}}, cluster_oracle{"oracle", "#2ca02c", {}};
  bool clusters_audited = false;
  const double nan = std::nan("");
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const FrameRecord& f = frames[i];
    const ClusterAuditFrame& c = f.cluster_audit;
    clusters_audited = clusters_audited || c.available;
    leaf_degraded.y.push_back(c.available ? static_cast<double>(c.degraded) : nan);
    leaf_excess.y.push_back(c.available ? static_cast<double>(c.excess_depth_max) : nan);
    leaf_switches.y.push_back(c.available ? static_cast<double>(c.switches) : nan);
    leaf_miscovered.y.push_back(c.available ? static_cast<double>(c.miscovered) : nan);
    cluster_drawn.y.push_back(c.available ? static_cast<double>(c.drawn_triangles) : nan);
    cluster_oracle.y.push_back(c.available ? static_cast<double>(c.oracle_triangles) : nan);
    const AuditFrame& a = f.audit;
    plot.x.push_back(f.t_s);
    degraded.y.push_back(a.available ? static_cast<double>(a.degraded) : nan);
    excess.y.push_back(a.available ? static_cast<double>(a.excess_max) : nan);
    switches.y.push_back(a.available ? static_cast<double>(a.switches) : nan);
    drawn.y.push_back(a.available ? static_cast<double>(a.drawn_triangles) : nan);
    oracle.y.push_back(a.available ? static_cast<double>(a.oracle_triangles) : nan);
    // A window runs from its first suppressed frame to the next frame that is not.
    if (a.available && a.suppressed && (i == 0 || !frames[i - 1].audit.suppressed)) {
      std::size_t j = i;
      while (j + 1 < frames.size() && frames[j + 1].audit.suppressed) ++j;
      const double end = j + 1 < frames.size() ? frames[j + 1].t_s : frames[j].t_s;
      plot.spans.push_back({f.t_s, end, "#7f7f7f"});
    }
  }
  // A scene of cluster meshes only: no empty per-object panels.
  const bool objects_seen = std::any_of(frames.begin(), frames.end(),
                                        [](const FrameRecord& f) { return f.audit.available && f.audit.in_view > 0; });
  if (objects_seen || !clusters_audited) {
    plot.panels.push_back({"in-view objects", {degraded, excess}});
    plot.panels.push_back({"switches per frame", {switches}});
    plot.panels.push_back({"triangles in view", {drawn, oracle}});
  }
  if (clusters_audited) {
    plot.panels.push_back({"in-view cluster leaves", {leaf_degraded, leaf_excess, leaf_miscovered}});
    plot.panels.push_back({"leaf switches per frame", {leaf_switches}});
    plot.panels.push_back({"cluster triangles in view", {cluster_drawn, cluster_oracle}});
  }
  plot.span_legend = "suppression window";
  return plot;
}

}  // namespace gazelod::cli
