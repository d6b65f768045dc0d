// SPDX-License-Identifier: Apache-2.0
// The offline optimum (see offline_bound.hpp): a shortest path per object over (frame, level),
// all objects advanced frame by frame so that the frame-major inputs are read in order.
#include "apps/gazelod/run/offline_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gazelod::cli {
namespace {

constexpr double kInfeasible = std::numeric_limits<double>::infinity();

std::string check_input(const OfflineBoundInput& in) {
  const std::size_t frames = in.suppressed.size();
  if (in.chains == nullptr || in.chains->size() < in.objects) return "the objects' levels are missing";
  if (in.ceiling.size() != frames * in.objects || in.in_view.size() != frames * in.objects)
    return "the frames' levels do not match frames x objects";
  if (!in.oracle.empty() && in.oracle.size() != frames * in.objects)
    return "the oracle's levels do not match frames x objects";
  if (frames == 0 || in.objects == 0) return "no object-frames";
  return {};
}

}  // namespace

OfflinePoint offline_optimum(const OfflineBoundInput& in, double price_triangles) {
  OfflinePoint out;
  if (std::string err = check_input(in); !err.empty()) {
    out.reason = err;
    return out;
  }
  if (!(std::isfinite(price_triangles) && price_triangles >= 0.0)) {
    out.reason = "the price per switch must be finite and >= 0";
    return out;
  }
  const std::size_t n = in.objects, frames = in.suppressed.size();
  const std::vector<std::vector<lod::LodLevel>>& chains = *in.chains;
  // Each object's levels at a fixed stride (the longest chain's), with its own count.
  std::size_t stride = 1;
  for (std::size_t i = 0; i < n; ++i) stride = std::max(stride, chains[i].size());
  std::vector<double> cost(n * stride, 0.0);
  std::vector<std::uint64_t> tri(n * stride, 0);
  std::vector<std::int64_t> sw(n * stride, 0), deg(n * stride, 0);
  const bool count_degraded = !in.oracle.empty();

  for (std::size_t k = 0; k < frames; ++k) {
    const bool suppressed = in.suppressed[k] != 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::vector<lod::LodLevel>& chain = chains[i];
      const std::size_t m = std::max<std::size_t>(chain.size(), 1);
      const std::size_t base = i * stride;
      const bool view = in.in_view[k * n + i] != 0;
      const std::size_t ceiling = std::min<std::size_t>(in.ceiling[k * n + i], m - 1);
      if (k > 0) {
        // Switch from the cheapest level of the previous frame (lowest level on a tie), or stay.
        std::size_t best = 0;
        for (std::size_t l = 1; l < m; ++l)
          if (cost[base + l] < cost[base + best]) best = l;
        const bool counted = view && !suppressed;
        const double via = cost[base + best] + (counted ? price_triangles : 0.0);
        const std::uint64_t via_tri = tri[base + best];
        const std::int64_t via_sw = sw[base + best] + (counted ? 1 : 0), via_deg = deg[base + best];
        for (std::size_t l = 0; l < m; ++l)
          if (l != best && via < cost[base + l])
            cost[base + l] = via, tri[base + l] = via_tri, sw[base + l] = via_sw, deg[base + l] = via_deg;
      }
      if (!view) continue;  // out of view: no triangles counted, any level allowed
      const std::size_t truth = count_degraded ? in.oracle[k * n + i] : m;
      for (std::size_t l = 0; l < m; ++l) {
        if (l > ceiling) {
          cost[base + l] = kInfeasible;
          continue;
        }
        const std::uint32_t t = chain.empty() ? 0 : chain[l].triangles;
        cost[base + l] += t;
        tri[base + l] += t;
        deg[base + l] += (!suppressed && l > truth) ? 1 : 0;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t m = std::max<std::size_t>(chains[i].size(), 1), base = i * stride;
    std::size_t best = 0;  // level 0 is never infeasible, so best is finite
    for (std::size_t l = 1; l < m; ++l)
      if (cost[base + l] < cost[base + best]) best = l;
    out.triangles += tri[base + best];
    out.switches += sw[base + best];
    out.degraded += deg[base + best];
  }
  out.available = true;
  out.price_triangles = price_triangles;
  return out;
}

OfflinePoint offline_bound(const OfflineBoundInput& in, std::int64_t max_switches) {
  const std::int64_t budget = std::max<std::int64_t>(max_switches, 0);
  // Every price tried gives a lower bound on the exact optimum (Lagrangian duality): a sequence
  // with at most `budget` switches costs at least T(p) + p (S(p) - budget) triangles.
  double lower = 0.0;
  const auto solve = [&](double price) {
    OfflinePoint p = offline_optimum(in, price);
    if (p.available)
      lower = std::max(lower, static_cast<double>(p.triangles) + price * static_cast<double>(p.switches - budget));
    return p;
  };
  OfflinePoint fit = solve(0.0);
  if (fit.available && fit.switches > budget) {
    // A price that fits the budget: start at the mean full-detail object and double. Above the
    // run's whole triangle count no switch pays, so this ends.
    double mean_full = 0.0;
    for (std::size_t i = 0; i < in.objects; ++i)
      if (!(*in.chains)[i].empty()) mean_full += (*in.chains)[i].front().triangles;
    double lo = 0.0, hi = std::max(1.0, mean_full / static_cast<double>(in.objects));
    fit = solve(hi);
    for (int doubling = 0; fit.switches > budget && doubling < 80; ++doubling) {
      lo = hi;
      hi *= 2.0;
      fit = solve(hi);
    }
    // Bisect (geometrically once lo > 0) for the lowest price that still fits: the most
    // switches within the budget, and so the fewest triangles among the hull's corners.
    for (int step = 0; step < 20; ++step) {  // the bracket to 1e-6 of its width: ample for a count
      const double mid = lo > 0.0 ? std::sqrt(lo * hi) : hi / 2.0;
      OfflinePoint p = solve(mid);
      if (p.switches <= budget)
        hi = mid, fit = p;
      else
        lo = mid;
    }
  }
  if (fit.available) fit.lower_triangles = std::min(lower, static_cast<double>(fit.triangles));
  return fit;
}

}  // namespace gazelod::cli
