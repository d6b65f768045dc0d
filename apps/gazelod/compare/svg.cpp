// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/compare/svg.hpp"

#include "apps/gazelod/plots/axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gazelod::cli {

std::string svg_escape(const std::string& text) {
  std::string s;
  for (char c : text) {
    switch (c) {
      case '&':
        s += "&amp;";
        break;
      case '<':
        s += "&lt;";
        break;
      case '>':
        s += "&gt;";
        break;
      case '"':
        s += "&quot;";
        break;
      default:
        s += c;
    }
  }
  return s;
}

namespace {

constexpr double kFontPx = 12.0;

// A value in a tooltip (not on the axis): four significant digits.
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

void write_bar_chart(const BarChart& c, std::ostream& out) {
  double vmax = 0.0;
  for (const BarSeries& s : c.series)
    for (double v : s.values)
      if (std::isfinite(v)) vmax = std::max(vmax, v);
  const Axis ya = linear_axis(0.0, vmax > 0.0 ? vmax : 1.0, 6, true);
  double label_w = 0.0;
  for (double t : ya.ticks) label_w = std::max(label_w, text_width_px(tick_label(t), kFontPx));
  // Left: the axis title (rotated), the tick labels; bottom: the group labels, the legend rows.
  const double left = 20.0 + kFontPx + 10.0 + label_w + 8.0, right = 20, top = 44;
  const double w = std::max(200.0, c.width_px - left - right);
  const std::size_t ng = std::max<std::size_t>(c.groups.size(), 1), ns = std::max<std::size_t>(c.series.size(), 1);
  const double gw = w / static_cast<double>(ng), bw = gw * 0.8 / static_cast<double>(ns);
  double group_w = 0.0;
  for (const std::string& g : c.groups) group_w = std::max(group_w, text_width_px(g, kFontPx));
  const bool slanted = group_w > gw - 6.0;  // labels wider than their group: at 35 degrees
  const double group_h = slanted ? group_w * std::sin(35.0 * 3.14159265358979 / 180.0) + 14.0 : 16.0;
  // The legend in rows that fit the width.
  std::vector<std::vector<std::size_t>> rows(1);
  double row_x = 0.0;
  for (std::size_t s = 0; s < c.series.size(); ++s) {
    const double entry = 16.0 + text_width_px(c.series[s].label, kFontPx) + 20.0;
    if (row_x + entry > w && !rows.back().empty()) rows.emplace_back(), row_x = 0.0;
    rows.back().push_back(s);
    row_x += entry;
  }
  const double legend_h = 20.0 * static_cast<double>(rows.size());
  const double h = std::max(100.0, c.height_px - top - 12.0 - group_h - 14.0 - legend_h);
  const double height = top + h + group_h + 14.0 + legend_h + 12.0;
  const auto sy = [&](double v) { return top + h - h * (v - ya.lo) / (ya.hi - ya.lo); };
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << c.width_px << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"" << kFontPx << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << c.width_px / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" << svg_escape(c.title)
      << "</text>\n";
  for (double t : ya.ticks) {
    out << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << sy(t) << "\" y2=\"" << sy(t)
        << "\" stroke=\"#ddd\"/><text class=\"tick\" x=\"" << left - 6 << "\" y=\"" << sy(t) + 4
        << "\" text-anchor=\"end\">" << tick_label(t) << "</text>\n";
  }
  out << "<text class=\"axis-title\" transform=\"translate(" << 20.0 + kFontPx / 2 << "," << top + h / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << svg_escape(c.y_label) << "</text>\n";
  for (std::size_t g = 0; g < c.groups.size(); ++g) {
    const double gx = left + gw * static_cast<double>(g);
    for (std::size_t s = 0; s < c.series.size(); ++s) {
      if (g >= c.series[s].values.size()) continue;
      const double v = c.series[s].values[g];
      if (!std::isfinite(v) || v < 0.0) continue;
      const double bh = top + h - sy(std::min(v, ya.hi));
      out << "<rect x=\"" << gx + gw * 0.1 + bw * static_cast<double>(s) << "\" y=\"" << top + h - bh << "\" width=\""
          << bw * 0.92 << "\" height=\"" << bh << "\" fill=\"" << svg_escape(c.series[s].colour) << "\"><title>"
          << svg_escape(c.groups[g] + ", " + c.series[s].label + ": " + num(v)) << "</title></rect>\n";
    }
    if (slanted)
      out << "<text class=\"group\" transform=\"translate(" << gx + gw / 2 << "," << top + h + 14
          << ") rotate(35)\" text-anchor=\"start\">" << svg_escape(c.groups[g]) << "</text>\n";
    else
      out << "<text class=\"group\" x=\"" << gx + gw / 2 << "\" y=\"" << top + h + 16 << "\" text-anchor=\"middle\">"
          << svg_escape(c.groups[g]) << "</text>\n";
  }
  out << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << top + h << "\" y2=\"" << top + h
      << "\" stroke=\"black\"/>\n";
  double ly = top + h + group_h + 14.0 + 12.0;
  for (const auto& row : rows) {
    double lx = left;
    for (std::size_t s : row) {
      out << "<rect x=\"" << lx << "\" y=\"" << ly - 10 << "\" width=\"12\" height=\"12\" fill=\""
          << svg_escape(c.series[s].colour) << "\"/><text class=\"legend\" x=\"" << lx + 16 << "\" y=\"" << ly << "\">"
          << svg_escape(c.series[s].label) << "</text>\n";
      lx += 16.0 + text_width_px(c.series[s].label, kFontPx) + 20.0;
    }
    ly += 20.0;
  }
  out << "</svg>\n";
}

}  // namespace gazelod::cli
