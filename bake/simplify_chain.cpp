// SPDX-License-Identifier: Apache-2.0
// meshopt_simplify per level, meshopt_simplifySloppy when topology stops it short of the target,
// meshopt_optimizeVertexCache on the result (see simplify_chain.hpp).
#include "bake/simplify_chain.hpp"

#include "bake/cluster_distance.hpp"
#include "bake/cluster_flips.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace gazelod::bake {
namespace {

// meshopt_simplify may stop a little above the target; beyond this factor the level counts as
// "not reached" and the sloppy simplifier gets a try.
constexpr double kReachSlack = 1.2;

std::uint32_t count_vertices(std::span<const std::uint32_t> idx, std::size_t vertex_count) {
  std::vector<bool> seen(vertex_count, false);
  std::uint32_t n = 0;
  for (std::uint32_t i : idx)
    if (!seen[i]) seen[i] = true, ++n;
  return n;
}

// The largest distance from a vertex of the source triangles to the level's triangles (each
// position once: `used` marks them, all 0 again on return); the source sampled at its vertices,
// as the cluster hierarchy measures it.
double largest_source_distance_m(std::span<const float> pos, std::span<const std::uint32_t> source,
                                 std::span<const std::uint32_t> level, TriangleGrid& grid,
                                 std::vector<std::uint8_t>& used) {
  grid.build(pos, level);
  double largest_m = 0.0;
  std::uint32_t hint = ~0u;
  for (std::uint32_t v : source) {
    if (used[v]) continue;
    used[v] = 1;
    // Only a farther triangle than the largest so far can raise it: the first one within it will do.
    const NearestTriangle t = grid.nearest(&pos[3 * std::size_t(v)], largest_m, hint);
    largest_m = std::max(largest_m, t.distance_m);
    hint = t.triangle;
  }
  for (std::uint32_t v : source) used[v] = 0;
  return largest_m;
}

}  // namespace

std::string validate_chain_options(const ChainOptions& o) {
  std::ostringstream m;
  if (o.ratios.empty() || o.ratios.size() > 254) {
    m << "need 1 to 254 coarser levels, got " << o.ratios.size();
    return m.str();
  }
  for (std::size_t k = 0; k < o.ratios.size(); ++k) {
    const double r = o.ratios[k];
    if (!(r > 0.0 && r < 1.0)) {
      m << "ratio " << k + 1 << " must be in (0, 1), got " << r;
      return m.str();
    }
    if (k > 0 && !(r < o.ratios[k - 1])) {
      m << "ratios must decrease strictly, got " << o.ratios[k - 1] << " then " << r;
      return m.str();
    }
  }
  if (!(o.target_error_rel > 0.0) || !std::isfinite(o.target_error_rel)) {
    m << "target error must be finite and > 0, got " << o.target_error_rel;
    return m.str();
  }
  return {};
}

PrimitiveChain simplify_chain(std::span<const float> pos, std::span<const std::uint32_t> idx,
                              const ChainOptions& options) {
  const std::size_t vcount = pos.size() / 3;
  PrimitiveChain chain;
  chain.scale_m = vcount ? meshopt_simplifyScale(pos.data(), vcount, 3 * sizeof(float)) : 0.0f;
  chain.levels.reserve(options.ratios.size() + 1);
  SimplifiedLevel& l0 = chain.levels.emplace_back();
  l0.indices.assign(idx.begin(), idx.end());
  l0.vertices = count_vertices(idx, vcount);

  const std::size_t tri0 = idx.size() / 3;
  const float target_error = static_cast<float>(options.target_error_rel);
  std::vector<std::uint32_t> dst(idx.size()), sloppy(idx.size());
  TriangleGrid grid;
  std::vector<std::uint8_t> used(vcount, 0);
  std::vector<float> normals;  // find_folds scratch
  for (double ratio : options.ratios) {
    const SimplifiedLevel& prev = chain.levels.back();
    SimplifiedLevel level;
    const auto target_tri = static_cast<std::size_t>(std::llround(static_cast<double>(tri0) * ratio));
    const std::size_t target = 3 * std::max<std::size_t>(1, target_tri);
    float err = 0.0f;
    std::size_t n =
        idx.empty()
            ? 0
            : meshopt_simplify(dst.data(), idx.data(), idx.size(), pos.data(), vcount, 3 * sizeof(float), target,
                               target_error, options.lock_borders ? unsigned(meshopt_SimplifyLockBorder) : 0u, &err);
    if (static_cast<double>(n) > kReachSlack * static_cast<double>(target)) {
      float serr = 0.0f;
      const std::size_t ns = meshopt_simplifySloppy(sloppy.data(), idx.data(), idx.size(), pos.data(), vcount,
                                                    3 * sizeof(float), target, target_error, &serr);
      if (ns < n) {  // closer to the target (possibly empty: the part vanishes at this level)
        dst.swap(sloppy);
        n = ns, err = serr, level.sloppy = true;
      }
    }
    if (n >= prev.indices.size()) {  // stuck: repeat the previous level
      level = prev;
      chain.levels.push_back(std::move(level));
      continue;
    }
    level.indices.assign(dst.begin(), dst.begin() + static_cast<std::ptrdiff_t>(n));
    meshopt_optimizeVertexCache(level.indices.data(), level.indices.data(), n, vcount);
    level.vertices = count_vertices(level.indices, vcount);
    // The error measured against the source, as the cluster hierarchy's (bake/cluster/cluster_build.hpp):
    // meshopt's estimate (`err`) is a quadric mean that falls several times below the largest
    // distance. A coarser level is never reported as more accurate than a finer one.
    // And at least the width of any triangle meshopt folded over (bake/cluster_flips.hpp): the
    // distance from the source's vertices cannot see the hole beside a fold.
    const Folds folds = find_folds(pos, idx, level.indices, normals);
    level.folded_triangles = folds.triangles;
    const double error_m =
        n == 0 ? double(chain.scale_m)
               : std::max(largest_source_distance_m(pos, idx, level.indices, grid, used), folds.width_m);
    level.error_m = std::max(error_m, prev.error_m);
    level.error_rel = chain.scale_m > 0.0 ? level.error_m / chain.scale_m : 0.0;
    chain.levels.push_back(std::move(level));
  }
  return chain;
}

}  // namespace gazelod::bake
