// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/clusters/eval_report.hpp"

#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/plots/svg_plot.hpp"
#include "gaze/atomic_file.hpp"

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

nlohmann::json parse_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw UsageError(path.string() + ": cannot read (the run wrote no report)", 1);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(path.string() + ": " + e.what(), 1);
  }
}

// The number at a JSON pointer ("/audit/visible_degradations/share"), finite.
double number_at(const nlohmann::json& j, const std::string& pointer, const std::string& source) {
  const nlohmann::json::json_pointer p(pointer);
  if (!j.contains(p)) throw UsageError(source + ": " + pointer + ": missing", 1);
  const nlohmann::json& v = j.at(p);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw UsageError(source + ": " + pointer + ": not a finite number", 1);
  return v.get<double>();
}

// frames.csv's t_s and one triangle column, one value per frame.
void read_frames_csv(const std::filesystem::path& path, const std::string& column, ClusterEvalSide& side) {
  std::ifstream in(path);
  if (!in) throw UsageError(path.string() + ": cannot read", 1);
  std::string line;
  if (!std::getline(in, line)) throw UsageError(path.string() + ":1: empty file", 1);
  int t_col = -1, tri_col = -1, col = 0;
  std::istringstream header(line);
  for (std::string name; std::getline(header, name, ','); ++col) {
    if (name == "t_s") t_col = col;
    if (name == column) tri_col = col;
  }
  if (t_col < 0 || tri_col < 0)
    throw UsageError(path.string() + ":1: no column '" + (t_col < 0 ? std::string("t_s") : column) + "'", 1);
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    std::istringstream row(line);
    double t = NAN, tri = NAN;
    col = 0;
    for (std::string cell; std::getline(row, cell, ','); ++col) {
      if (col != t_col && col != tri_col) continue;
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (cell.empty() || end != cell.c_str() + cell.size() || !std::isfinite(v))
        throw UsageError(path.string() + ":" + std::to_string(number) + ": column " + std::to_string(col + 1) + ": '" +
                             cell + "' is not a number",
                         1);
      (col == t_col ? t : tri) = v;
    }
    if (!std::isfinite(t) || !std::isfinite(tri))
      throw UsageError(path.string() + ":" + std::to_string(number) + ": too few columns", 1);
    side.t_s.push_back(t);
    side.triangles.push_back(tri);
  }
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

ClusterEvalSide read_cluster_eval_side(const std::filesystem::path& dir, bool clusters) {
  const auto path = dir / "summary.json";
  const nlohmann::json j = parse_file(path);
  const std::string src = path.string();
  ClusterEvalSide s;
  s.frames = static_cast<std::int64_t>(number_at(j, "/frames", src));
  if (s.frames <= 0) throw UsageError(src + ": /frames: no frames", 1);
  const double frames = static_cast<double>(s.frames);
  if (clusters && !(j.contains("clusters") && j["clusters"].is_object()))
    throw UsageError(src +
                         ": no cluster figures (no \"clusters\" object): this gazelod run did not draw cluster "
                         "cuts (it needs `gazelod run --scene F --scene-placement file` with cluster meshes)",
                     1);
  const std::string root = clusters ? "/clusters" : "";
  s.triangles_per_frame = number_at(j, root + "/triangles_drawn", src) / frames;
  s.full_triangles_per_frame = number_at(j, root + "/triangles_full", src) / frames;
  const std::string audit = root + "/audit";
  if (!j.contains(nlohmann::json::json_pointer(audit + "/available")) ||
      !j.at(nlohmann::json::json_pointer(audit + "/available")).is_boolean() ||
      !j.at(nlohmann::json::json_pointer(audit + "/available")).get<bool>())
    throw UsageError(src + ": " + audit + ": the visibility audit is not available", 1);
  s.drawn_over_oracle = number_at(j, audit + "/triangles_in_view/drawn_over_oracle", src);
  s.in_view_triangles_per_frame = number_at(j, audit + "/triangles_in_view/drawn", src) / frames;
  const std::string unit = clusters ? "leaf" : "object";
  s.audit_unit_frames =
      static_cast<std::int64_t>(number_at(j, audit + "/visible_degradations/" + unit + "_frames", src));
  s.degraded_share = number_at(j, audit + "/visible_degradations/share", src);
  s.switches_per_unit_s = number_at(j, audit + "/switches/outside_suppression/per_" + unit + "_second", src);
  if (clusters) {
    const std::string t = audit + "/triangles_in_view/";
    s.oracle_in_view_per_frame = number_at(j, t + "oracle", src) / frames;
    s.oracle_size_only_per_frame = number_at(j, t + "oracle_by_criterion_alone/size", src) / frames;
    s.oracle_eccentricity_only_per_frame = number_at(j, t + "oracle_by_criterion_alone/eccentricity", src) / frames;
    s.oracle_velocity_only_per_frame = number_at(j, t + "oracle_by_criterion_alone/velocity", src) / frames;
  }
  read_frames_csv(dir / "frames.csv", clusters ? "cluster_triangles_drawn" : "triangles_drawn", s);
  return s;
}

double read_mean_frame_ms(const std::filesystem::path& dir) {
  const auto path = dir / "summary.json";
  return number_at(parse_file(path), "/frame_time_ms/mean", path.string());
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
    gaze::write_file_atomic(file.string(), svg.str());
  } catch (const gaze::WriteError& e) {
    throw UsageError(std::string("--out: ") + e.what(), 1);
  }
}

}  // namespace gazelod::cli
