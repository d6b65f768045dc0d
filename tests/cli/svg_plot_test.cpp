// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/plots/svg_plot.hpp"

#include "apps/gazelod/compare/svg.hpp"
#include "apps/gazelod/plots/axis.hpp"
#include "tests/cli/svg_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace gazelod::cli {
namespace {

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(SvgPlot, OnePathPerSeriesAndMarkersInEveryPanel) {
  Plot plot;
  plot.title = "frames <test>";
  plot.x = {0, 1, 2, 3};
  plot.panels.push_back({"triangles", {{"drawn", "#f00", {4, 3, 2, 1}}, {"full", "#00f", {4, 4, 4, 4}}}});
  plot.panels.push_back({"ms", {{"frame", "#0a0", {1, 2, 1, 2}}}});
  plot.markers = {{1.5, "#999"}};
  std::ostringstream out;
  write_svg(plot, out);
  const std::string svg = out.str();
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(count(svg, "<path"), 3u);
  EXPECT_EQ(count(svg, "stroke-opacity"), 2u);  // one marker line per panel
  EXPECT_NE(svg.find("frames &lt;test&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(SvgPlot, NonFiniteValuesBreakTheLineAndNeverReachTheFile) {
  Plot plot;
  plot.x = {0, 1, 2, 3, 4};
  plot.panels.push_back({"v", {{"s", "#000", {1, NAN, 2, INFINITY, 3}}}});
  std::ostringstream out;
  write_svg(plot, out);
  const std::string svg = out.str();
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
  // Three separate pieces: each starts with a move.
  const size_t d = svg.find(" d=\"");
  ASSERT_NE(d, std::string::npos);
  const std::string path = svg.substr(d, svg.find('"', d + 4) - d);
  EXPECT_EQ(count(path, "M"), 3u);
}

TEST(SvgPlot, EmptyAndConstantDataGiveFiniteAxes) {
  Plot plot;
  plot.panels.push_back({"empty", {}});
  plot.panels.push_back({"const", {{"c", "#000", {}}}});
  std::ostringstream out;
  write_svg(plot, out);
  EXPECT_EQ(out.str().find("nan"), std::string::npos);
  plot.x = {5, 5};
  plot.panels[1].series[0].y = {2, 2};
  std::ostringstream out2;
  write_svg(plot, out2);
  EXPECT_EQ(out2.str().find("nan"), std::string::npos);
  EXPECT_NE(out2.str().find("M"), std::string::npos);
}

std::string svg_of(const Plot& plot) {
  std::ostringstream out;
  write_svg(plot, out);
  return out.str();
}

std::vector<std::string> labels(const Axis& a) {
  std::vector<std::string> l;
  for (double t : a.ticks) l.push_back(tick_label(t));
  return l;
}

TEST(PlotAxis, RoundTicksForTheRangesThatGaveRawOnes) {
  // Ranges whose old ticks read 0.01111, 4.009 and 3.069e+06.
  EXPECT_EQ(labels(linear_axis(0.0, 0.01111)), (std::vector<std::string>{"0", "0.005", "0.01", "0.015"}));
  EXPECT_EQ(labels(linear_axis(1.2, 4.009)), (std::vector<std::string>{"1", "2", "3", "4", "5"}));
  const Axis a = linear_axis(1.2, 4.009);
  EXPECT_LE(a.ticks.size(), 6u);
  EXPECT_LE(a.lo, 1.2);
  EXPECT_GE(a.hi, 4.009);
  EXPECT_EQ(labels(linear_axis(0.0, 3.069e6)), (std::vector<std::string>{"0", "1M", "2M", "3M", "4M"}));
  EXPECT_EQ(labels(linear_axis(0.0, 2.2e4, 6)), (std::vector<std::string>{"0", "5k", "10k", "15k", "20k", "25k"}));
  EXPECT_EQ(labels(linear_axis(-3.0, 7.0, 6)), (std::vector<std::string>{"-5", "0", "5", "10"}))
      << "steps of 2 would need 7 ticks";
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {0, 0.01111}, {1.2, 4.009}, {0, 3.069e6}, {-3, 7}, {0.0031, 0.0047}, {17, 1234567}, {0, 1e10}}) {
    const Axis x = linear_axis(lo, hi, 6);
    EXPECT_LE(x.ticks.size(), 6u) << lo << ".." << hi;
    EXPECT_LE(x.lo, lo) << lo << ".." << hi;
    EXPECT_GE(x.hi, hi) << lo << ".." << hi;
    for (const std::string& l : labels(x)) EXPECT_TRUE(svgcheck::round_label(l)) << l << " for " << lo << ".." << hi;
  }
}

TEST(PlotAxis, ConstantsAndEmptyNeverGoBelowZeroForCounts) {
  const Axis zero = linear_axis(0.0, 0.0, 5, true);
  EXPECT_EQ(zero.lo, 0.0) << "a constant 0 (an empty count): no negative ticks";
  EXPECT_GT(zero.hi, 0.0);
  const Axis nan = linear_axis(NAN, NAN);
  EXPECT_EQ(nan.lo, 0.0);
  EXPECT_EQ(nan.hi, 1.0);
  const Axis seven = linear_axis(7.0, 7.0, 5, true);
  EXPECT_EQ(seven.lo, 0.0);
  EXPECT_GE(seven.hi, 7.0);
}

TEST(PlotAxis, LogAxisAtDecadesAndTickLabels) {
  EXPECT_FALSE(wants_log_axis(0.0, 100.0)) << "zero cannot be on a log axis";
  EXPECT_FALSE(wants_log_axis(1.0, 99.0));
  EXPECT_TRUE(wants_log_axis(0.015, 16.0));
  EXPECT_EQ(labels(log_axis(0.015, 16.0)), (std::vector<std::string>{"0.01", "0.1", "1", "10", "100"}));
  EXPECT_EQ(labels(log_axis(3.0, 40.0)), (std::vector<std::string>{"1", "2", "5", "10", "20", "50", "100"}));
  const std::vector<std::pair<double, std::string>> cases{
      {0, "0"},        {0.05, "0.05"}, {2.5, "2.5"},   {120, "120"},       {1500, "1.5k"},    {20000, "20k"},
      {1.5e6, "1.5M"}, {2e9, "2G"},    {-500, "-500"}, {0.0025, "0.0025"}, {1234567, "1.23M"}};
  for (const auto& [v, text] : cases) EXPECT_EQ(tick_label(v), text) << v;
  EXPECT_EQ(tick_label(NAN), "");
}

// A plot with what used to go wrong: raw ticks, long legends, an empty count panel, a panel
// spanning decades, identical series, marker and band keys.
Plot hard_plot(std::size_t n) {
  Plot p;
  p.title = "gazelod run: a plot with long labels";
  p.x_label = "time (s)";
  for (std::size_t i = 0; i < n; ++i) p.x.push_back(20.0 * static_cast<double>(i) / static_cast<double>(n));
  PlotSeries drawn{"drawn triangles per eye (per-object LOD (bake --clusters))", "#d62728", {}};
  PlotSeries full{"full detail", "#1f77b4", {}};
  PlotSeries frame{"frame", "#2ca02c", {}}, select{"selection", "#9467bd", {}};
  PlotSeries a{"degraded", "#000", {}}, b{"excess levels", "#888", {}};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = p.x[i];
    drawn.y.push_back(1.7e6 + 1.3e6 * std::sin(t));
    full.y.push_back(3.069e6);
    frame.y.push_back(11.0 + std::sin(7 * t));
    select.y.push_back(0.015 + 0.001 * std::cos(t));
    a.y.push_back(0.0);
    b.y.push_back(0.0);
  }
  p.panels.push_back({"triangles", {drawn, full}});
  p.panels.push_back({"time (ms)", {frame, select}});
  p.panels.push_back({"in-view objects", {a, b}});
  p.markers = {{3.0, "#999"}, {11.0, "#999"}};
  p.marker_legend = "saccade onsets (a long legend for the marker key)";
  p.spans = {{4.0, 5.0, "#7f7f7f"}};
  p.span_legend = "suppression windows";
  return p;
}

TEST(SvgPlot, RoundTicksNoOverlapsLogWhereNeededAndIdenticalSeriesShown) {
  const std::string svg = svg_of(hard_plot(2000));
  EXPECT_EQ(svgcheck::unround_ticks(svg), std::vector<std::string>{});
  EXPECT_EQ(svgcheck::overlapping_texts(svg), std::vector<std::string>{});
  EXPECT_NE(svg.find(">time (ms) (log)</text>"), std::string::npos) << "selection under frame time: a log axis";
  EXPECT_EQ(svg.find(">triangles (log)<"), std::string::npos) << "triangles do not span decades";
  EXPECT_NE(svg.find("excess levels (same as degraded)"), std::string::npos);
  EXPECT_EQ(count(svg, "stroke-dasharray"), 2u) << "the identical series and its legend line";
  for (const svgcheck::TextBox& b : svgcheck::text_boxes(svg)) {
    if (b.cls == "tick") {
      EXPECT_EQ(b.text.find('-'), std::string::npos) << "no negative tick for counts: " << b.text;
    }
  }
  EXPECT_NE(svg.find(">saccade onsets (a long legend for the marker key)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">suppression windows</text>"), std::string::npos);
}

TEST(SvgPlot, LongSeriesAreThinnedToWhatThePixelsShow) {
  const std::string small = svg_of(hard_plot(1000)), big = svg_of(hard_plot(400000));
  EXPECT_LT(big.size(), 400u * 1000u) << "400k frames: the file stays small";
  EXPECT_LT(big.size(), 3 * small.size());
  EXPECT_EQ(svgcheck::overlapping_texts(big), std::vector<std::string>{});
  // The envelope is kept: the extreme values of the sine still reach the panel's edges.
  EXPECT_NE(big.find("M"), std::string::npos);
}

TEST(BarChart, RoundTicksSlantedGroupsAndLegendRowsWithoutOverlap) {
  BarChart c;
  c.title = "gazelod compare: triangles per frame";
  c.y_label = "% of full detail";
  const char* names[] = {"iglasses",     "questpro",   "quest3", "varjoxr4", "visionpro",
                         "pimaxcrystal", "viveproeye", "psvr2",  "index",    "desktop"};
  for (const char* n : names) c.groups.push_back(std::string(n) + " (a longer group name)");
  for (int s = 0; s < 6; ++s) {
    BarSeries bs{
        "criteria set number " + std::to_string(s) + " with a long label", "#" + std::string(6, char('3' + s)), {}};
    for (std::size_t g = 0; g < c.groups.size(); ++g) bs.values.push_back(3.069 * static_cast<double>(g + s));
    c.series.push_back(bs);
  }
  std::ostringstream out;
  write_bar_chart(c, out);
  const std::string svg = out.str();
  EXPECT_EQ(svgcheck::unround_ticks(svg), std::vector<std::string>{});
  EXPECT_EQ(svgcheck::overlapping_texts(svg), std::vector<std::string>{});
  EXPECT_NE(svg.find("rotate(35)"), std::string::npos) << "group labels wider than their group are slanted";
}

TEST(SvgCheck, TheCheckerFindsOverlapsAndRawTicks) {
  // The checks themselves can fail.
  EXPECT_EQ(svgcheck::overlapping_texts(R"(<text x="10" y="10">abc</text><text x="15" y="12">def</text>)").size(), 1u);
  EXPECT_EQ(svgcheck::overlapping_texts(R"(<text x="10" y="10">abc</text><text x="10" y="40">def</text>)").size(), 0u);
  EXPECT_EQ(svgcheck::overlapping_texts(
                R"svg(<text transform="translate(20,100) rotate(-90)" text-anchor="middle">a vertical title</text>)svg"
                R"svg(<text x="15" y="100" text-anchor="start">x</text>)svg")
                .size(),
            1u);
  EXPECT_FALSE(svgcheck::round_label("0.01111"));
  EXPECT_FALSE(svgcheck::round_label("3.069e+06"));
  EXPECT_FALSE(svgcheck::round_label("4.009"));
  EXPECT_TRUE(svgcheck::round_label("1.5M"));
  EXPECT_TRUE(svgcheck::round_label("0.015"));
}

}  // namespace
}  // namespace gazelod::cli
