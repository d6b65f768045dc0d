// SPDX-License-Identifier: Apache-2.0
#include "budget/frame_budget.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace gazelod::budget {
namespace {

double checked_budget(double budget_ms) {
  if (!std::isfinite(budget_ms) || budget_ms <= 0.0)
    throw std::invalid_argument("frame budget: budget_ms must be a positive number of ms, got " +
                                std::to_string(budget_ms));
  return budget_ms;
}

double clean(double v, double lo, double hi, double fallback) {
  return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
}

const FrameBudgetOptions& checked_options(const FrameBudgetOptions& options) {
  if (std::string e = validate_frame_budget_options(options); !e.empty())
    throw std::invalid_argument("frame budget: " + e);
  return options;
}

}  // namespace

std::string validate_frame_budget_options(const FrameBudgetOptions& o) {
  const CostCoefficients& p = o.prior;
  if (!std::isfinite(p.c0_s)) return "prior.c0_s must be finite, got " + std::to_string(p.c0_s);
  const std::pair<const char*, double> per_primitive[] = {{"prior.c1_s_per_tri", p.c1_s_per_tri},
                                                          {"prior.c2_s_per_vert", p.c2_s_per_vert},
                                                          {"prior.c3_s_per_px", p.c3_s_per_px}};
  for (const auto& [name, v] : per_primitive)
    if (!(std::isfinite(v) && v >= 0.0))
      return std::string(name) + " must be finite and >= 0, got " + std::to_string(v);
  if (!(o.forgetting >= 0.5 && o.forgetting <= 1.0))
    return "forgetting must be in [0.5, 1], got " + std::to_string(o.forgetting);
  if (!(o.headroom >= 0.0 && o.headroom <= 0.9))
    return "headroom must be in [0, 0.9], got " + std::to_string(o.headroom);
  if (o.solve_time_limit && o.solve_time_limit->count() <= 0)
    return "solve_time_limit must be > 0 when set, got " + std::to_string(o.solve_time_limit->count()) + " ns";
  return {};
}

FrameBudget::FrameBudget(std::vector<std::vector<lod::LodLevel>> chains, double budget_ms,
                         const FrameBudgetOptions& options, std::size_t cluster_meshes)
    : chains_(std::move(chains)),
      budget_ms_(checked_budget(budget_ms)),
      options_(checked_options(options)),
      rls_(options.prior, options.forgetting) {
  for (std::size_t k = 0; k < chains_.size(); ++k) {
    const std::size_t m = chains_[k].size();
    if (m == 0 || m > 255)
      throw std::invalid_argument("frame budget: object " + std::to_string(k) + " has " + std::to_string(m) +
                                  " levels (1 to 255 allowed)");
  }
  level_first_.reserve(chains_.size() + 1);
  for (const auto& chain : chains_) {
    level_first_.push_back(static_cast<std::uint32_t>(level_tris_.size()));
    for (const lod::LodLevel& l : chain) {
      level_tris_.push_back(l.triangles);
      level_verts_.push_back(l.vertices);
      level_sqrt_.push_back(std::sqrt(std::max<double>(l.triangles, 1.0)));
    }
  }
  level_first_.push_back(static_cast<std::uint32_t>(level_tris_.size()));
  // Structure: subset k holds object k's levels coarsest first, so that items are in cost
  // order for ordinary chains (the solver's fast path) and index 0 is the cheapest.
  std::vector<budget::MckpItem> items;
  for (std::size_t k = 0; k < chains_.size(); ++k) {
    const std::size_t m = chains_[k].size();
    items.assign(m, budget::MckpItem{});
    for (std::size_t j = 0; j < m; ++j) {
      items[j].cost = level_cost_ms(ms_coefficients(), level_first_[k] + (m - 1 - j), 0.0);
      items[j].profit = static_cast<double>(j + 1);
    }
    frame_.add_subset(items);
  }
  // Cluster mesh c: subset object_count + c, its steps coarsest first (costs written per frame).
  items.assign(kClusterSteps, budget::MckpItem{});
  for (std::size_t j = 0; j < kClusterSteps; ++j) items[j].profit = static_cast<double>(j + 1);
  for (std::size_t c = 0; c < cluster_meshes; ++c) frame_.add_subset(items);
  frame_.capacity = budget_ms_;
  budget::IncrementalScheduler::Options so;
  so.drop_ip_dominated = false;  // profits change every frame: keep every level
  scheduler_.reset(frame_, so);
  prev_choice_.assign(chains_.size() + cluster_meshes, 0);
  cluster_pred_tris_.assign(cluster_meshes, 0.0);
  cluster_fit_tris_.assign(cluster_meshes, 0.0);
  cluster_pixels_.assign(cluster_meshes, 0.0);
  last_lod_.assign(chains_.size(), 0);
  last_pixels_.assign(chains_.size(), 0.0);
}

void FrameBudget::set_budget_ms(double budget_ms) {
  budget_ms_ = checked_budget(budget_ms);
}

FrameBudget::MsCoefficients FrameBudget::ms_coefficients() const {
  const budget::CostCoefficients& c = rls_.coefficients();
  return {1e3 * c.c1_s_per_tri, 1e3 * c.c2_s_per_vert, 1e3 * c.c3_s_per_px};
}

std::string FrameBudget::choose(std::span<const std::uint8_t> perceptual_lod, std::span<const BudgetObjectView> view,
                                std::span<std::uint8_t> out_lod) {
  return choose(perceptual_lod, view, out_lod, {}, {});
}

// Mesh c's steps as subset object_count + c, coarsest first: cost under the fit, benefit
// size_px * importance * sqrt(triangles_k / triangles_0) capped at 1 (as an object's).
void FrameBudget::write_cluster_items(const MsCoefficients& coeff, std::span<const BudgetClusterView> clusters) {
  const std::size_t n = chains_.size();
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const BudgetClusterView& v = clusters[c];
    const double px = clean(v.size_px, 0.0, 1e12, 0.0);
    const double importance = clean(v.importance, 0.0, 1.0, 0.0);
    const double root0 = std::sqrt(std::max(clean(v.triangles[0], 0.0, 1e15, 0.0), 1.0));
    const double value = px * importance / root0;
    cluster_pixels_[c] = px;
    budget::MckpItem* items = frame_.items.data() + frame_.subset_offsets[n + c];
    for (std::size_t j = 0; j < kClusterSteps; ++j) {
      const std::size_t step = kClusterSteps - 1 - j;
      const double tris = clean(v.triangles[step], 0.0, 1e15, 0.0);
      items[j].profit = value * std::min(std::sqrt(std::max(tris, 1.0)), root0);
      items[j].cost = fs_cost_ms(coeff, tris, kClusterVerticesPerTriangle * tris, px);
    }
  }
}

std::string FrameBudget::choose(std::span<const std::uint8_t> perceptual_lod, std::span<const BudgetObjectView> view,
                                std::span<std::uint8_t> out_lod, std::span<const BudgetClusterView> clusters,
                                std::span<std::uint8_t> out_step) {
  const std::size_t n = chains_.size();
  if (clusters.size() != cluster_pred_tris_.size() || out_step.size() != cluster_pred_tris_.size())
    return "frame budget: choose() needs " + std::to_string(cluster_pred_tris_.size()) +
           " cluster meshes in both spans, got " + std::to_string(clusters.size()) + " views and " +
           std::to_string(out_step.size()) + " outputs";
  if (perceptual_lod.size() != n || view.size() != n || out_lod.size() != n)
    return "frame budget: choose() needs " + std::to_string(n) + " objects in every span, got " +
           std::to_string(perceptual_lod.size()) + " perceptual levels, " + std::to_string(view.size()) + " views, " +
           std::to_string(out_lod.size()) + " outputs";
  for (std::size_t k = 0; k < n; ++k)
    if (perceptual_lod[k] >= level_first_[k + 1] - level_first_[k])
      return "frame budget: perceptual_lod[" + std::to_string(k) + "] = " + std::to_string(perceptual_lod[k]) +
             " but object " + std::to_string(k) + " has " + std::to_string(chains_[k].size()) + " levels";

  const double overhead_ms = 1e3 * rls_.coefficients().c0_s;
  // headroom passed validate_frame_budget_options at construction: in [0, 0.9].
  const double capacity = budget_ms_ * (1.0 - options_.headroom) - overhead_ms;
  frame_.capacity = capacity;
  // A level finer than the perceptual one buys nothing visible: it keeps the perceptual level's
  // benefit and costs more than the whole budget, so no solver can afford it (it must stay a
  // finite, modest number: the solver keeps running sums).
  const double unaffordable_ms = std::max(capacity, 0.0) + 1.0;
  const MsCoefficients coeff = ms_coefficients();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t first = level_first_[k];
    const std::size_t m = level_first_[k + 1] - first;
    const std::size_t p = perceptual_lod[k];
    const double px = clean(view[k].size_px, 0.0, 1e12, 0.0);
    const double importance = clean(view[k].importance, 0.0, 1.0, 0.0);
    const double* sqrt_tris = level_sqrt_.data() + first;
    const double value = px * importance / sqrt_tris[p];  // benefit per sqrt(triangle)
    last_pixels_[k] = px;
    budget::MckpItem* items = frame_.items.data() + frame_.subset_offsets[k];
    double perceptual_profit = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t level = m - 1 - j;
      if (level >= p) {
        // sqrt(tris_L / tris_P), capped at 1 (a coarser level with more triangles gains nothing)
        items[j].profit = value * std::min(sqrt_tris[level], sqrt_tris[p]);
        items[j].cost = level_cost_ms(coeff, first + level, px);
        perceptual_profit = items[j].profit;  // the last one written is level p
      } else {
        items[j].profit = perceptual_profit;
        items[j].cost = unaffordable_ms;
      }
    }
    // Start from last frame's level, but never above this frame's perceptual ceiling.
    prev_choice_[k] = std::min<std::uint32_t>(prev_choice_[k], static_cast<std::uint32_t>(m - 1 - p));
  }
  write_cluster_items(coeff, clusters);

  budget::SolveLimits limits;
  limits.max_moves = options_.max_moves;
  limits.wall_clock_limit = options_.solve_time_limit;  // nullopt unless asked: deterministic
  scheduler_.step(frame_, prev_choice_, {}, limits, solution_);
  truncated_ = solution_.truncated;
  infeasible_ = !solution_.feasible;
  double cost_ms = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t m = chains_[k].size();
    std::uint32_t j = solution_.choice[k];
    const std::uint32_t ceiling = static_cast<std::uint32_t>(m - 1 - perceptual_lod[k]);
    if (infeasible_ || j == budget::kNoItem) j = 0;  // coarsest: the cheapest frame there is
    j = std::min(j, ceiling);                        // belt and braces: never finer than needed
    prev_choice_[k] = j;
    const auto level = static_cast<std::uint8_t>(m - 1 - j);
    out_lod[k] = level;
    last_lod_[k] = level;
    cost_ms += level_cost_ms(coeff, level_first_[k] + level, last_pixels_[k]);
  }
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    std::uint32_t j = solution_.choice[n + c];
    if (infeasible_ || j == budget::kNoItem) j = 0;  // the coarsest step
    prev_choice_[n + c] = j;
    const std::size_t step = kClusterSteps - 1 - j;
    out_step[c] = static_cast<std::uint8_t>(step);
    const double tris = clean(clusters[c].triangles[step], 0.0, 1e15, 0.0);
    cluster_pred_tris_[c] = cluster_fit_tris_[c] = tris;
    cost_ms += fs_cost_ms(coeff, tris, kClusterVerticesPerTriangle * tris, cluster_pixels_[c]);
  }
  predicted_ms_ = overhead_ms + cost_ms;
  have_frame_ = true;
  return {};
}

bool FrameBudget::observe(double measured_frame_ms) {
  if (!have_frame_ || !std::isfinite(measured_frame_ms) || measured_frame_ms < 0.0) return false;
  budget::FrameCostFeatures features = rls_.begin_frame();
  const budget::CostCoefficients c = rls_.coefficients();
  for (std::size_t k = 0; k < chains_.size(); ++k) {
    const std::size_t i = level_first_[k] + last_lod_[k];
    budget::add_object(c, level_tris_[i], level_verts_[i], last_pixels_[k], features);
  }
  for (std::size_t m = 0; m < cluster_fit_tris_.size(); ++m) {
    const double tris = cluster_fit_tris_[m];
    budget::add_object(c, tris, kClusterVerticesPerTriangle * tris, cluster_pixels_[m], features);
  }
  return rls_.update(features, measured_frame_ms * 1e-3);
}

}  // namespace gazelod::budget

namespace gazelod::budget {

bool FrameBudget::record_cluster_triangles(std::span<const double> drawn_triangles) {
  if (drawn_triangles.size() != cluster_fit_tris_.size()) return false;
  for (std::size_t c = 0; c < drawn_triangles.size(); ++c)
    cluster_fit_tris_[c] = clean(drawn_triangles[c], 0.0, 1e15, 0.0);
  return true;
}

}  // namespace gazelod::budget
