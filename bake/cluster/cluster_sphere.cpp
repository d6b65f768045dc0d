// SPDX-License-Identifier: Apache-2.0
// Ritter's (1990) bounding sphere, generalised from points to spheres (cluster_sphere.hpp).
#include "bake/cluster/cluster_sphere.hpp"

#include <algorithm>
#include <cmath>

namespace gazelod::bake {
namespace {

struct Ball {
  double c[3];
  double r;
};

Ball ball(const Sphere& s) {
  return {{s.x, s.y, s.z}, s.radius_m};
}

double distance(const double a[3], const double b[3]) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The smallest sphere around `a` and `b` (one of them when it holds the other).
Ball around_two(const Ball& a, const Ball& b) {
  const double d = distance(a.c, b.c);
  if (d + b.r <= a.r) return a;
  if (d + a.r <= b.r) return b;
  const double r = (d + a.r + b.r) / 2.0;
  // d > 0 here: with d == 0 one of the tests above holds.
  const double t = (r - a.r) / d;
  return {{a.c[0] + (b.c[0] - a.c[0]) * t, a.c[1] + (b.c[1] - a.c[1]) * t, a.c[2] + (b.c[2] - a.c[2]) * t}, r};
}

double reach(const Sphere& outer_centre, const Sphere& s) {
  const double c[3] = {outer_centre.x, outer_centre.y, outer_centre.z};
  const Ball b = ball(s);
  return distance(c, b.c) + b.r;
}

}  // namespace

Sphere enclosing_sphere(std::span<const Sphere> spheres) {
  if (spheres.empty()) return {};
  // Start from the two spheres farthest apart along the axis of largest spread.
  std::size_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t i = 1; i < spheres.size(); ++i) {
    const Ball b = ball(spheres[i]);
    for (int k = 0; k < 3; ++k) {
      if (b.c[k] - b.r < ball(spheres[lo[k]]).c[k] - ball(spheres[lo[k]]).r) lo[k] = i;
      if (b.c[k] + b.r > ball(spheres[hi[k]]).c[k] + ball(spheres[hi[k]]).r) hi[k] = i;
    }
  }
  int axis = 0;
  double best = -1.0;
  for (int k = 0; k < 3; ++k) {
    const Ball a = ball(spheres[lo[k]]), b = ball(spheres[hi[k]]);
    const double spread = (b.c[k] + b.r) - (a.c[k] - a.r);
    if (spread > best) best = spread, axis = k;
  }
  Ball s = around_two(ball(spheres[lo[axis]]), ball(spheres[hi[axis]]));
  for (const Sphere& q : spheres) s = around_two(s, ball(q));

  // Rounding the centre to float moves it: measure the radius again about the stored centre.
  Sphere out{static_cast<float>(s.c[0]), static_cast<float>(s.c[1]), static_cast<float>(s.c[2]), 0.0f};
  double r = 0.0;
  for (const Sphere& q : spheres) r = std::max(r, reach(out, q));
  float rf = static_cast<float>(r);
  while (static_cast<double>(rf) < r) rf = std::nextafter(rf, INFINITY);
  out.radius_m = rf;
  return out;
}

bool sphere_contains(const Sphere& outer, const Sphere& inner) {
  return reach(outer, inner) <= static_cast<double>(outer.radius_m);
}

}  // namespace gazelod::bake
