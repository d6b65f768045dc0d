// SPDX-License-Identifier: Apache-2.0
// The per-record rule of lod/cluster/cluster_select.hpp written directly in double with the exact
// scalar criteria (tests/lod/reference_criteria.hpp, lod/acuity.hpp): the reference the float
// kernel is held against (it may keep finer, never coarser).
#pragma once

#include "lod/cluster/cluster_select.hpp"

#include <glm/vec3.hpp>

namespace gazelod::lod::test {

struct RecordRef {
  bool combined = false, size = false, eccentricity = false, velocity = false;  // invisible
  double ecc_deg = 0.0, vel_dps = 0.0, near_m = 0.0;                            // E, v (the sphere's slowest point), d
  // False where the kernel's slacks could move a decision: a removed frequency within 0.1 % +
  // 0.001 cycles/deg of a threshold, E within 0.01 deg of M's seam, or the eye within 1e-4 of
  // the sphere's surface (relative) or the distance floor.
  bool robust = true;
};

// The rule for one record (centre, radius, error) of a mesh moving at mesh_velocity_m_s whose
// finest error is finest_error_m.
RecordRef reference_record(const Viewer& viewer, const glm::dvec3& mesh_velocity_m_s, double finest_error_m,
                           const glm::dvec3& center_m, double radius_m, double error_m);

// Cluster i's self (parent = false) or parent record of a ClusterSet, with its mesh's data.
RecordRef reference_record(const Viewer& viewer, const ClusterSet& clusters, std::size_t i, bool parent);

}  // namespace gazelod::lod::test
