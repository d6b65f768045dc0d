// The volumetric foveal cone of Reddy 1995 (seed 003 sections 5-5.3): a cone along the gaze
// ray, one nested shell per LOD whose half-angle follows from the acuity model, inflated by
// the eye tracker's angular error. Membership tests may over-include (keep detail) but never
// exclude an object that touches the cone; the projected-circle test is the renderer-level
// variant the paper sketches, and is approximate (bench/lod measures how often it errs).
#pragma once

#include <glm/vec3.hpp>

#include <span>

namespace gazelod::lod {

struct Cone {
  glm::dvec3 apex_m{0.0};
  glm::dvec3 axis{0.0, 0.0, -1.0};  // unit
  double half_angle_rad = 0.0;      // in [0, pi]
};

// A cone at the eye along the gaze, half-angle + tracker error (both degrees, clamped to
// [0, 180]). gaze_dir must be non-zero; NaN angles count as 180 (include everything).
Cone make_foveal_cone(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, double half_angle_deg,
                      double tracker_error_deg);

// Half-angle (deg) of each LOD's shell: inside it level k's removed detail (removed_freq_cpd[k],
// cycles/deg at the object's current size) is still visible at retinal velocity vel_dps, so
// level k must not be used by an object touching the shell. 0 when the level is invisible
// everywhere; +inf when it is visible everywhere. Plus tracker_error_deg. out.size() must
// equal removed_freq_cpd.size().
void lod_shell_half_angles_deg(std::span<const double> removed_freq_cpd, double vel_dps,
                               double xi_cpd, double scale, double tracker_error_deg,
                               std::span<double> out_deg);

// Sphere touches cone: exact for spheres (angle to the centre minus the angular radius
// <= half-angle; the eye inside the sphere always touches).
bool sphere_touches_cone(const Cone& cone, const glm::dvec3& center_m, double radius_m);

// Axis-aligned box touches cone: exact for half-angles below 90 deg (a box corner inside,
// the axis ray through the box, or an edge crossing the cone surface); for 90 deg and more
// it answers true (over-includes).
bool box_touches_cone(const Cone& cone, const glm::dvec3& box_min_m, const glm::dvec3& box_max_m);

// Renderer level (seed 003 section 5.2): a view looking along view_forward with up view_up
// (orthonormalised here) projects the sphere to a circle of radius r / z around the
// projected centre and the cone to a circle of radius tan(half-angle) around the projected
// gaze point (image plane at distance 1); the circles are tested for overlap. Objects reaching
// behind the eye plane (z <= r) are included. Approximate: off-axis spheres project to
// ellipses, so it can miss or over-include; never use it where exclusion must be safe.
bool projected_circle_touches(const Cone& cone, const glm::dvec3& view_forward,
                              const glm::dvec3& view_up, const glm::dvec3& center_m,
                              double radius_m);

}  // namespace gazelod::lod
