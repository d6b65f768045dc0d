// SPDX-License-Identifier: Apache-2.0
// Checks on the SVG plots gazelod writes, as a reader would make them at a glance: every tick
// label a round number (at most three significant digits, k / M / G allowed), and no two texts
// overlapping. Texts are boxes of 0.6 em a character (the plots' own estimate, plots/axis.hpp)
// and one em high, turned by their rotate(); overlap is a separating-axis test on the turned
// boxes.
#pragma once

#include <cmath>
#include <regex>
#include <string>
#include <vector>

namespace gazelod::cli::svgcheck {

struct TextBox {
  std::string text, cls;
  double cx = 0, cy = 0;  // the box's centre
  double half_w = 0, half_h = 0;
  double angle_rad = 0;  // the text's direction
};

inline double attr(const std::string& attrs, const std::string& name, double fallback) {
  const std::regex re("\\b" + name + "=\"([-0-9.eE+]+)\"");
  std::smatch m;
  return std::regex_search(attrs, m, re) ? std::stod(m[1]) : fallback;
}

inline std::string attr_text(const std::string& attrs, const std::string& name) {
  const std::regex re("\\b" + name + "=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(attrs, m, re) ? std::string(m[1]) : std::string();
}

inline std::size_t glyphs(const std::string& s) {  // entities count as one character
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i, ++n)
    if (s[i] == '&') i = s.find(';', i) == std::string::npos ? i : s.find(';', i);
  return n;
}

inline std::vector<TextBox> text_boxes(const std::string& svg, double default_font_px = 12.0) {
  std::vector<TextBox> boxes;
  const std::regex text_re("<text([^>]*)>([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text_re); it != std::sregex_iterator(); ++it) {
    const std::string attrs = (*it)[1], content = (*it)[2];
    if (content.empty()) continue;
    const double f = attr(attrs, "font-size", default_font_px);
    const double w = 0.6 * f * static_cast<double>(glyphs(content));
    double x = attr(attrs, "x", 0), y = attr(attrs, "y", 0), angle = 0;
    const std::string transform = attr_text(attrs, "transform");
    std::smatch m;
    if (std::regex_search(transform, m, std::regex("translate\\(([-0-9.eE+]+),\\s*([-0-9.eE+]+)\\)")))
      x = std::stod(m[1]), y = std::stod(m[2]);
    if (std::regex_search(transform, m, std::regex("rotate\\(([-0-9.eE+]+)\\)")))
      angle = std::stod(m[1]) * M_PI / 180.0;
    const std::string anchor = attr_text(attrs, "text-anchor");
    // Along the text: start, middle or end at the anchor; across: ascent 0.8 em, descent 0.2.
    const double along = anchor == "middle" ? 0.0 : anchor == "end" ? -w / 2 : w / 2;
    const double across = -0.3 * f;
    TextBox b;
    b.text = content;
    b.cls = attr_text(attrs, "class");
    b.angle_rad = angle;
    b.cx = x + along * std::cos(angle) - across * std::sin(angle);
    b.cy = y + along * std::sin(angle) + across * std::cos(angle);
    b.half_w = w / 2, b.half_h = 0.5 * f;
    boxes.push_back(b);
  }
  return boxes;
}

inline bool overlap(const TextBox& a, const TextBox& b) {
  const auto project = [](const TextBox& t, double ax, double ay, double& lo, double& hi) {
    const double c = ax * t.cx + ay * t.cy;
    const double ux = std::cos(t.angle_rad), uy = std::sin(t.angle_rad);
    const double r = t.half_w * std::fabs(ax * ux + ay * uy) + t.half_h * std::fabs(-ax * uy + ay * ux);
    lo = c - r, hi = c + r;
  };
  for (const TextBox* t : {&a, &b})
    for (double angle : {t->angle_rad, t->angle_rad + M_PI / 2}) {
      double alo, ahi, blo, bhi;
      project(a, std::cos(angle), std::sin(angle), alo, ahi);
      project(b, std::cos(angle), std::sin(angle), blo, bhi);
      if (ahi <= blo || bhi <= alo) return false;  // a separating axis
    }
  return true;
}

// "a" and "b" overlap: one line per pair.
inline std::vector<std::string> overlapping_texts(const std::string& svg) {
  const std::vector<TextBox> boxes = text_boxes(svg);
  std::vector<std::string> found;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (overlap(boxes[i], boxes[j])) found.push_back("'" + boxes[i].text + "' and '" + boxes[j].text + "'");
  return found;
}

// A plain decimal (no exponent) of at most three significant digits (leading zeros and an
// integer's trailing zeros do not count), with an optional sign and k / M / G suffix.
inline bool round_label(const std::string& label) {
  static const std::regex re("-?[0-9]+(\\.[0-9]+)?[kMG]?");
  if (!std::regex_match(label, re)) return false;
  std::string digits;
  for (char c : label)
    if (c >= '0' && c <= '9') digits += c;
  const bool integer = label.find('.') == std::string::npos;
  const std::size_t first = digits.find_first_not_of('0');
  if (first == std::string::npos) return true;  // zero
  std::size_t last = digits.size() - 1;
  if (integer) last = digits.find_last_not_of('0');
  return last - first + 1 <= 3;
}

// Tick labels that are not round.
inline std::vector<std::string> unround_ticks(const std::string& svg) {
  std::vector<std::string> bad;
  for (const TextBox& b : text_boxes(svg))
    if (b.cls == "tick" && !round_label(b.text)) bad.push_back(b.text);
  return bad;
}

}  // namespace gazelod::cli::svgcheck
