// SPDX-License-Identifier: Apache-2.0
// Uniform-grid nearest-triangle search (cluster_distance.hpp).
#include "bake/cluster_distance.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace gazelod::bake {
namespace {

double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double segment_distance_sq(const double p[3], const double a[3], const double b[3]) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const double len_sq = dot(ab, ab);
  const double t = len_sq > 0.0 ? std::clamp(dot(ap, ab) / len_sq, 0.0, 1.0) : 0.0;
  const double d[3] = {ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]};
  return dot(d, d);
}

double segment_distance(const double p[3], const double a[3], const double b[3]) {
  return std::sqrt(segment_distance_sq(p, a, b));
}

double distance_to(const double p[3], const double q[3]) {
  const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  return std::sqrt(dot(d, d));
}

}  // namespace

double point_triangle_distance(const double p[3], const double a[3], const double b[3], const double c[3]) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double ap[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return distance_to(p, a);
  const double bp[3] = {p[0] - b[0], p[1] - b[1], p[2] - b[2]};
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return distance_to(p, b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return segment_distance(p, a, b);
  const double cp[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return distance_to(p, c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return segment_distance(p, a, c);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return segment_distance(p, b, c);
  const double sum = va + vb + vc;
  if (!(sum > 0.0))  // collinear corners: the nearest point is on an edge
    return std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, a, c)});
  const double v = vb / sum, w = vc / sum;
  const double q[3] = {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w};
  return distance_to(p, q);
}

void TriangleGrid::cell_of(const double p[3], int c[3]) const {
  for (int k = 0; k < 3; ++k) {  // truncation is floor once negatives are clamped to 0
    const double u = (p[k] - lo_[k]) * per_cell_;
    c[k] = u > 0.0 ? std::min(static_cast<int>(std::min(u, 1e9)), dim_[k] - 1) : 0;
  }
}

// Squared distance, or infinity when it cannot be below `below_sq` (the plane is that far). Inside
// the triangle's prism it is the plane's; outside, the nearest point is on an edge the point lies
// beyond (barycentric weight < 0), and only those edges are tried.
double TriangleGrid::distance_sq(std::uint32_t t, const double p[3], double below_sq) const {
  const double* q = &tri_[kStride * t];
  const double* b = q + 16;
  const double* c = q + 19;
  const double v[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  if (q[15] == 0.0)
    return std::min({segment_distance_sq(p, q, b), segment_distance_sq(p, b, c), segment_distance_sq(p, q, c)});
  const double h = v[0] * q[9] + v[1] * q[10] + v[2] * q[11];
  if (h * h >= below_sq) return std::numeric_limits<double>::infinity();
  const double d20 = v[0] * q[3] + v[1] * q[4] + v[2] * q[5], d21 = v[0] * q[6] + v[1] * q[7] + v[2] * q[8];
  const double wb = (q[14] * d20 - q[13] * d21) * q[15], wc = (q[12] * d21 - q[13] * d20) * q[15];
  if (wb >= 0.0 && wc >= 0.0 && wb + wc <= 1.0) return h * h;
  double d = std::numeric_limits<double>::infinity();
  if (wb < 0.0) d = std::min(d, segment_distance_sq(p, q, c));
  if (wc < 0.0) d = std::min(d, segment_distance_sq(p, q, b));
  if (wb + wc > 1.0) d = std::min(d, segment_distance_sq(p, b, c));
  return d;
}

void TriangleGrid::build(std::span<const float> pos, std::span<const std::uint32_t> tris) {
  const std::size_t count = tris.size() / 3;
  tri_.resize(kStride * count);
  double hi[3];
  for (int k = 0; k < 3; ++k) lo_[k] = INFINITY, hi[k] = -INFINITY;
  double area_m2 = 0.0;
  for (std::size_t t = 0; t < count; ++t) {
    double* q = &tri_[kStride * t];
    double c[9];
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        c[3 * j + k] = pos[3 * tris[3 * t + j] + k];
        lo_[k] = std::min(lo_[k], c[3 * j + k]), hi[k] = std::max(hi[k], c[3 * j + k]);
      }
    const double u[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]}, v[3] = {c[6] - c[0], c[7] - c[1], c[8] - c[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double n_len = std::sqrt(dot(n, n));
    area_m2 += 0.5 * n_len;
    const double d00 = dot(u, u), d01 = dot(u, v), d11 = dot(v, v), gram = d00 * d11 - d01 * d01;
    // Nearly collinear corners: the edges alone give the distance.
    const bool flat = !(n_len > 0.0) || !(gram > 1e-12 * d00 * d11);
    const double row[22] = {c[0],
                            c[1],
                            c[2],
                            u[0],
                            u[1],
                            u[2],
                            v[0],
                            v[1],
                            v[2],
                            flat ? 0.0 : n[0] / n_len,
                            flat ? 0.0 : n[1] / n_len,
                            flat ? 0.0 : n[2] / n_len,
                            d00,
                            d01,
                            d11,
                            flat ? 0.0 : 1.0 / gram,
                            c[3],
                            c[4],
                            c[5],
                            c[6],
                            c[7],
                            c[8]};
    std::copy(row, row + kStride, q);
  }
  const double extent_m = std::max({hi[0] - lo_[0], hi[1] - lo_[1], hi[2] - lo_[2]});
  // About one triangle per cell face; never so fine that the cells outnumber 4 per triangle.
  cell_m_ = std::max({std::sqrt(area_m2 / double(std::max<std::size_t>(count, 1))), extent_m * 1e-3, 1e-9});
  const double cap = 4.0 * double(count) + 64.0;
  for (;;) {
    double cells = 1.0;
    for (int k = 0; k < 3; ++k) cells *= std::floor((hi[k] - lo_[k]) / cell_m_) + 1.0;
    if (cells <= cap) break;
    cell_m_ *= 1.25;
  }
  per_cell_ = 1.0 / cell_m_;
  for (int k = 0; k < 3; ++k) dim_[k] = static_cast<int>(std::floor((hi[k] - lo_[k]) / cell_m_)) + 1;
  const std::size_t cells = std::size_t(dim_[0]) * dim_[1] * dim_[2];
  first_.assign(cells + 1, 0);
  // Each triangle's range of cells (its box's corners' cells), for both passes below.
  range_.resize(6 * count);
  for (std::size_t t = 0; t < count; ++t) {
    const double* q = &tri_[kStride * t];
    const double mn[3] = {std::min({q[0], q[16], q[19]}), std::min({q[1], q[17], q[20]}),
                          std::min({q[2], q[18], q[21]})};
    const double mx[3] = {std::max({q[0], q[16], q[19]}), std::max({q[1], q[17], q[20]}),
                          std::max({q[2], q[18], q[21]})};
    cell_of(mn, &range_[6 * t]), cell_of(mx, &range_[6 * t + 3]);
  }
  auto each_cell = [&](std::size_t t, auto&& f) {
    const int* c0 = &range_[6 * t];
    const int* c1 = c0 + 3;
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y)
        for (int x = c0[0]; x <= c1[0]; ++x) f((std::size_t(z) * dim_[1] + y) * dim_[0] + x);
  };
  for (std::size_t t = 0; t < count; ++t) each_cell(t, [&](std::size_t c) { ++first_[c + 1]; });
  for (std::size_t c = 1; c <= cells; ++c) first_[c] += first_[c - 1];
  items_.resize(first_[cells]);
  fill_.assign(first_.begin(), first_.end() - 1);
  for (std::size_t t = 0; t < count; ++t)
    each_cell(t, [&](std::size_t c) { items_[fill_[c]++] = static_cast<std::uint32_t>(t); });
  static std::atomic<std::uint64_t> builds{0};
  build_ = ++builds;
}

NearestTriangle GridSearch::nearest(const TriangleGrid& g, const float point[3], double good_enough_m,
                                    std::uint32_t hint) {
  if (grid_ != &g || build_ != g.build_) {
    grid_ = &g, build_ = g.build_;
    stamp_.assign(g.triangles(), 0);
    query_ = 0;
    // All of the last answers' state: where the next one goes decides the order they are
    // tried in, so a search must not inherit it from another grid's queries.
    std::fill(std::begin(recent_), std::end(recent_), ~0u);
    recent_next_ = 0;
  }
  if (++query_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0u), query_ = 1;
  const double p[3] = {point[0], point[1], point[2]};
  // Squared distances until the answer.
  const double enough_sq = good_enough_m * good_enough_m;
  NearestTriangle best{std::numeric_limits<double>::infinity(), 0};
  auto done = [&] { return NearestTriangle{std::sqrt(best.distance_m), best.triangle}; };
  if (hint < stamp_.size()) {
    best = {g.distance_sq(hint, p, std::numeric_limits<double>::infinity()), hint};
    if (best.distance_m <= enough_sq) return done();
    stamp_[hint] = query_;
  }
  // The last answers found by a search: a query near the previous ones is often near one of them.
  if (good_enough_m > 0.0)
    for (std::uint32_t t : recent_) {
      if (t >= stamp_.size() || stamp_[t] == query_) continue;
      stamp_[t] = query_;
      const double d = g.distance_sq(t, p, best.distance_m);
      if (d < best.distance_m) {
        best = {d, t};
        if (d <= enough_sq) return done();
      }
    }
  auto found = [&] {
    recent_[recent_next_++ % kRecent] = best.triangle;
    return done();
  };
  int c[3];
  g.cell_of(p, c);
  const int max_ring = std::max({g.dim_[0], g.dim_[1], g.dim_[2]});
  for (int r = 0; r <= max_ring; ++r) {
    // Cells of ring r are at least (r - 1) cells from the point's (clamped) cell.
    const double ring_m = double(r - 1) * g.cell_m_;
    if (r > 0 && ring_m * ring_m >= best.distance_m) break;
    const int z0 = std::max(c[2] - r, 0), z1 = std::min(c[2] + r, g.dim_[2] - 1);
    const int y0 = std::max(c[1] - r, 0), y1 = std::min(c[1] + r, g.dim_[1] - 1);
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y) {
        // Inside the ring's faces in z and y, only its two x faces are on the ring.
        const bool shell = std::abs(z - c[2]) == r || std::abs(y - c[1]) == r;
        const int x0 = std::max(c[0] - r, 0), x1 = std::min(c[0] + r, g.dim_[0] - 1);
        const int step = shell || r == 0 ? 1 : 2 * r;
        for (int x = shell ? x0 : c[0] - r; x <= x1; x += step) {
          if (x < x0) continue;
          // Distance from the point to the cell's box: no triangle part in the cell is closer.
          const int cc[3] = {x, y, z};
          double box_sq = 0.0;
          for (int k = 0; k < 3; ++k) {
            const double a = g.lo_[k] + cc[k] * g.cell_m_, b = a + g.cell_m_;
            const double d = p[k] < a ? a - p[k] : (p[k] > b ? p[k] - b : 0.0);
            box_sq += d * d;
          }
          if (box_sq >= best.distance_m) continue;
          const std::size_t cell = (std::size_t(z) * g.dim_[1] + y) * g.dim_[0] + x;
          for (std::uint32_t i = g.first_[cell]; i < g.first_[cell + 1]; ++i) {
            const std::uint32_t t = g.items_[i];
            if (stamp_[t] == query_) continue;
            stamp_[t] = query_;
            const double d = g.distance_sq(t, p, best.distance_m);
            if (d < best.distance_m) {
              best = {d, t};
              if (d <= enough_sq) return found();
            }
          }
        }
      }
  }
  return found();
}

}  // namespace gazelod::bake
