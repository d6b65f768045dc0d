// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/plots/svg_plot.hpp"

#include "apps/gazelod/compare/svg.hpp"
#include "apps/gazelod/plots/axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace gazelod::cli {
namespace {

constexpr double kFontPx = 12.0, kTitlePx = 15.0;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);  // pixel coordinates: a tenth is plenty
  return buf;
}

struct Extent {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

// The panel's y axis: log where asked or where the data span decades; from zero for
// non-negative data.
Axis panel_axis(const PlotPanel& panel, int max_ticks) {
  Extent e;
  for (const PlotSeries& s : panel.series)
    for (double v : s.y) e.add(v);
  const bool log =
      panel.scale == PlotScale::log ? e.lo > 0.0 : panel.scale == PlotScale::automatic && wants_log_axis(e.lo, e.hi);
  if (log) return log_axis(e.lo, e.hi);
  if (e.empty()) return linear_axis(0.0, 1.0, max_ticks, true);
  return linear_axis(e.lo, e.hi, max_ticks, e.lo >= 0.0);
}

// Indices of the points to draw: all of them, or per pixel column the first, the minimum, the
// maximum and the last (in order), so a long series keeps its envelope at a fraction of the size.
std::vector<std::size_t> thinned(const std::vector<double>& x, const std::vector<double>& y, double x_lo, double x_hi,
                                 double width_px) {
  const std::size_t n = std::min(x.size(), y.size());
  std::vector<std::size_t> keep;
  if (static_cast<double>(n) <= 2.0 * width_px || !(x_hi > x_lo)) {
    for (std::size_t i = 0; i < n; ++i) keep.push_back(i);
    return keep;
  }
  long column = std::numeric_limits<long>::min();
  std::size_t first = 0, lo = 0, hi = 0, last = 0;
  bool open = false;
  const auto flush = [&] {
    if (!open) return;
    std::size_t v[4] = {first, lo, hi, last};
    std::sort(v, v + 4);
    for (int k = 0; k < 4; ++k)
      if (keep.empty() || keep.back() != v[k]) keep.push_back(v[k]);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {  // a break stays a break
      flush();
      open = false;
      keep.push_back(i);
      continue;
    }
    const long c = std::lround((x[i] - x_lo) / (x_hi - x_lo) * width_px);
    if (!open || c != column) {
      flush();
      column = c, first = lo = hi = last = i, open = true;
    }
    if (y[i] < y[lo]) lo = i;
    if (y[i] > y[hi]) hi = i;
    last = i;
  }
  flush();
  return keep;
}

}  // namespace

void write_svg(const Plot& plot, std::ostream& out) {
  const double w = plot.width_px, ph = plot.panel_height_px;
  const int y_ticks = std::max(3, static_cast<int>(ph / 40.0));
  std::vector<Axis> axes;
  // Each series' legend entry: a series with the same values as an earlier one in its panel
  // is drawn dashed over it and says so ("" in same_as: none).
  std::vector<std::vector<std::string>> same_as(plot.panels.size());
  double label_w = 0.0, legend_w = 0.0;
  for (std::size_t p = 0; p < plot.panels.size(); ++p) {
    const PlotPanel& panel = plot.panels[p];
    axes.push_back(panel_axis(panel, y_ticks));
    for (double t : axes.back().ticks) label_w = std::max(label_w, text_width_px(tick_label(t), kFontPx));
    for (std::size_t si = 0; si < panel.series.size(); ++si) {
      std::string same;
      for (std::size_t e = 0; e < si && same.empty(); ++e)
        if (!panel.series[si].y.empty() && panel.series[e].y == panel.series[si].y) same = panel.series[e].label;
      same_as[p].push_back(same);
      const std::string entry =
          same.empty() ? panel.series[si].label : panel.series[si].label + " (same as " + same + ")";
      legend_w = std::max(legend_w, text_width_px(entry, kFontPx));
    }
  }
  // Left: the axis title (one line, rotated), a gap, the tick labels. Right: the legend.
  const double left = 20.0 + kFontPx + 10.0 + label_w + 8.0;
  const double right = std::max(40.0, 46.0 + legend_w);
  const double pw = std::max(100.0, w - left - right);
  const double top = 44.0, gap = 34.0;
  const double n_panels = static_cast<double>(plot.panels.size());
  const double xb = top + n_panels * (ph + gap) - gap;  // the last panel's bottom
  const bool has_marker_key = !plot.marker_legend.empty() && !plot.markers.empty();
  const bool has_span_key = !plot.span_legend.empty() && !plot.spans.empty();
  const double height = xb + 56.0 + (has_marker_key || has_span_key ? 22.0 : 0.0);

  Extent xe;
  for (double v : plot.x) xe.add(v);
  // x ticks as many as their labels leave room for.
  Axis xa = linear_axis(xe.empty() ? 0.0 : xe.lo, xe.empty() ? 1.0 : xe.hi, 10, !xe.empty() && xe.lo >= 0.0);
  for (int m = 10; m > 2; --m) {
    xa = linear_axis(xe.empty() ? 0.0 : xe.lo, xe.empty() ? 1.0 : xe.hi, m, !xe.empty() && xe.lo >= 0.0);
    double widest = 0.0;
    for (double t : xa.ticks) widest = std::max(widest, text_width_px(tick_label(t), kFontPx));
    if (xa.ticks.size() < 2 || pw / static_cast<double>(xa.ticks.size() - 1) > widest + 12.0) break;
  }
  const auto sx = [&](double x) { return left + (x - xa.lo) / (xa.hi - xa.lo) * pw; };

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << num(height)
      << "\" font-family=\"sans-serif\" font-size=\"" << kFontPx << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << num(w / 2) << "\" y=\"24\" text-anchor=\"middle\" font-size=\"" << kTitlePx << "\">"
      << svg_escape(plot.title) << "</text>\n";

  for (std::size_t p = 0; p < plot.panels.size(); ++p) {
    const PlotPanel& panel = plot.panels[p];
    const Axis& ya = axes[p];
    const double y0 = top + static_cast<double>(p) * (ph + gap);
    const auto sy = [&](double y) {
      const double f = ya.log ? (std::log10(y) - std::log10(ya.lo)) / (std::log10(ya.hi) - std::log10(ya.lo))
                              : (y - ya.lo) / (ya.hi - ya.lo);
      return y0 + ph - f * ph;
    };
    out << "<rect x=\"" << num(left) << "\" y=\"" << num(y0) << "\" width=\"" << num(pw) << "\" height=\"" << ph
        << "\" fill=\"none\" stroke=\"#888\"/>\n";
    for (double t : ya.ticks) {
      out << "<line x1=\"" << num(left) << "\" x2=\"" << num(left + pw) << "\" y1=\"" << num(sy(t)) << "\" y2=\""
          << num(sy(t)) << "\" stroke=\"#eee\"/>\n"
          << "<text class=\"tick\" x=\"" << num(left - 6) << "\" y=\"" << num(sy(t) + 4) << "\" text-anchor=\"end\">"
          << tick_label(t) << "</text>\n";
    }
    out << "<text class=\"axis-title\" transform=\"translate(" << num(20.0 + kFontPx / 2) << "," << num(y0 + ph / 2)
        << ") rotate(-90)\" text-anchor=\"middle\">" << svg_escape(panel.y_label + (ya.log ? " (log)" : ""))
        << "</text>\n";
    for (const PlotSpan& b : plot.spans) {
      if (!std::isfinite(b.x0) || !std::isfinite(b.x1)) continue;
      const double x0 = std::clamp(sx(std::min(b.x0, b.x1)), left, left + pw);
      const double x1 = std::clamp(sx(std::max(b.x0, b.x1)), left, left + pw);
      out << "<rect class=\"span\" x=\"" << num(x0) << "\" y=\"" << num(y0) << "\" width=\""
          << num(std::max(x1 - x0, 0.5)) << "\" height=\"" << ph << "\" fill=\"" << b.colour
          << "\" fill-opacity=\"0.2\"/>\n";
    }
    for (const PlotMarker& m : plot.markers) {
      if (!std::isfinite(m.x)) continue;
      out << "<line x1=\"" << num(sx(m.x)) << "\" x2=\"" << num(sx(m.x)) << "\" y1=\"" << num(y0) << "\" y2=\""
          << num(y0 + ph) << "\" stroke=\"" << m.colour << "\" stroke-opacity=\"0.35\"/>\n";
    }
    for (std::size_t si = 0; si < panel.series.size(); ++si) {
      const PlotSeries& s = panel.series[si];
      const std::string& same = same_as[p][si];
      out << "<path fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\""
          << (same.empty() ? "" : " stroke-dasharray=\"6 4\"") << " d=\"";
      bool pen_down = false;
      for (std::size_t i : thinned(plot.x, s.y, xa.lo, xa.hi, pw)) {
        const double y = s.y[i];
        if (!std::isfinite(y) || !std::isfinite(plot.x[i]) || (ya.log && !(y > 0.0))) {
          pen_down = false;
          continue;
        }
        out << (pen_down ? "L" : "M") << num(sx(plot.x[i])) << ' ' << num(sy(y)) << ' ';
        pen_down = true;
      }
      out << "\"/>\n";
      const double ly = y0 + 16 + 18 * static_cast<double>(si);
      out << "<line x1=\"" << num(left + pw + 10) << "\" x2=\"" << num(left + pw + 30) << "\" y1=\"" << num(ly - 4)
          << "\" y2=\"" << num(ly - 4) << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\""
          << (same.empty() ? "" : " stroke-dasharray=\"6 4\"") << "/>\n"
          << "<text class=\"legend\" x=\"" << num(left + pw + 36) << "\" y=\"" << num(ly) << "\">"
          << svg_escape(same.empty() ? s.label : s.label + " (same as " + same + ")") << "</text>\n";
    }
  }
  for (double t : xa.ticks)
    out << "<text class=\"tick\" x=\"" << num(sx(t)) << "\" y=\"" << num(xb + 16) << "\" text-anchor=\"middle\">"
        << tick_label(t) << "</text>\n";
  out << "<text class=\"axis-title\" x=\"" << num(left + pw / 2) << "\" y=\"" << num(xb + 36)
      << "\" text-anchor=\"middle\">" << svg_escape(plot.x_label) << "</text>\n";
  // The keys of markers and bands: one row under the x axis title.
  double kx = left;
  const double ky = xb + 58;
  if (has_marker_key) {
    out << "<line x1=\"" << num(kx) << "\" x2=\"" << num(kx) << "\" y1=\"" << num(ky - 11) << "\" y2=\"" << num(ky + 1)
        << "\" stroke=\"" << plot.markers.front().colour << "\" stroke-width=\"2\"/>\n"
        << "<text class=\"legend\" x=\"" << num(kx + 6) << "\" y=\"" << num(ky) << "\">"
        << svg_escape(plot.marker_legend) << "</text>\n";
    kx += 6 + text_width_px(plot.marker_legend, kFontPx) + 24;
  }
  if (has_span_key)
    out << "<rect x=\"" << num(kx) << "\" y=\"" << num(ky - 11) << "\" width=\"12\" height=\"12\" fill=\""
        << plot.spans.front().colour << "\" fill-opacity=\"0.2\"/>\n"
        << "<text class=\"legend\" x=\"" << num(kx + 16) << "\" y=\"" << num(ky) << "\">"
        << svg_escape(plot.span_legend) << "</text>\n";
  out << "</svg>\n";
}

}  // namespace gazelod::cli
