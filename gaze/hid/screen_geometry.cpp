// SPDX-License-Identifier: Apache-2.0
#include "gaze/hid/screen_geometry.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace gazelod::gaze::hid {
namespace {

constexpr double kUmToM = 1e-6;

// An eye position from the report, in S (metres).
glm::dvec3 eye_in_s(const Point3Um& p, const ScreenGeometry& g) {
  double x = p.x * kUmToM, y = p.y * kUmToM;
  const double z = p.z * kUmToM;
  if (g.eye_frame.y_down) y = -y;
  if (g.eye_frame.origin_top_left) {  // corner origin -> centre origin
    x -= 0.5 * g.width_m;
    y += 0.5 * g.height_m;
  }
  return {x, y, z};
}

}  // namespace

std::string validate(const ScreenGeometry& g) {
  if (!(std::isfinite(g.width_m) && g.width_m > 0.0 && std::isfinite(g.height_m) && g.height_m > 0.0))
    return "screen size must be finite and > 0 m, got " + std::to_string(g.width_m) + " x " +
           std::to_string(g.height_m);
  return "";
}

GazeSample gaze_from_screen(const TrackingData& t, const ScreenGeometry& g) {
  GazeSample s;  // direction (0,0,-1), invalid
  if (!validate(g).empty()) return s;

  // An eye is tracked when it is in front of the screen.
  const bool left_ok = t.left_eye_um.z > 0, right_ok = t.right_eye_um.z > 0;
  if (!left_ok && !right_ok) return s;
  glm::dvec3 eye{0.0};
  if (left_ok) eye += eye_in_s(t.left_eye_um, g);
  if (right_ok) eye += eye_in_s(t.right_eye_um, g);
  eye /= (left_ok && right_ok) ? 2.0 : 1.0;

  const double gx = t.gaze_x_um * kUmToM, gy = t.gaze_y_um * kUmToM;
  // Trackers report a little beyond the edges; half a screen beyond is not a gaze point.
  if (gx < -0.5 * g.width_m || gx > 1.5 * g.width_m || gy < -0.5 * g.height_m || gy > 1.5 * g.height_m) return s;
  const glm::dvec3 point{gx - 0.5 * g.width_m, 0.5 * g.height_m - gy, 0.0};

  const glm::dvec3 d = point - eye;
  const double len = glm::length(d);
  if (!(len > 1e-6)) return s;  // eye on the gaze point: no direction

  s.direction = d / len;
  s.origin_m = glm::dvec3{0.0};
  if (t.has_head && t.head_position_um.z > 0) s.origin_m = eye - eye_in_s(t.head_position_um, g);
  s.valid = true;
  s.confidence = (left_ok && right_ok) ? 1.0f : 0.5f;
  return s;
}

}  // namespace gazelod::gaze::hid
