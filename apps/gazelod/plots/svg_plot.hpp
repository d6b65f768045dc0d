// SPDX-License-Identifier: Apache-2.0
// A small SVG line-plot writer for reports (frames over time, per-HMD comparisons): stacked
// panels sharing one x axis, optional vertical event markers and shaded bands. Axes from
// plots/axis.hpp (round ticks, k/M labels, a log scale where a panel spans decades); margins
// sized to the widest tick label and legend entry so no two texts overlap; a series identical
// to an earlier one in its panel is dashed and says so; a series longer than the plot is wide
// is thinned to each pixel column's minimum and maximum (what the pixels can show). No
// dependencies.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace gazelod::cli {

struct PlotSeries {
  std::string label;
  std::string colour;     // CSS colour, e.g. "#d62728"
  std::vector<double> y;  // one value per x; non-finite values break the line
};

enum class PlotScale { automatic, linear, log };

struct PlotPanel {
  std::string y_label;
  std::vector<PlotSeries> series;
  // automatic: log where every value is positive and they span two decades or more.
  PlotScale scale = PlotScale::automatic;
};

struct PlotMarker {
  double x = 0.0;
  std::string colour;
};

// A shaded band across every panel from x0 to x1 (e.g. a time window).
struct PlotSpan {
  double x0 = 0.0, x1 = 0.0;
  std::string colour;
};

struct Plot {
  std::string title;
  std::string x_label;
  std::vector<double> x;
  std::vector<PlotPanel> panels;
  std::vector<PlotMarker> markers;  // vertical lines across every panel
  std::string marker_legend;        // what the markers mean
  std::vector<PlotSpan> spans;      // shaded bands across every panel
  std::string span_legend;          // what the bands mean
  int width_px = 960;
  int panel_height_px = 220;
};

// Writes a standalone SVG document. Empty or constant series still produce valid axes.
void write_svg(const Plot& plot, std::ostream& out);

}  // namespace gazelod::cli
