#include "apps/gazelod/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace gazelod::cli {
namespace {

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // A range that can be divided by: empty -> [0,1], constant -> padded.
  void settle() {
    if (!(lo <= hi)) {
      lo = 0.0;
      hi = 1.0;
    } else if (hi - lo < 1e-12 * std::max(1.0, std::fabs(hi))) {
      lo -= 0.5;
      hi += 0.5;
    }
  }
};

std::string escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '&': r += "&amp;"; break;
      case '"': r += "&quot;"; break;
      default: r += c;
    }
  }
  return r;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

void write_svg(const Plot& plot, std::ostream& out) {
  const double left = 80, right = 160, top = 40, gap = 30, bottom = 50;
  const double w = plot.width_px, ph = plot.panel_height_px;
  const double pw = w - left - right;
  const double n_panels = static_cast<double>(plot.panels.size());
  const double height = top + n_panels * (ph + gap) + bottom;
  Range xr;
  for (double v : plot.x) xr.add(v);
  xr.settle();
  auto sx = [&](double x) { return left + (x - xr.lo) / (xr.hi - xr.lo) * pw; };

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << w / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
      << escape(plot.title) << "</text>\n";

  for (size_t p = 0; p < plot.panels.size(); ++p) {
    const PlotPanel& panel = plot.panels[p];
    const double y0 = top + static_cast<double>(p) * (ph + gap);
    Range yr;
    for (const PlotSeries& s : panel.series)
      for (double v : s.y) yr.add(v);
    yr.settle();
    auto sy = [&](double y) { return y0 + ph - (y - yr.lo) / (yr.hi - yr.lo) * ph; };

    out << "<rect x=\"" << left << "\" y=\"" << y0 << "\" width=\"" << pw << "\" height=\"" << ph
        << "\" fill=\"none\" stroke=\"#888\"/>\n";
    for (int i = 0; i <= 4; ++i) {
      const double v = yr.lo + (yr.hi - yr.lo) * i / 4.0;
      out << "<text x=\"" << left - 6 << "\" y=\"" << sy(v) + 4 << "\" text-anchor=\"end\">"
          << num(v) << "</text>\n"
          << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << sy(v) << "\" y2=\""
          << sy(v) << "\" stroke=\"#eee\"/>\n";
    }
    out << "<text transform=\"translate(18," << y0 + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
        << escape(panel.y_label) << "</text>\n";
    for (const PlotSpan& b : plot.spans) {
      if (!std::isfinite(b.x0) || !std::isfinite(b.x1)) continue;
      const double x0 = std::clamp(sx(std::min(b.x0, b.x1)), left, left + pw);
      const double x1 = std::clamp(sx(std::max(b.x0, b.x1)), left, left + pw);
      out << "<rect class=\"span\" x=\"" << num(x0) << "\" y=\"" << y0 << "\" width=\""
          << num(std::max(x1 - x0, 0.5)) << "\" height=\"" << ph << "\" fill=\"" << b.colour
          << "\" fill-opacity=\"0.2\"/>\n";
    }
    for (const PlotMarker& m : plot.markers) {
      if (!std::isfinite(m.x)) continue;
      out << "<line x1=\"" << sx(m.x) << "\" x2=\"" << sx(m.x) << "\" y1=\"" << y0 << "\" y2=\""
          << y0 + ph << "\" stroke=\"" << m.colour << "\" stroke-opacity=\"0.35\"/>\n";
    }
    for (size_t si = 0; si < panel.series.size(); ++si) {
      const PlotSeries& s = panel.series[si];
      out << "<path fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\" d=\"";
      bool pen_down = false;
      const size_t n = std::min(s.y.size(), plot.x.size());
      for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(s.y[i]) || !std::isfinite(plot.x[i])) {
          pen_down = false;
          continue;
        }
        out << (pen_down ? "L" : "M") << num(sx(plot.x[i])) << ' ' << num(sy(s.y[i])) << ' ';
        pen_down = true;
      }
      out << "\"/>\n";
      const double ly = y0 + 16 + 18 * static_cast<double>(si);
      out << "<line x1=\"" << left + pw + 10 << "\" x2=\"" << left + pw + 30 << "\" y1=\"" << ly - 4
          << "\" y2=\"" << ly - 4 << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"/>\n"
          << "<text x=\"" << left + pw + 36 << "\" y=\"" << ly << "\">" << escape(s.label) << "</text>\n";
    }
  }
  const double xb = top + n_panels * (ph + gap) - gap;
  for (int i = 0; i <= 5; ++i) {
    const double v = xr.lo + (xr.hi - xr.lo) * i / 5.0;
    out << "<text x=\"" << sx(v) << "\" y=\"" << xb + 16 << "\" text-anchor=\"middle\">" << num(v)
        << "</text>\n";
  }
  out << "<text x=\"" << left + pw / 2 << "\" y=\"" << xb + 36 << "\" text-anchor=\"middle\">"
      << escape(plot.x_label) << "</text>\n";
  if (!plot.marker_legend.empty() && !plot.markers.empty())
    out << "<text x=\"" << left + pw + 10 << "\" y=\"" << xb + 16 << "\" fill=\""
        << plot.markers.front().colour << "\">| " << escape(plot.marker_legend) << "</text>\n";
  if (!plot.span_legend.empty() && !plot.spans.empty())
    out << "<rect x=\"" << left + pw + 10 << "\" y=\"" << xb + 26 << "\" width=\"12\" height=\"12\" fill=\""
        << plot.spans.front().colour << "\" fill-opacity=\"0.2\"/>\n"
        << "<text x=\"" << left + pw + 26 << "\" y=\"" << xb + 36 << "\">" << escape(plot.span_legend) << "</text>\n";
  out << "</svg>\n";
}

}  // namespace gazelod::cli
