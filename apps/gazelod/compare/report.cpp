// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/compare/report.hpp"

#include "apps/gazelod/compare/svg.hpp"
#include "auxiliary/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace gazelod::cli {
namespace {

double per_frame(const SetResult& s, std::int64_t frames) {
  return frames > 0 ? static_cast<double>(s.triangles) / static_cast<double>(frames) : 0.0;
}

nlohmann::json set_json(const SetResult& s, std::int64_t frames) {
  return {{"triangles", per_frame(s, frames)}, {"triangles_total", s.triangles}, {"average_lod", s.average_lod}};
}

}  // namespace

nlohmann::json compare_json(const std::vector<HmdComparison>& results) {
  nlohmann::json hmds = nlohmann::json::array();
  for (const HmdComparison& c : results) {
    nlohmann::json runs = nlohmann::json::object();
    for (std::size_t i = 0; i < kCriteriaSets.size(); ++i) runs[kCriteriaSets[i]] = set_json(c.sets[i], c.frames);
    hmds.push_back({{"hmd", c.hmd},
                    {"xi_cpd", c.xi_cpd},
                    {"eccentricity_threshold_deg", c.eccentricity_threshold_deg},
                    {"velocity_threshold_dps", c.velocity_threshold_dps},
                    {"frames", c.frames},
                    {"eye_tracker", c.eye_tracker},
                    {"gaze_valid_share", c.gaze_valid_share},
                    {"runs", runs},
                    {"lod_map", set_json(c.lod_map, c.frames)},
                    {"shares",
                     {{"size", c.shares.size},
                      {"eccentricity", c.shares.eccentricity},
                      {"velocity", c.shares.velocity},
                      {"interaction", c.shares.interaction}}},
                    {"audit", audit_json(c.audit)}});
  }
  return {{"hmds", hmds}};
}

void print_compare_table(const std::vector<HmdComparison>& results, std::ostream& out, bool breakdown) {
  char line[256];
  for (const HmdComparison& c : results) {
    std::snprintf(
        line, sizeof line,
        "\n== %s: xi %.2f c/deg, eccentricity threshold %.1f deg, velocity threshold %.1f deg/s, %lld frames%s ==\n",
        c.hmd.c_str(), c.xi_cpd, c.eccentricity_threshold_deg, c.velocity_threshold_dps,
        static_cast<long long>(c.frames), c.eye_tracker ? "" : ", no eye tracker: head-fixed gaze");
    out << line;
    std::snprintf(line, sizeof line, "%-28s %14s %9s %11s\n", "criteria", "triangles/frame", "of none", "average LOD");
    out << line;
    const double none = per_frame(c.sets[0], c.frames);
    const auto row = [&](const char* name, const SetResult& s) {
      const double t = per_frame(s, c.frames);
      std::snprintf(line, sizeof line, "%-28s %14.0f %8.1f%% %11.3f\n", name, t, none > 0.0 ? 100.0 * t / none : 0.0,
                    s.average_lod);
      out << line;
    };
    for (std::size_t i = 0; i < kCriteriaSets.size(); ++i) row(kCriteriaSets[i], c.sets[i]);
    row("lod map (thesis)", c.lod_map);
    std::snprintf(
        line, sizeof line, "reduction owed to: size %.1f%%, eccentricity %.1f%%, velocity %.1f%%, interaction %.1f%%\n",
        100 * c.shares.size, 100 * c.shares.eccentricity, 100 * c.shares.velocity, 100 * c.shares.interaction);
    out << line;
    print_audit(c.audit, out, breakdown);
  }
}

void write_compare_chart(const std::vector<HmdComparison>& results, const std::filesystem::path& dir) {
  BarChart chart;
  chart.title = "gazelod compare: triangles per frame (per eye) by criteria set";
  chart.y_label = "% of full detail";
  static const char* colours[] = {"#7f7f7f", "#1f77b4", "#2ca02c", "#ff7f0e", "#d62728", "#9467bd"};
  for (std::size_t i = 0; i < kCriteriaSets.size() + 1; ++i)
    chart.series.push_back({i < kCriteriaSets.size() ? kCriteriaSets[i] : "lod map (thesis)", colours[i], {}});
  for (const HmdComparison& c : results) {
    chart.groups.push_back(c.hmd);
    const double none = static_cast<double>(c.sets[0].triangles);
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
      const SetResult& s = i < kCriteriaSets.size() ? c.sets[i] : c.lod_map;
      chart.series[i].values.push_back(none > 0.0 ? 100.0 * static_cast<double>(s.triangles) / none : 0.0);
    }
  }
  std::ostringstream svg;
  write_bar_chart(chart, svg);
  aux::write_file_atomic((dir / "compare.svg").string(), svg.str());  // never a partial chart
}

}  // namespace gazelod::cli
