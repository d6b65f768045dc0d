// SPDX-License-Identifier: Apache-2.0
// The per-object quantities the acuity model needs (Reddy 1998 section 3.2): angular size,
// eccentricity of the bounding sphere's nearest point to the gaze ray, retinal velocity.
// Exact scalar forms with libm (atan2, never acos of a dot product): the tests' reference.
// lod/select.cpp computes the same quantities inline for whole arrays (vectorised) and is
// tested against these; no product code calls them, so they live with the tests.
#pragma once

#include <glm/vec3.hpp>

namespace gazelod::lod {

// Angular radius of a sphere of radius_m whose centre is dist_m away: asin(r / d) written as
// atan2(r, sqrt(d^2 - r^2)); pi/2 when the eye is inside or on the sphere (d <= r).
double angular_radius_rad(double dist_m, double radius_m);

// Pixels the sphere's diameter covers at px_per_deg (display pixels per degree).
double pixel_diameter_px(double angular_radius_deg, double px_per_deg);

// Eccentricity (deg) of the sphere's point nearest the gaze ray: the angle from the gaze to
// the centre minus the angular radius, 0 when the gaze ray passes through the sphere or the
// eye is inside it. gaze_dir need not be unit length (must be non-zero).
double nearest_point_eccentricity_deg(const glm::dvec3& eye_m, const glm::dvec3& gaze_dir, const glm::dvec3& center_m,
                                      double radius_m);

// Angular speed (deg/s) of the object's image on the retina. The direction r = centre - eye
// turns at w_obj = r x (v_obj - v_eye) / |r|^2 (head translation and object motion); the gaze
// turns at w_gaze = head rotation + eye-in-head rotation (smooth pursuit keeps the object
// still on the retina). Retinal speed = |(w_obj - w_gaze) x r| / |r|. 0 at r = 0.
double retinal_velocity_dps(const glm::dvec3& eye_m, const glm::dvec3& eye_velocity_m_s,
                            const glm::dvec3& gaze_angular_velocity_rad_s, const glm::dvec3& center_m,
                            const glm::dvec3& object_velocity_m_s);

}  // namespace gazelod::lod
