// SPDX-License-Identifier: Apache-2.0
// One group's simplification (group_simplify.hpp).
#include "bake/cluster/group_simplify.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <cfloat>

namespace gazelod::bake {
namespace {

// meshopt's error estimate (relative to the group's extent) up to which a collapse is free:
// float noise on coplanar or collinear collapses.
constexpr float kFreeErrorRel = 1e-5f;

}  // namespace

GroupSimplified simplify_group_triangles(std::vector<float>& positions_xyz, std::size_t vertex_count,
                                         std::span<const std::uint32_t> indices, const GroupSimplifyOptions& o,
                                         std::vector<std::uint32_t>& simplified, GroupSimplifyScratch& s) {
  simplified.resize(indices.size());
  auto simplify = [&](std::size_t target_indices, float error_limit, float* error_rel) {
    return meshopt_simplify(simplified.data(), indices.data(), indices.size(), positions_xyz.data(),
                            positions_xyz.size() / 3, 3 * sizeof(float), target_indices, error_limit,
                            o.lock_open_borders ? unsigned(meshopt_SimplifyLockBorder) : 0u, error_rel);
  };
  auto folds = [&](std::size_t count, std::vector<std::uint32_t>* corners = nullptr) {
    return find_folds(positions_xyz, indices, std::span<const std::uint32_t>(simplified.data(), count), s.normals,
                      corners);
  };
  const std::size_t target = 3 * static_cast<std::size_t>(double(indices.size() / 3) * o.simplify_ratio);
  float error_rel = 0.0f;  // meshopt's estimate, relative to the group's extent
  std::size_t n = target < 3 ? 0 : simplify(target, FLT_MAX, &error_rel);
  // Reached at no error: take every free collapse, past the target, rather than leave free
  // detail to a level that may have to force collapses; unless its folds are wider than the
  // step to the target's.
  bool took_free = false;
  if (n > 0 && error_rel <= kFreeErrorRel) {
    const double at_target_m = folds(n).width_m;
    const std::size_t free = simplify(0, kFreeErrorRel, nullptr);
    if (free > 0 && folds(free).width_m <= at_target_m)
      n = free, took_free = true;
    else
      n = simplify(target, FLT_MAX, nullptr);
  }
  // meshopt 0.18 folds some triangles over: counted by the caller, whose group error is raised
  // to the width of the hole they may leave. (Redoing folded groups in gentler steps cost 30 to
  // 40 % of the build's throughput and still left a third to three quarters.)
  Folds f = n > 0 ? folds(n) : Folds{};
  // The retries, only where the folds would set the group's error: wider than meshopt's own
  // estimate (a quadric mean, below the largest distance the build will measure). A narrower
  // fold (the slivers on a terrain) costs nothing in the error, and its retry, constrained by
  // the locks, tends to raise the distance: skipping those made the build 15 % faster on the
  // evaluation's terrain and its cut 2 % smaller. On the generated city two retries leave 1,458
  // of 5,607 folds; the rest fold elsewhere or can only be avoided by stopping.
  const double estimate_m =
      f.triangles > 0 ? double(error_rel) * meshopt_simplifyScale(positions_xyz.data(), vertex_count, 3 * sizeof(float))
                      : 0.0;
  for (unsigned retry = 0; retry < o.fold_retries && f.triangles > 0 && f.width_m > estimate_m; ++retry) {
    s.corners.clear();
    folds(n, &s.corners);
    lock_around_folds(positions_xyz, vertex_count, indices, s.corners, s.marks);
    s.kept.assign(simplified.begin(), simplified.begin() + static_cast<std::ptrdiff_t>(n));
    const std::size_t again = took_free ? simplify(0, kFreeErrorRel, nullptr) : simplify(target, FLT_MAX, nullptr);
    const Folds g = again > 0 ? folds(again) : Folds{};
    if (again > 0 && g.width_m < f.width_m && double(again) <= o.stuck_ratio * double(indices.size())) {
      n = again, f = g;
    } else {
      std::copy(s.kept.begin(), s.kept.end(), simplified.begin());
      break;
    }
  }
  return {n, f};
}

}  // namespace gazelod::bake
