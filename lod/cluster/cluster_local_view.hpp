// SPDX-License-Identifier: Apache-2.0
// The viewer moved into a cluster instance's own space (lod/cluster/cluster_instances.hpp), and
// the linear selection there: the reference the bounding-hierarchy selection equals bit for bit
// (cluster_selector.hpp), and the path for the per-criterion cuts.
//
// Why the rule is the same in the instance's space: world = t + s R local with R a rotation and
// s > 0 uniform. Every quantity select_clusters compares is invariant under it when the viewer
// is moved along: the eye to R^T (eye - t) / s, the gaze and both angular velocities to R^T w
// (angles do not scale), the eye's and the mesh's velocities to R^T v / s (so |V| / d, a rate in
// rad/s, does not change); then distances and errors both shrink by s (f = d / (K e) is
// unchanged), angles and angular rates are the same, and so is the mesh's size-off cap in
// proportion. The float rounding is not the same (the records are not rounded into world
// space, the eye is rounded in local units), so near a threshold the local cut may differ from
// ClusterStore's world-space one in either direction, both being conservative against the exact
// rule; tests/lod/cluster_local_view_test.cpp and bench/RESULTS.md measure how often. One
// absolute constant does not scale: the nearest-point floor kNearFloorM (1 um) applies in local
// units, i.e. s um in the world (only errors below about 1e-8 s m are affected).
#pragma once

#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_kernel.hpp"
#include "lod/select.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace gazelod::lod {

// Largest |coordinate| of the eye in an instance's space that the float kernel takes (the eye
// is split into a float pair there).
inline constexpr double kMaxLocalEyeM = 1e30;

struct LocalView {
  Viewer viewer;                  // the world viewer moved into the instance's space
  glm::dvec3 mesh_velocity{0.0};  // the instance's velocity in its space
};

// world: a valid viewer (validate_viewer; not checked again here). "" or why not: an eye beyond
// kMaxLocalEyeM in the instance's units, or a velocity that overflows there.
[[nodiscard]] std::string local_view(const Viewer& world, const ClusterInstance& instance, LocalView& out);

// The kernel's constants for one instance in its space (select_clusters' own, for a one-mesh
// set of that velocity and finest error).
struct LocalFrames {
  detail::ClusterFrame frame;
  detail::ClusterMeshFrame mesh;
};
// detail_scale: the instance's (ClusterSet::mesh_detail_scale; 1 the perceptual cut), in [1, 1e6].
LocalFrames local_frames(const LocalView& view, double finest_error_m, double detail_scale = 1.0);

// A hierarchy as a one-mesh ClusterSet (no distinct records) with a velocity: what select_clusters
// reads for one instance in its space.
class OneInstanceSet {
 public:
  OneInstanceSet(const ClusterHierarchy& h, const glm::dvec3& velocity_m_s, double finest_error_m,
                 double detail_scale = 1.0);
  OneInstanceSet(const OneInstanceSet&) = delete;  // set() points into this object
  OneInstanceSet& operator=(const OneInstanceSet&) = delete;
  const ClusterSet& set() const { return set_; }

 private:
  std::uint32_t first_ = 0, count_ = 0;
  double vx_ = 0.0, vy_ = 0.0, vz_ = 0.0, finest_ = 0.0, detail_scale_ = 1.0;
  ClusterSet set_;
};

// select_clusters over every instance, each in its own space (the clusters numbered as
// ClusterInstances numbers them); every output of ClusterDecisions but record_flags (not used).
// Linear in the clusters. "" or the first instance's refusal (outputs then partly written).
// detail_scale: empty (every instance at 1, the perceptual cut) or one per instance, each in
// [1, 1e6] (ClusterSet::mesh_detail_scale: a frame budget's coarsening step).
[[nodiscard]] std::string select_clusters_local(const Viewer& viewer, const ClusterInstances& instances,
                                                const ClusterDecisions& out, std::span<const double> detail_scale = {});

}  // namespace gazelod::lod
