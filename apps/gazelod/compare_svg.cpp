#include "apps/gazelod/compare_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gazelod::cli {

std::string svg_escape(const std::string& text) {
  std::string s;
  for (char c : text) {
    switch (c) {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      default: s += c;
    }
  }
  return s;
}

namespace {

// A "nice" axis top (1, 2 or 5 times a power of ten) at or above `v`.
double nice_top(double v) {
  if (!(v > 0.0) || !std::isfinite(v)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= v) return m * p;
  return 10.0 * p;
}

std::string num(double v) {
  char b[32];
  if (std::fabs(v) >= 1e5 || (std::fabs(v) < 1e-2 && v != 0.0)) std::snprintf(b, sizeof b, "%.3g", v);
  else std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

void write_bar_chart(const BarChart& c, std::ostream& out) {
  const double left = 80, right = 20, top = 40, bottom = 90;
  const double w = std::max(200.0, c.width_px - left - right);
  const double h = std::max(100.0, c.height_px - top - bottom);
  double vmax = 0.0;
  for (const BarSeries& s : c.series)
    for (double v : s.values)
      if (std::isfinite(v)) vmax = std::max(vmax, v);
  const double ytop = nice_top(vmax);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << c.width_px << "\" height=\"" << c.height_px
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << c.width_px / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
      << svg_escape(c.title) << "</text>\n";
  for (int i = 0; i <= 5; ++i) {
    const double v = ytop * i / 5.0, y = top + h - h * i / 5.0;
    out << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << y << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << y + 4
        << "\" text-anchor=\"end\">" << num(v) << "</text>\n";
  }
  out << "<text transform=\"translate(16," << top + h / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
      << svg_escape(c.y_label) << "</text>\n";
  const std::size_t ng = std::max<std::size_t>(c.groups.size(), 1), ns = std::max<std::size_t>(c.series.size(), 1);
  const double gw = w / static_cast<double>(ng), bw = gw * 0.8 / static_cast<double>(ns);
  for (std::size_t g = 0; g < c.groups.size(); ++g) {
    const double gx = left + gw * static_cast<double>(g);
    for (std::size_t s = 0; s < c.series.size(); ++s) {
      if (g >= c.series[s].values.size()) continue;
      const double v = c.series[s].values[g];
      if (!std::isfinite(v) || v < 0.0) continue;
      const double bh = h * std::min(v / ytop, 1.0);
      out << "<rect x=\"" << gx + gw * 0.1 + bw * static_cast<double>(s) << "\" y=\"" << top + h - bh
          << "\" width=\"" << bw * 0.92 << "\" height=\"" << bh << "\" fill=\"" << svg_escape(c.series[s].colour)
          << "\"><title>" << svg_escape(c.groups[g] + ", " + c.series[s].label + ": " + num(v))
          << "</title></rect>\n";
    }
    out << "<text x=\"" << gx + gw / 2 << "\" y=\"" << top + h + 16 << "\" text-anchor=\"middle\">"
        << svg_escape(c.groups[g]) << "</text>\n";
  }
  out << "<line x1=\"" << left << "\" x2=\"" << left + w << "\" y1=\"" << top + h << "\" y2=\"" << top + h
      << "\" stroke=\"black\"/>\n";
  double lx = left;
  const double ly = top + h + 44;
  for (const BarSeries& s : c.series) {
    out << "<rect x=\"" << lx << "\" y=\"" << ly - 10 << "\" width=\"12\" height=\"12\" fill=\""
        << svg_escape(s.colour) << "\"/><text x=\"" << lx + 16 << "\" y=\"" << ly << "\">"
        << svg_escape(s.label) << "</text>\n";
    lx += 24 + 7.0 * static_cast<double>(s.label.size());
  }
  out << "</svg>\n";
}

}  // namespace gazelod::cli
