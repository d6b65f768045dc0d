// SPDX-License-Identifier: Apache-2.0
#include "apps/gazelod/plots/axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gazelod::cli {
namespace {

// The smallest 1, 2 or 5 x 10^n at least `raw`.
double nice_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw * (1.0 - 1e-9)) return m * p;
  return 10.0 * p;
}

}  // namespace

Axis linear_axis(double lo, double hi, int max_ticks, bool from_zero) {
  Axis a;
  max_ticks = std::max(max_ticks, 2);
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) lo = 0.0, hi = 1.0;
  if (from_zero && lo >= 0.0) lo = 0.0;
  if (hi - lo <= 1e-12 * std::max(1.0, std::fabs(hi))) {
    // A constant: a unit around it, not below zero for non-negative data.
    const double pad = std::max(std::fabs(hi) * 0.5, 0.5);
    const bool non_negative = lo >= 0.0;
    lo = non_negative ? std::max(0.0, lo - pad) : lo - pad;
    hi = hi + pad;
  }
  double step = nice_step((hi - lo) / (max_ticks - 1));
  double first = std::floor(lo / step + 1e-9) * step, last = std::ceil(hi / step - 1e-9) * step;
  while ((last - first) / step + 1.0 > max_ticks + 1e-9) {  // the rounding added ticks: a larger step
    step = nice_step(step * 1.0001);
    first = std::floor(lo / step + 1e-9) * step, last = std::ceil(hi / step - 1e-9) * step;
  }
  const int n = static_cast<int>(std::lround((last - first) / step)) + 1;
  for (int i = 0; i < n; ++i) {
    double t = first + step * i;
    if (std::fabs(t) < step * 1e-9) t = 0.0;  // no "-0"
    a.ticks.push_back(t);
  }
  a.lo = a.ticks.front();
  a.hi = a.ticks.back();
  return a;
}

Axis log_axis(double lo, double hi) {
  Axis a;
  a.log = true;
  if (!(lo > 0.0) || !std::isfinite(lo) || !std::isfinite(hi) || hi < lo) lo = 1.0, hi = 10.0;
  const int d0 = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int d1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (d1 <= d0) d1 = d0 + 1;
  const bool few = d1 - d0 <= 2;
  for (int d = d0; d <= d1; ++d) {
    const double p = std::pow(10.0, d);
    a.ticks.push_back(p);
    if (few && d < d1) a.ticks.push_back(2.0 * p), a.ticks.push_back(5.0 * p);
  }
  a.lo = a.ticks.front();
  a.hi = a.ticks.back();
  return a;
}

bool wants_log_axis(double lo, double hi) {
  return lo > 0.0 && std::isfinite(hi) && hi / lo >= 100.0;
}

std::string tick_label(double v) {
  if (!std::isfinite(v)) return "";
  if (v == 0.0) return "0";
  const double a = std::fabs(v);
  const char* suffix = "";
  double shown = v;
  if (a >= 1e9)
    shown = v / 1e9, suffix = "G";
  else if (a >= 1e6)
    shown = v / 1e6, suffix = "M";
  else if (a >= 1e3)
    shown = v / 1e3, suffix = "k";
  char buf[32];
  // Three significant digits, trailing zeros dropped ("%g"), never an exponent for what the
  // plots show (1e-4 and up; smaller values keep %g's own form).
  std::snprintf(buf, sizeof buf, std::fabs(shown) >= 1e-4 ? "%.3g" : "%.2g", shown);
  std::string s = buf;
  if (s.find('e') != std::string::npos && std::fabs(shown) >= 1.0) {
    std::snprintf(buf, sizeof buf, "%.0f", shown);  // 100..999 with %.3g never uses e; safety
    s = buf;
  }
  return s + suffix;
}

double text_width_px(const std::string& text, double font_px) {
  return 0.6 * font_px * static_cast<double>(text.size());
}

}  // namespace gazelod::cli
