// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/eval/tables.hpp"

#include "apps/gazelod/compare/svg.hpp"
#include "apps/gazelod/plots/svg_plot.hpp"
#include "auxiliary/atomic_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gazelod::cli {
namespace {

std::string f(const char* format, double v) {
  char s[64];
  std::snprintf(s, sizeof s, format, v);
  return s;
}

double ratio(double a, double b) {
  return b > 0.0 ? a / b : 0.0;
}

// Reddy 1998's Figure 6 measure: the share of the average-LOD reduction (above level 1) that
// eccentricity + velocity alone achieve; the rest is owed to size.
double ecc_vel_share_of_lod(const Figure6Row& r) {
  return ratio(r.no_size.lod_drawn - 1.0, r.all.lod_drawn - 1.0);
}

// Whole or not at all (auxiliary/atomic_file.hpp): a failed write leaves no cut plot.
template <class Write>
void write_file(const std::filesystem::path& path, Write write) {
  std::ostringstream out;
  write(out);
  aux::write_file_atomic(path.string(), out.str());
}

}  // namespace

void figure5_table(const std::vector<Figure5Row>& rows, std::ostream& md) {
  md << "| objects | frame rate, no LOD (Hz) | frame rate, perceptual LOD (Hz) | speed-up | triangles/frame, no LOD | "
        "triangles/frame, perceptual | triangle reduction | LOD map (thesis) triangles/frame | LOD map reduction |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Figure5Row& r : rows)
    md << "| " << r.objects << " | " << f("%.1f", r.none.frame_rate_hz) << " | " << f("%.1f", r.all.frame_rate_hz)
       << " | " << f("%.2fx", ratio(r.all.frame_rate_hz, r.none.frame_rate_hz)) << " | "
       << f("%.0f", r.none.triangles_per_frame) << " | " << f("%.0f", r.all.triangles_per_frame) << " | "
       << f("%.2fx", ratio(r.all.full_triangles_per_frame, r.all.triangles_per_frame)) << " | "
       << f("%.0f", r.all.triangles_map) << " | "
       << f("%.2fx", ratio(r.all.full_triangles_per_frame, r.all.triangles_map)) << " |\n";
}

void figure6_table(const std::vector<Figure6Row>& rows, std::ostream& md) {
  md << "| objects | in view (mean) | average LOD, all criteria | average LOD, eccentricity + velocity only | average "
        "LOD, size only | "
        "ecc + vel share of the LOD reduction | size share (triangles) | eccentricity share | velocity share | "
        "LOD map (thesis) average LOD |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Figure6Row& r : rows)
    md << "| " << r.objects << " | " << f("%.1f", r.all.objects_in_view) << " | " << f("%.3f", r.all.lod_drawn) << " | "
       << f("%.3f", r.no_size.lod_drawn) << " | " << f("%.3f", r.all.lod_size) << " | "
       << f("%.1f%%", 100 * ecc_vel_share_of_lod(r)) << " | " << f("%.1f%%", 100 * r.all.shares.size) << " | "
       << f("%.1f%%", 100 * r.all.shares.eccentricity) << " | " << f("%.1f%%", 100 * r.all.shares.velocity) << " | "
       << f("%.3f", r.all.lod_map) << " |\n";
}

void head_turn_table(const std::vector<HeadTurnRow>& rows, std::ostream& md) {
  md << "| head turn (deg/s) | in view (mean) | average LOD, all | size only | size + eccentricity | size + velocity | "
        "triangles, % of full | size share | eccentricity share | velocity share | interaction | "
        "LOD map average LOD | LOD map triangles, % of full |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const HeadTurnRow& r : rows) {
    const EvalRun& a = r.all;
    md << "| " << f("%.0f", r.rate_deg_s) << " | " << f("%.1f", a.objects_in_view) << " | " << f("%.3f", a.lod_drawn)
       << " | " << f("%.3f", a.lod_size) << " | " << f("%.3f", a.lod_size_ecc) << " | " << f("%.3f", a.lod_size_vel)
       << " | " << f("%.1f%%", 100 * ratio(a.triangles_per_frame, a.full_triangles_per_frame)) << " | "
       << f("%.1f%%", 100 * a.shares.size) << " | " << f("%.1f%%", 100 * a.shares.eccentricity) << " | "
       << f("%.1f%%", 100 * a.shares.velocity) << " | " << f("%.1f%%", 100 * a.shares.interaction) << " | "
       << f("%.3f", a.lod_map) << " | " << f("%.1f%%", 100 * ratio(a.triangles_map, a.full_triangles_per_frame))
       << " |\n";
  }
}

void write_eval_plots(const std::vector<Figure5Row>& f5, const std::vector<Figure6Row>& f6,
                      const std::vector<HeadTurnRow>& turns, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!f5.empty()) {
    Plot p;
    p.title = "Reddy 1998 Figure 5 with gazelod's renderer: frame rate without and with perceptual LOD";
    p.x_label = "objects (plotted at their index: 10, 20, 50, 100, 200, 500, 1000)";
    PlotSeries none{"no LOD", "#1f77b4", {}}, all{"perceptual LOD", "#d62728", {}}, up{"speed-up", "#2ca02c", {}};
    for (std::size_t i = 0; i < f5.size(); ++i) {
      p.x.push_back(static_cast<double>(i));
      none.y.push_back(f5[i].none.frame_rate_hz);
      all.y.push_back(f5[i].all.frame_rate_hz);
      up.y.push_back(ratio(f5[i].all.frame_rate_hz, f5[i].none.frame_rate_hz));
    }
    p.panels.push_back({"frame rate (Hz)", {none, all}});
    p.panels.push_back({"speed-up (x)", {up}});
    write_file(dir / "figure5.svg", [&](std::ostream& o) { write_svg(p, o); });
  }
  if (!f6.empty()) {
    BarChart c;
    c.title = "Reddy 1998 Figure 6: average LOD (1..4, higher = coarser), still head";
    c.y_label = "average LOD";
    c.series = {{"all criteria", "#d62728", {}},
                {"eccentricity + velocity", "#1f77b4", {}},
                {"size only", "#2ca02c", {}},
                {"LOD map (thesis)", "#9467bd", {}}};
    for (const Figure6Row& r : f6) {
      c.groups.push_back(std::to_string(r.objects) + " objects");
      c.series[0].values.push_back(r.all.lod_drawn);
      c.series[1].values.push_back(r.no_size.lod_drawn);
      c.series[2].values.push_back(r.all.lod_size);
      c.series[3].values.push_back(r.all.lod_map);
    }
    write_file(dir / "figure6.svg", [&](std::ostream& o) { write_bar_chart(c, o); });
  }
  if (!turns.empty()) {
    BarChart c;
    c.title = "Head turns: share of the triangle reduction owed to each criterion";
    c.y_label = "% of the reduction";
    c.series = {{"size", "#2ca02c", {}}, {"eccentricity", "#1f77b4", {}}, {"velocity", "#ff7f0e", {}}};
    for (const HeadTurnRow& r : turns) {
      c.groups.push_back(f("%.0f deg/s", r.rate_deg_s));
      c.series[0].values.push_back(100 * r.all.shares.size);
      c.series[1].values.push_back(100 * r.all.shares.eccentricity);
      c.series[2].values.push_back(100 * r.all.shares.velocity);
    }
    write_file(dir / "head_turns.svg", [&](std::ostream& o) { write_bar_chart(c, o); });
  }
}

}  // namespace gazelod::cli
