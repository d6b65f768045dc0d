// SPDX-License-Identifier: Apache-2.0
// Axes a reader trusts at a glance, for every plot gazelod writes (svg_plot.hpp, compare/svg.hpp):
// ticks at round values (1, 2 or 5 x 10^n; powers of ten on a log axis), labels of at most three
// significant digits with k / M / G for thousands, millions, billions (never "3.069e+06"), and an
// estimate of a label's width so the layout can keep text boxes apart.
#pragma once

#include <string>
#include <vector>

namespace gazelod::cli {

struct Axis {
  double lo = 0.0, hi = 1.0;  // the axis' extent: the outer ticks (log: their values, > 0)
  bool log = false;
  std::vector<double> ticks;  // ascending, round values, the first == lo and the last == hi
};

// Ticks every 1, 2 or 5 x 10^n covering [lo, hi] with at most max_ticks of them (at least 2);
// the axis extends to the outer ticks. from_zero: the axis starts at 0 when lo >= 0 (counts,
// triangles: a bar or a series of counts read against zero). Non-finite or empty input gives
// [0, 1]; a constant gives a range around it (never below 0 for non-negative data).
Axis linear_axis(double lo, double hi, int max_ticks = 6, bool from_zero = false);

// Decades covering [lo, hi] (lo > 0), with 2 and 5 between them when there are at most two.
Axis log_axis(double lo, double hi);

// Whether a series set spanning [lo, hi] reads better on a log axis: every value positive and
// at least two decades between the smallest and the largest.
bool wants_log_axis(double lo, double hi);

// "0", "0.05", "2.5", "120", "1.5k", "20k", "1.5M", "2G": at most three significant digits (more only
// where neighbouring ticks would otherwise read the same, which 1-2-5 steps avoid).
std::string tick_label(double v);

// A text's width in pixels at `font_px` in the plots' sans-serif (0.6 em a character: a
// slight over-estimate for digits and lower case, so boxes laid out with it do not touch).
double text_width_px(const std::string& text, double font_px);

}  // namespace gazelod::cli
