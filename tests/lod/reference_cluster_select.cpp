// SPDX-License-Identifier: Apache-2.0
// The exact per-record rule (see reference_cluster_select.hpp).
#include "tests/lod/reference_cluster_select.hpp"

#include "auxiliary/angles.hpp"
#include "lod/acuity.hpp"
#include "lod/cluster/cluster_select_kernel.hpp"  // kNearFloorM
#include "tests/lod/reference_criteria.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gazelod::lod::test {
namespace {

constexpr double kK = 360.0 / std::numbers::pi;  // f = dist / (K e)

// Invisible: f = dist / (K e) > A; e = 0 always, e = +inf never.
bool invisible(double a_cpd, double dist_m, double e_m) {
  if (e_m == 0.0) return true;
  return dist_m > a_cpd * e_m * kK;
}

struct Decisions {
  bool combined, size, eccentricity, velocity;
};

Decisions decide(const Viewer& vw, double ecc, double vel, double near, double cap, double e, double slack_rel,
                 double slack_cpd) {
  const double s = vw.scale, xi = vw.xi_cpd;
  const auto a = [&](double v, double ecc_deg) {
    return acuity_cpd(v, ecc_deg, xi, s) * (1.0 + slack_rel) + slack_cpd;
  };
  const double e_on = vw.use_eccentricity ? ecc : 0.0, v_on = vw.use_velocity ? vel : 0.0;
  const double dist_off = std::min(near, cap);
  Decisions d;
  d.combined = invisible(a(v_on, e_on), vw.use_size ? near : dist_off, e);
  d.size = vw.use_size ? invisible(a(0.0, 0.0), near, e) : e == 0.0;
  d.eccentricity = vw.use_eccentricity ? invisible(a(0.0, ecc), dist_off, e) : e == 0.0;
  d.velocity = vw.use_velocity ? invisible(a(vel, 0.0), dist_off, e) : e == 0.0;
  return d;
}

}  // namespace

RecordRef reference_record(const Viewer& vw, const glm::dvec3& mesh_vel, double finest, const glm::dvec3& c, double rho,
                           double e) {
  const double floor_m = detail::kNearFloorM;
  const glm::dvec3 w = vw.head_angular_velocity_rad_s + vw.gaze_angular_velocity_in_head_rad_s;
  const double dist = glm::length(c - vw.eye_position_m);
  const bool near = !(dist - rho > floor_m);
  RecordRef r;
  r.near_m = near ? floor_m : dist - rho;
  r.ecc_deg = std::max(
      0.0, nearest_point_eccentricity_deg(vw.eye_position_m, vw.gaze_direction, c, rho) - vw.tracker_error_deg);
  // The centre's retinal velocity lowered to the sphere's slowest point (cluster_select.hpp).
  const double speed = glm::length(mesh_vel - vw.eye_velocity_m_s), spin = glm::length(w);
  const double v_centre = retinal_velocity_dps(vw.eye_position_m, vw.eye_velocity_m_s, w, c, mesh_vel);
  const double lip_dps = rho * (2.0 * speed / r.near_m + spin) / r.near_m * aux::kDegPerRad;
  r.vel_dps = near ? 0.0 : std::max(0.0, v_centre - lip_dps);
  const double a0 = acuity_cpd(0.0, 0.0, vw.xi_cpd, vw.scale);
  const double cap = kK * a0 * finest;

  const Decisions exact = decide(vw, r.ecc_deg, r.vel_dps, r.near_m, cap, e, 0.0, 0.0);
  r.combined = exact.combined, r.size = exact.size;
  r.eccentricity = exact.eccentricity, r.velocity = exact.velocity;

  // Robust: still invisible with every input moved towards keeping detail by ten times or more
  // the kernel's slacks (cluster_select_kernel.hpp).
  const double scale_dps = (speed / std::max(dist, floor_m) + spin) * aux::kDegPerRad;
  const bool at_surface = !(dist - rho > 1e-4 * dist);
  const bool at_floor = !(dist - rho > floor_m * (1.0 + 1e-4) + 1e-6 * dist);
  const double ecc_p = at_surface ? 0.0 : std::max(0.0, r.ecc_deg - 0.003);
  const double vel_p = at_floor ? 0.0 : std::max(0.0, r.vel_dps * (1.0 - 1e-3) - 3e-4 * scale_dps);
  // The kernel lowers d - rho by 2^-20 d (and rounds d to float): an absolute 4e-6 d.
  const double near_p = at_floor ? floor_m : std::max(floor_m, r.near_m * (1.0 - 1e-5) - 4e-6 * dist);
  const Decisions moved = decide(vw, ecc_p, vel_p, near_p, cap * (1.0 - 1e-5), e, 1e-3, 1e-3);
  r.robust = (!exact.combined || moved.combined) && (!exact.size || moved.size) &&
             (!exact.eccentricity || moved.eccentricity) && (!exact.velocity || moved.velocity);
  return r;
}

RecordRef reference_record(const Viewer& vw, const ClusterSet& cs, std::size_t i, bool parent) {
  std::size_t mesh = 0;
  while (i >= std::size_t{cs.mesh_first_cluster[mesh]} + cs.mesh_cluster_count[mesh]) ++mesh;
  const glm::dvec3 vel = cs.mesh_vel_x_m_s.empty()
                             ? glm::dvec3{0.0}
                             : glm::dvec3{cs.mesh_vel_x_m_s[mesh], cs.mesh_vel_y_m_s[mesh], cs.mesh_vel_z_m_s[mesh]};
  if (parent)
    return reference_record(vw, vel, cs.mesh_finest_error_m[mesh],
                            {cs.parent_center_x_m[i], cs.parent_center_y_m[i], cs.parent_center_z_m[i]},
                            cs.parent_radius_m[i], cs.parent_error_m[i]);
  return reference_record(vw, vel, cs.mesh_finest_error_m[mesh],
                          {cs.self_center_x_m[i], cs.self_center_y_m[i], cs.self_center_z_m[i]}, cs.self_radius_m[i],
                          cs.self_error_m[i]);
}

}  // namespace gazelod::lod::test
