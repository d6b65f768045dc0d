// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/eval_report.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/plots/svg_plot.hpp"
#include "auxiliary/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

namespace gazelod::cli {
namespace {

double ratio(double a, double b) {
  return b > 0.0 && std::isfinite(a) ? a / b : 0.0;
}

std::string fmt(const char* format, double v) {
  char s[96];
  std::snprintf(s, sizeof s, format, v);
  return s;
}

nlohmann::json side_json(const ClusterEvalSide& s) {
  return {{"frames", s.frames},
          {"triangles_per_frame", s.triangles_per_frame},
          {"full_triangles_per_frame", s.full_triangles_per_frame},
          {"share_of_full", ratio(s.triangles_per_frame, s.full_triangles_per_frame)},
          {"drawn_over_oracle", s.drawn_over_oracle},
          {"in_view_triangles_per_frame", s.in_view_triangles_per_frame},
          {"audit_unit_frames", s.audit_unit_frames},
          {"visible_degradations_share", s.degraded_share},
          {"switches_per_unit_second", s.switches_per_unit_s},
          {"oracle_in_view_triangles_per_frame",
           {{"all", s.oracle_in_view_per_frame},
            {"size_alone", s.oracle_size_only_per_frame},
            {"eccentricity_alone", s.oracle_eccentricity_only_per_frame},
            {"velocity_alone", s.oracle_velocity_only_per_frame}}}};
}

// Means over bins of consecutive frames, at most `points` of them (a long run's SVG stays small
// and the plotted mean stays the run's mean).
std::vector<double> binned(const std::vector<double>& v, std::size_t points) {
  if (v.size() <= points || points == 0) return v;
  std::vector<double> out;
  const std::size_t per = (v.size() + points - 1) / points;
  for (std::size_t i = 0; i < v.size(); i += per) {
    const std::size_t end = std::min(v.size(), i + per);
    double sum = 0.0;
    for (std::size_t k = i; k < end; ++k) sum += v[k];
    out.push_back(sum / static_cast<double>(end - i));
  }
  return out;
}

}  // namespace

ClusterEvalSide cluster_eval_side(const RunSummary& run, const std::vector<FrameRecord>& frames, bool clusters,
                                  const std::string& source) {
  ClusterEvalSide s;
  s.frames = run.frames;
  if (s.frames <= 0) throw UsageError(source + ": the run had no frames", 1);
  const double n = static_cast<double>(s.frames);
  if (clusters && run.clusters.meshes == 0)
    throw UsageError(source +
                         ": no cluster figures: this run drew no cluster cuts (it needs a scene with cluster "
                         "meshes, placed by the file)",
                     1);
  const auto per_frame = [n](auto v) { return static_cast<double>(v) / n; };
  if (clusters) {
    const ClusterAuditSummary& a = run.clusters.audit;
    if (!a.available) throw UsageError(source + ": the cluster meshes' visibility audit is not available", 1);
    s.triangles_per_frame = per_frame(run.clusters.triangles_drawn);
    s.full_triangles_per_frame = per_frame(run.clusters.triangles_full);
    s.drawn_over_oracle = a.triangle_ratio;
    s.in_view_triangles_per_frame = per_frame(a.drawn_triangles);
    s.audit_unit_frames = a.leaf_frames;
    s.degraded_share = a.degraded_share;
    s.switches_per_unit_s = a.switches_per_leaf_s_fixation;
    s.oracle_in_view_per_frame = per_frame(a.oracle_triangles);
    s.oracle_size_only_per_frame = per_frame(a.oracle_size_only_triangles);
    s.oracle_eccentricity_only_per_frame = per_frame(a.oracle_eccentricity_only_triangles);
    s.oracle_velocity_only_per_frame = per_frame(a.oracle_velocity_only_triangles);
  } else {
    const AuditSummary& a = run.audit;
    if (!a.available) throw UsageError(source + ": the visibility audit is not available: " + a.reason, 1);
    s.triangles_per_frame = per_frame(run.triangles_drawn);
    s.full_triangles_per_frame = per_frame(run.triangles_full);
    s.drawn_over_oracle = a.triangle_ratio;
    s.in_view_triangles_per_frame = per_frame(a.drawn_triangles);
    s.audit_unit_frames = a.object_frames;
    s.degraded_share = a.degraded_share;
    s.switches_per_unit_s = a.switches_fixation.per_object_s;
  }
  s.t_s.reserve(frames.size());
  s.triangles.reserve(frames.size());
  for (const FrameRecord& f : frames) {
    s.t_s.push_back(f.t_s);
    s.triangles.push_back(static_cast<double>(clusters ? f.cluster_triangles_drawn : f.triangles_drawn));
  }
  return s;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

double ClusterEvalReport::triangle_ratio(std::size_t a, std::size_t b, bool in_view) const {
  if (a >= columns.size() || b >= columns.size() || !columns[a].side || !columns[b].side) return 0.0;
  if (in_view) return ratio(columns[a].side->in_view_triangles_per_frame, columns[b].side->in_view_triangles_per_frame);
  return ratio(columns[a].side->triangles_per_frame, columns[b].side->triangles_per_frame);
}

bool ClusterEvalReport::target_met() const {
  return columns.size() > kClustersColumn && columns[kClustersColumn].side && columns[kPerObjectColumn].side &&
         triangle_ratio(kClustersColumn, kPerObjectColumn) <= kClusterTriangleRatioTarget &&
         columns[kClustersColumn].side->degraded_share <= kClusterDegradationTarget;
}

std::string cluster_eval_markdown(const ClusterEvalReport& r) {
  std::ostringstream md;
  const std::int64_t frames = r.columns.empty() || !r.columns[0].side ? 0 : r.columns[0].side->frames;
  md << "Scene: " << r.scene << "; scenario " << r.scenario << "; " << frames << " frames"
     << (r.machine.empty() ? "" : "; " + r.machine) << ".\n\n";
  // One row: a label, then each column's cell (n/a where the column was not measured).
  auto row = [&](const std::string& label, const std::function<std::string(const ClusterEvalColumn&)>& cell) {
    md << "| " << label;
    for (const ClusterEvalColumn& c : r.columns) md << " | " << (c.side ? cell(c) : std::string("n/a"));
    md << " |\n";
  };
  md << "|";
  for (const ClusterEvalColumn& c : r.columns) md << " | " << c.title;
  md << " |\n|---";
  for (std::size_t i = 0; i < r.columns.size(); ++i) md << "|---:";
  md << "|\n";
  row("triangles drawn per frame (mean, per eye)",
      [](const auto& c) { return fmt("%.0f", c.side->triangles_per_frame); });
  row("vs full detail", [](const auto& c) {
    return fmt("%.2f%%", 100 * ratio(c.side->triangles_per_frame, c.side->full_triangles_per_frame)) + " of " +
           fmt("%.0f", c.side->full_triangles_per_frame);
  });
  row("cluster LOD's triangles over this column's", [&](const auto& c) {
    const auto& k = r.columns[kClustersColumn];
    return k.side ? fmt("%.3f", ratio(k.side->triangles_per_frame, c.side->triangles_per_frame)) : std::string("n/a");
  });
  row("of those, in the first eye's view (sphere in view: what a renderer culling by sphere draws)",
      [](const auto& c) { return fmt("%.0f", c.side->in_view_triangles_per_frame); });
  row("cluster LOD's in-view triangles over this column's", [&](const auto& c) {
    const auto& k = r.columns[kClustersColumn];
    return k.side ? fmt("%.3f", ratio(k.side->in_view_triangles_per_frame, c.side->in_view_triangles_per_frame))
                  : std::string("n/a");
  });
  row("in view: drawn / what the true gaze needs (its oracle)",
      [](const auto& c) { return fmt("%.3f", c.side->drawn_over_oracle); });
  row("visible degradations outside suppression", [](const auto& c) {
    return fmt("%.3f%%", 100 * c.side->degraded_share) + " of " + std::to_string(c.side->audit_unit_frames) +
           (c.clusters ? " leaf-frames" : " object-frames");
  });
  row("switches per object-s / leaf-s outside suppression",
      [](const auto& c) { return fmt("%.3f", c.side->switches_per_unit_s); });
  if (r.rendered_frames > 0) {
    row("rendered (" + std::to_string(r.rendered_rounds) + " interleaved rounds of " +
            std::to_string(r.rendered_frames) + " frames): median of the rounds' mean frame time (range)",
        [](const auto& c) {
          if (!(c.frame_ms > 0.0)) return std::string("n/a");
          const auto [lo, hi] = std::minmax_element(c.frame_ms_rounds.begin(), c.frame_ms_rounds.end());
          std::string cell = fmt("%.1f ms", c.frame_ms);
          if (c.frame_ms_rounds.size() > 1) cell += fmt(" (%.1f", *lo) + fmt("-%.1f)", *hi);
          return cell;
        });
    row("rendered: triangles per frame (mean, per eye)",
        [](const auto& c) { return c.frame_ms > 0.0 ? fmt("%.0f", c.rendered_triangles) : std::string("n/a"); });
  }
  md << "\n";
  for (const ClusterEvalColumn& c : r.columns)
    if (!c.side) md << "Not measured: " << c.title << ": " << c.missing << "\n";
  const auto& k = r.columns.size() > kClustersColumn ? r.columns[kClustersColumn] : ClusterEvalColumn{};
  md << "Target (cluster LOD <= 1/3 of per-object LOD's triangles at <= 0.5 % visible degradations): ";
  if (!k.side || !r.columns[kPerObjectColumn].side)
    md << "not measured\n";
  else
    md << (r.target_met() ? "met" : "MISSED") << " (ratio "
       << fmt("%.3f", r.triangle_ratio(kClustersColumn, kPerObjectColumn)) << ", degradations "
       << fmt("%.3f%%", 100 * k.side->degraded_share) << "; in the first eye's view "
       << fmt("%.3f", r.triangle_ratio(kClustersColumn, kPerObjectColumn, true)) << ")\n";
  if (k.side)
    md << "\nThe cluster oracle (the cut at the true gaze) in the first eye's view, triangles per frame: "
       << fmt("%.0f", k.side->oracle_in_view_per_frame) << " with every criterion; each alone: size "
       << fmt("%.0f", k.side->oracle_size_only_per_frame) << ", eccentricity "
       << fmt("%.0f", k.side->oracle_eccentricity_only_per_frame) << ", velocity "
       << fmt("%.0f", k.side->oracle_velocity_only_per_frame) << "\n";
  return md.str();
}

nlohmann::json cluster_eval_json(const ClusterEvalReport& r) {
  nlohmann::json j = {{"scene", r.scene}, {"scenario", r.scenario}, {"machine", r.machine}};
  for (const ClusterEvalColumn& c : r.columns) {
    nlohmann::json col = c.side ? side_json(*c.side) : nlohmann::json{{"missing", c.missing}};
    col["title"] = c.title;
    if (r.rendered_frames > 0 && c.frame_ms > 0.0)
      col["rendered"] = {{"frames", r.rendered_frames},
                         {"rounds", c.frame_ms_rounds.size()},
                         {"frame_ms", c.frame_ms},
                         {"frame_ms_rounds", c.frame_ms_rounds},
                         {"triangles_per_frame", c.rendered_triangles}};
    j[c.key] = col;
  }
  j["triangle_ratio"] = r.triangle_ratio(kClustersColumn, kPerObjectColumn);
  j["triangle_ratio_same_rule"] = r.triangle_ratio(kClustersColumn, kSameRuleColumn);
  j["in_view_triangle_ratio"] = r.triangle_ratio(kClustersColumn, kPerObjectColumn, true);
  j["target"] = {{"triangle_ratio_max", kClusterTriangleRatioTarget},
                 {"degradations_max", kClusterDegradationTarget},
                 {"met", r.target_met()}};
  return j;
}

void write_cluster_eval_svg(const ClusterEvalReport& r, const std::filesystem::path& file) {
  constexpr std::size_t kPoints = 1500;
  static const char* kColours[] = {"#1f77b4", "#ff7f0e", "#d62728", "#9467bd"};
  Plot plot;
  plot.title = "gazelod eval clusters: triangles drawn per frame (per eye), " + r.scenario;
  plot.x_label = "time (s)";
  PlotPanel triangles{"triangles per frame", {}};
  for (std::size_t i = 0; i < r.columns.size(); ++i) {
    const ClusterEvalColumn& c = r.columns[i];
    if (!c.side) continue;
    if (plot.x.empty()) {
      plot.x = binned(c.side->t_s, kPoints);
      triangles.series.push_back(
          {"full detail", "#7f7f7f", std::vector<double>(plot.x.size(), c.side->full_triangles_per_frame)});
    }
    // The runs step the same scenario frame by frame; a shorter one is padded with gaps.
    std::vector<double> y = binned(c.side->triangles, kPoints);
    y.resize(plot.x.size(), NAN);
    triangles.series.push_back({c.title, kColours[i % 4], y});
  }
  plot.panels.push_back(triangles);
  std::ostringstream svg;
  write_svg(plot, svg);
  try {
    aux::write_file_atomic(file.string(), svg.str());
  } catch (const aux::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what(), 1);
  }
}

}  // namespace gazelod::cli
