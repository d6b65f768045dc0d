#include "apps/gazelod/svg_plot.hpp"

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

}  // namespace
}  // namespace gazelod::cli
