// SPDX-License-Identifier: Apache-2.0
// A grouped bar chart as a standalone SVG (for `gazelod compare` and `gazelod eval`): one
// group per label on the x axis, one bar per series in each group, a legend. No dependencies.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace gazelod::cli {

struct BarSeries {
  std::string label;
  std::string colour;          // CSS colour
  std::vector<double> values;  // one per group; non-finite or negative values draw no bar
};

struct BarChart {
  std::string title;
  std::string y_label;
  std::vector<std::string> groups;
  std::vector<BarSeries> series;
  int width_px = 960;
  int height_px = 420;
};

// Escapes &, <, >, " for SVG text.
std::string svg_escape(const std::string& text);

void write_bar_chart(const BarChart& chart, std::ostream& out);

}  // namespace gazelod::cli
