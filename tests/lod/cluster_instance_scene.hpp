// SPDX-License-Identifier: Apache-2.0
// Scenes of cluster instances for the bounding-hierarchy selection's tests: a baked terrain
// tile (bake's cluster hierarchy of a generated terrain) and synthetic trees, placed many times
// with different rotations, scales and velocities; a walking viewer; and the comparison of the
// selector's cut (lod/cluster/cluster_selector.hpp) with the linear pass in local space
// (select_clusters_local), byte for byte.
#pragma once

#include "lod/cluster/cluster_instances.hpp"
#include "lod/cluster/cluster_selector.hpp"
#include "lod/select.hpp"
#include "sim/simulator.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace gazelod::lod::test {

// bake::build_cluster_hierarchy of a generated terrain of about `triangles` triangles over a
// square of side size_m centred on the origin (bake/terrain_mesh.hpp), one thread.
ClusterHierarchy baked_terrain(std::uint64_t triangles, double size_m, double relief_m);

// One placed instance of hierarchy `hierarchy` of the scene.
struct Placement {
  std::uint32_t hierarchy = 0;
  InstanceTransform pose;
  glm::dvec3 velocity_m_s{0.0};
};

// `count` placements of the given hierarchies in turn on a square grid of `spacing_m`, each
// rotated about a random axis (every third about +Y only), scaled by 0.05 to 20 (every other one
// 1) and every fourth moving.
std::vector<Placement> scatter(std::size_t count, std::uint32_t hierarchies, double spacing_m, std::uint64_t seed);

// A walk: frame k's viewer, passing over the scene at eye height, its head sweeping and now
// and then turning fast (G towards 0), saccades (fast gaze rotation), sometimes a criterion off.
Viewer walk_viewer(std::size_t frame, std::size_t frames, double extent_m, std::uint64_t seed);

// The viewer of a scenario at t_ns: the simulator's true head and gaze (as `gazelod run`'s
// audit oracle takes them: the gaze's rotation by a central difference over +-1 ms), tracker
// error 0, xi_cpd as given.
Viewer scenario_viewer(sim::Simulator& simulator, std::int64_t t_ns, double xi_cpd);

// Outputs of one pass, one byte per cluster.
struct CutBytes {
  explicit CutBytes(std::size_t n = 0) : drawn(n), why(n), bits(n) {}
  std::vector<std::uint8_t> drawn, why, bits;
};

// Record decisions (two per cluster and frame) where a local-space cut and a world-space one
// disagree, by direction (the local record invisible where the world one is not: coarser).
struct Disagreement {
  std::size_t decisions = 0, local_coarser = 0, local_finer = 0, drawn_differ = 0, frames = 0;
  void add(const CutBytes& local, const CutBytes& world);  // one frame
};

// "" when the selector's bytes and list equal the linear pass's (run here into `linear`) for
// this viewer, else the first difference. `bytes`: the selector's byte arrays, kept by the caller
// between frames and written by nobody else (the selector writes them incrementally).
std::string compare_with_linear(const Viewer& viewer, const ClusterInstances& instances, ClusterSelector& selector,
                                CutBytes& bytes, CutBytes& linear);

}  // namespace gazelod::lod::test
