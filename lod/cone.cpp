// Foveal cone construction and membership tests (see cone.hpp).
#include "lod/cone.hpp"

#include "lod/acuity.hpp"
#include "lod/criteria.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gazelod::lod {
namespace {
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
}

Cone make_foveal_cone(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, double half_angle_deg,
                      double tracker_error_deg) {
  Cone c;
  c.apex_m = eye_m;
  c.axis = glm::normalize(gaze_dir);
  double a = half_angle_deg + tracker_error_deg;
  if (std::isnan(a)) a = 180.0;
  c.half_angle_rad = std::clamp(a, 0.0, 180.0) / kDegPerRad;
  return c;
}

void lod_shell_half_angles_deg(std::span<const double> removed_freq_cpd, double vel_dps,
                               double xi_cpd, double scale, double tracker_error_deg,
                               std::span<double> out_deg) {
  const std::size_t n = std::min(removed_freq_cpd.size(), out_deg.size());
  if (std::isnan(scale) || scale > 1.0) scale = 1.0;
  const double err = tracker_error_deg > 0.0 ? tracker_error_deg : 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double f = removed_freq_cpd[k];
    double e;
    if (!(f > 0.0) || !(scale > 0.0)) {
      e = (scale > 0.0) ? std::numeric_limits<double>::infinity() : 0.0;
    } else if (xi_cpd > 0.0 && f > scale * xi_cpd) {
      e = 0.0;  // beyond what the display shows: invisible everywhere
    } else {
      // Visible while s G(v) M(E) >= f: up to the eccentricity where H falls below f / s.
      e = eccentricity_threshold_deg(f / scale, vel_dps);
    }
    out_deg[k] = (e > 0.0) ? e + err : e;
  }
}

bool sphere_touches_cone(const Cone& cone, const glm::dvec3& center_m, double radius_m) {
  const glm::dvec3 r = center_m - cone.apex_m;
  const double d = glm::length(r);
  if (!(d > radius_m)) return true;
  const double phi = angle_between_rad(cone.axis, r);
  return phi - angular_radius_rad(d, radius_m) <= cone.half_angle_rad;
}

namespace {

// Point p (relative to the apex) inside the one-sided cone of unit axis a, cos^2 of half-angle.
bool point_in_cone(const glm::dvec3& p, const glm::dvec3& a, double cos2) {
  const double pa = glm::dot(p, a);
  return pa >= 0.0 && pa * pa >= cos2 * glm::dot(p, p);
}

// Segment p0 + t (p1 - p0), t in [0, 1], meets the cone. f(t) = (p.a)^2 - cos2 |p|^2 is a
// quadratic; f >= 0 with p.a >= 0 is the cone. Endpoints are tested as corners; an interior
// piece of the cone has f's maximum inside (A < 0), tested at the vertex t* = -B / 2A.
bool segment_in_cone(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& a, double cos2) {
  const glm::dvec3 dv = p1 - p0;
  const double pa = glm::dot(p0, a), da = glm::dot(dv, a);
  const double qa = da * da - cos2 * glm::dot(dv, dv);
  const double qb = 2.0 * (pa * da - cos2 * glm::dot(p0, dv));
  if (!(qa < 0.0)) return false;
  const double t = -qb / (2.0 * qa);
  if (!(t > 0.0 && t < 1.0)) return false;
  return point_in_cone(p0 + t * dv, a, cos2);
}

// The axis ray from the apex hits the box (slab test); includes the apex inside the box.
bool ray_hits_box(const glm::dvec3& o, const glm::dvec3& a, const glm::dvec3& lo,
                  const glm::dvec3& hi) {
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (a[i] == 0.0) {
      if (o[i] < lo[i] || o[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - o[i]) / a[i], tb = (hi[i] - o[i]) / a[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

bool box_touches_cone(const Cone& cone, const glm::dvec3& lo, const glm::dvec3& hi) {
  if (!(cone.half_angle_rad < std::numbers::pi / 2)) return true;
  const double c = std::cos(cone.half_angle_rad);
  const double cos2 = c * c;
  glm::dvec3 corner[8];
  for (int i = 0; i < 8; ++i) {
    corner[i] = glm::dvec3{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z} -
                cone.apex_m;
    if (point_in_cone(corner[i], cone.axis, cos2)) return true;
  }
  if (ray_hits_box(cone.apex_m, cone.axis, lo, hi)) return true;
  for (int i = 0; i < 8; ++i)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(i & bit) && segment_in_cone(corner[i], corner[i | bit], cone.axis, cos2)) return true;
  return false;
}

bool projected_circle_touches(const Cone& cone, const glm::dvec3& view_forward,
                              const glm::dvec3& view_up, const glm::dvec3& center_m,
                              double radius_m) {
  const glm::dvec3 fwd = glm::normalize(view_forward);
  const glm::dvec3 right = glm::normalize(glm::cross(fwd, view_up));
  const glm::dvec3 up = glm::cross(right, fwd);
  const glm::dvec3 p = center_m - cone.apex_m;
  const double z = glm::dot(p, fwd);
  if (z <= radius_m) return true;  // reaches behind the eye plane: cannot project, keep it
  const double gz = glm::dot(cone.axis, fwd);
  if (!(gz > 0.0)) return true;  // gaze off the image plane: no spot to test against
  const double sx = glm::dot(p, right) / z, sy = glm::dot(p, up) / z;
  const double gx = glm::dot(cone.axis, right) / gz, gy = glm::dot(cone.axis, up) / gz;
  const double r_obj = radius_m / z;
  const double r_spot = cone.half_angle_rad < std::numbers::pi / 2
                            ? std::tan(cone.half_angle_rad)
                            : std::numeric_limits<double>::infinity();
  const double dx = sx - gx, dy = sy - gy;
  const double reach = r_obj + r_spot;
  return dx * dx + dy * dy <= reach * reach;
}

}  // namespace gazelod::lod
