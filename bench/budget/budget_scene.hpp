// SPDX-License-Identifier: Apache-2.0
// Synthetic frame-budget scenes for bench_budget: n objects with m levels each, triangles
// halving per level. Cost per level (ms) is Funkhouser & Sequin's max(C1 tris + C2 verts,
// C3 pixels); benefit is the FrameBudget form (budget/frame_budget.hpp):
// size_px * importance * sqrt(tris / tris_finest), concave in cost except where the fill term
// binds (coarse levels of large objects), so the scenes are mostly, not perfectly, convex.
#pragma once

#include "budget/cost_model.hpp"
#include "budget/knapsack.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace gazelod::budget::bench {

struct Scene {
  MckpInstance inst;
  std::vector<double> size_px;      // per object; drifts frame to frame
  std::vector<double> base_px;      // per object: the size the drift reverts to
  std::vector<double> drift_log;    // per object: log(size_px / base_px)
  std::vector<double> importance;   // per object
  std::vector<double> tris, verts;  // per item
};

// ms per triangle / vertex / pixel: ~500 M triangles/s.
inline const CostCoefficients kSceneCoeff{0.0, 2e-6, 1e-6, 2e-7};

// Recomputes every item's cost and profit from the objects' sizes (what a frame does).
inline void update_items(Scene& s) {
  for (std::size_t k = 0; k < s.inst.subset_count(); ++k) {
    const std::uint32_t a = s.inst.subset_offsets[k], b = s.inst.subset_offsets[k + 1];
    const double finest = s.tris[b - 1];
    for (std::uint32_t j = a; j < b; ++j) {
      MckpItem& it = s.inst.items[j];
      it.cost = object_cost_s(kSceneCoeff, s.tris[j], s.verts[j], s.size_px[k]);
      it.profit = s.size_px[k] * s.importance[k] * std::sqrt(s.tris[j] / finest);
    }
  }
}

// Capacity: halfway between the coarsest and the finest frame.
inline Scene make_scene(std::size_t objects, int levels, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::lognormal_distribution<double> top_tris(std::log(20000.0), 1.0), px(std::log(3000.0), 1.2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  std::vector<MckpItem> items(static_cast<std::size_t>(levels));
  for (std::size_t k = 0; k < objects; ++k) {
    const double top = top_tris(rng);
    s.size_px.push_back(px(rng));
    s.importance.push_back(0.3 + 0.7 * u(rng));
    for (int j = 0; j < levels; ++j) {  // coarse to fine
      const double t = std::max(8.0, std::round(top / std::pow(2.0, levels - 1 - j)));
      s.tris.push_back(t);
      s.verts.push_back(std::round(t * (0.5 + 0.2 * u(rng))));
    }
    s.inst.add_subset(items);
  }
  update_items(s);
  double lo = 0, hi = 0;
  for (std::size_t k = 0; k < objects; ++k) {
    lo += s.inst.subset(k).front().cost;
    hi += s.inst.subset(k).back().cost;
  }
  s.inst.capacity = lo + 0.5 * (hi - lo);
  return s;
}

// Frame-to-frame coherence: every object's projected size changes by ~sigma per frame, as a
// mean-reverting walk in log size (x <- 0.98 x + sigma z: stationary spread ~5 sigma), so a
// long benchmark run stays near the scene it started from.
inline void drift(Scene& s, std::mt19937& rng, double sigma) {
  std::normal_distribution<double> z(0.0, sigma);
  if (s.base_px.empty()) {
    s.base_px = s.size_px;
    s.drift_log.assign(s.size_px.size(), 0.0);
  }
  for (std::size_t k = 0; k < s.size_px.size(); ++k) {
    s.drift_log[k] = 0.98 * s.drift_log[k] + z(rng);
    s.size_px[k] = s.base_px[k] * std::exp(s.drift_log[k]);
  }
  update_items(s);
}

}  // namespace gazelod::budget::bench
