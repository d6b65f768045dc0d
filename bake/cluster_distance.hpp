// SPDX-License-Identifier: Apache-2.0
// Point-to-surface distance for the errors of the cluster hierarchy (bake/cluster/cluster_build.hpp) and
// of the LOD chain (bake/simplify_chain.hpp): the triangles of one simplified group or level in a
// uniform grid of cubic cells, about one triangle's area
// per cell face, searched ring by ring outward from the query point's cell with cells farther
// than the best distance so far skipped (Ericson 2005, ch. 7). The distance returned is always
// that to a real triangle, so it is never below the true nearest distance.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace gazelod::bake {

struct NearestTriangle {
  double distance_m = 0.0;
  std::uint32_t triangle = 0;  // position in the triangle list given to build()
};

class TriangleGrid;

// One caller's searches in a grid: its per-triangle visit stamps and its last answers. Several
// threads may search one grid at once, each with its own GridSearch; a search starts afresh when
// given a grid (or a build of it) other than its last, or after restart().
class GridSearch {
 public:
  // The nearest triangle, or, when `good_enough_m` > 0, the first one found within that distance
  // (tried first: `hint`, e.g. the previous query's answer, when it is a valid triangle; then
  // the last few answers a grid search found since the grid's build, as queries come in
  // spatial runs).
  NearestTriangle nearest(const TriangleGrid& grid, const float point[3], double good_enough_m = 0.0,
                          std::uint32_t hint = ~0u);
  // Forgets the last answers, as if given a new grid: a run of queries that must not depend on
  // the runs before it (another thread's, another order's) starts with this.
  void restart() { grid_ = nullptr; }

 private:
  const TriangleGrid* grid_ = nullptr;
  std::uint64_t build_ = 0;
  std::vector<std::uint32_t> stamp_;  // per triangle
  std::uint32_t query_ = 0;
  static constexpr std::size_t kRecent = 4;  // fewer grid searches by 40 % on a terrain's build
  std::uint32_t recent_[kRecent] = {~0u, ~0u, ~0u, ~0u};
  std::size_t recent_next_ = 0;
};

// Keeps its arrays between builds (one per thread).
class TriangleGrid {
 public:
  // positions_xyz: 3 floats per vertex; triangles: a non-empty triangle list into them.
  void build(std::span<const float> positions_xyz, std::span<const std::uint32_t> triangles);
  std::size_t triangles() const { return tri_.size() / kStride; }
  // GridSearch::nearest with the grid's own search state.
  NearestTriangle nearest(const float point[3], double good_enough_m = 0.0, std::uint32_t hint = ~0u) {
    return search_.nearest(*this, point, good_enough_m, hint);
  }

 private:
  friend class GridSearch;
  static constexpr std::size_t kStride = 22;  // doubles per triangle in tri_
  void cell_of(const double p[3], int c[3]) const;
  double distance_sq(std::uint32_t triangle, const double p[3], double below_sq) const;
  double lo_[3] = {0, 0, 0}, cell_m_ = 1.0, per_cell_ = 1.0;
  int dim_[3] = {1, 1, 1};
  std::vector<std::uint32_t> first_, items_, fill_;  // per cell: first item; items; build scratch
  std::vector<int> range_;                           // build scratch: per triangle, its first and last cell (x, y, z)
  // Per triangle: corner a, edges ab and ac, unit normal, ab.ab, ab.ac, ac.ac, 1 / Gram
  // determinant (0: degenerate), then corners b and c.
  std::vector<double> tri_;
  std::uint64_t build_ = 0;  // unique per build of any grid in the process
  GridSearch search_;
};

// Distance from p to triangle (a, b, c), all in double (Ericson 2005, 5.1.5).
double point_triangle_distance(const double p[3], const double a[3], const double b[3], const double c[3]);

}  // namespace gazelod::bake
