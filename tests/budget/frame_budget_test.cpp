// SPDX-License-Identifier: Apache-2.0
// FrameBudget (budget/frame_budget.hpp): the predicted frame time stays under the budget when
// any choice fits, no level finer than the perceptual one, the coarsest levels (reported
// infeasible) when nothing fits, and the RLS cost fit converging on synthetic frame times.
#include "budget/frame_budget.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace gazelod::budget {
namespace {

using Chains = std::vector<std::vector<lod::LodLevel>>;

lod::LodLevel level(std::uint32_t tris, std::uint32_t verts) {
  lod::LodLevel l;
  l.triangles = tris;
  l.vertices = verts;
  return l;
}

// Random scene: m levels per object, triangles halving per level, vertices 50-100 % of them.
Chains random_chains(std::mt19937& rng, std::size_t objects, std::size_t levels) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Chains chains(objects);
  for (auto& chain : chains) {
    double tris = 2000.0 + 60000.0 * u(rng);
    for (std::size_t l = 0; l < levels; ++l, tris *= 0.5) {
      const auto t = static_cast<std::uint32_t>(std::max(tris, 4.0));
      chain.push_back(level(t, static_cast<std::uint32_t>(t * (0.5 + 0.5 * u(rng)))));
    }
  }
  return chains;
}

// Independent prediction: C0 + sum over objects of C1 triangles + C2 vertices, in ms.
double predicted_by_hand(const budget::CostCoefficients& c, const Chains& chains, std::span<const std::uint8_t> lods) {
  double s = c.c0_s;
  for (std::size_t k = 0; k < chains.size(); ++k)
    s += c.c1_s_per_tri * chains[k][lods[k]].triangles + c.c2_s_per_vert * chains[k][lods[k]].vertices;
  return 1e3 * s;
}

double cost_of(const budget::CostCoefficients& c, const Chains& chains, std::size_t level_from_end) {
  std::vector<std::uint8_t> lods(chains.size());
  for (std::size_t k = 0; k < chains.size(); ++k)
    lods[k] = static_cast<std::uint8_t>(chains[k].size() - 1 - level_from_end);
  return predicted_by_hand(c, chains, lods);
}

TEST(FrameBudget, HandWorkedTwoObjects) {
  // Costs 1.0 / 0.5 / 0.25 ms per object (C1 = 1e-6 s/tri, C2 = 0). Benefit 100 sqrt(t/1000):
  // 100, 70.7, 50. Budget 1.5 ms: {0, 1} and {1, 0} (170.7) are the best affordable; the tie
  // goes to the lower stable id, so object 0 gets full detail.
  FrameBudgetOptions opt;
  opt.prior = {0.0, 1e-6, 0.0, 0.0};
  const Chains chains(2, {level(1000, 600), level(500, 300), level(250, 150)});
  FrameBudget fb(chains, 1.5 + 1e-9, opt);
  const std::vector<std::uint8_t> perceptual{0, 0};
  const std::vector<BudgetObjectView> view(2, {100.0, 1.0});
  std::vector<std::uint8_t> out(2);
  ASSERT_EQ(fb.choose(perceptual, view, out), "");
  EXPECT_FALSE(fb.infeasible());
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0, 1}));
  EXPECT_NEAR(fb.predicted_ms(), 1.5, 1e-9);
  // With room for everything, the answer is exactly the perceptual choice.
  fb.set_budget_ms(10.0);
  const std::vector<std::uint8_t> floor{1, 0};
  ASSERT_EQ(fb.choose(floor, view, out), "");
  EXPECT_FALSE(fb.infeasible());
  EXPECT_EQ(out, floor);
  EXPECT_NEAR(fb.predicted_ms(), 1.5, 1e-9);
  // Headroom: a 3 ms budget with half kept free plans exactly like the 1.5 ms budget above.
  opt.headroom = 0.5;
  FrameBudget half(chains, 3.0 + 2e-9, opt);
  ASSERT_EQ(half.choose(perceptual, view, out), "");
  EXPECT_FALSE(half.infeasible());
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0, 1}));
}

TEST(FrameBudget, PredictedTimeNeverAboveBudgetAndNeverFinerThanPerceptual) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Chains chains = random_chains(rng, 300, 5);
  const FrameBudgetOptions opt;
  const double lo = cost_of(opt.prior, chains, 0), hi = cost_of(opt.prior, chains, 4);
  FrameBudget fb(chains, lo + 0.3 * (hi - lo), opt);
  std::vector<std::uint8_t> perceptual(chains.size()), out(chains.size());
  std::vector<BudgetObjectView> view(chains.size());
  for (auto& v : view) v = {100.0 + 1e5 * u(rng) * u(rng), 0.2 + 0.8 * u(rng)};
  int frames_over_floor = 0;
  for (int frame = 0; frame < 200; ++frame) {
    // Coherent motion with occasional jumps; the budget moves too.
    for (std::size_t k = 0; k < chains.size(); ++k) {
      if (frame == 0 || u(rng) < 0.05) perceptual[k] = static_cast<std::uint8_t>(u(rng) * 5);
      view[k].size_px *= std::exp(0.02 * (u(rng) - 0.5));
    }
    if (frame % 50 == 49) fb.set_budget_ms(lo + u(rng) * (hi - lo));
    ASSERT_EQ(fb.choose(perceptual, view, out), "") << "frame " << frame;
    EXPECT_FALSE(fb.infeasible());
    EXPECT_LE(fb.predicted_ms(), fb.budget_ms() + 1e-9) << "frame " << frame;
    EXPECT_NEAR(fb.predicted_ms(), predicted_by_hand(fb.coefficients(), chains, out), 1e-9);
    bool coarser_somewhere = false;
    for (std::size_t k = 0; k < chains.size(); ++k) {
      ASSERT_GE(out[k], perceptual[k]) << "object " << k << " frame " << frame;
      ASSERT_LT(out[k], chains[k].size());
      coarser_somewhere |= out[k] > perceptual[k];
    }
    frames_over_floor += coarser_somewhere;  // the budget really binds (not a vacuous check)
  }
  EXPECT_GT(frames_over_floor, 100);
}

TEST(FrameBudget, NothingFitsGivesCoarsestAndSaysInfeasible) {
  std::mt19937 rng(5);
  const Chains chains = random_chains(rng, 20, 4);
  const FrameBudgetOptions opt;
  FrameBudget fb(chains, 0.5 * cost_of(opt.prior, chains, 0), opt);
  const std::vector<std::uint8_t> perceptual(20, 0);
  const std::vector<BudgetObjectView> view(20, {1000.0, 1.0});
  std::vector<std::uint8_t> out(20, 0);
  EXPECT_EQ(fb.choose(perceptual, view, out), "");  // chosen: infeasible is an outcome, not a refusal
  EXPECT_TRUE(fb.infeasible());
  for (std::uint8_t l : out) EXPECT_EQ(l, 3);
  EXPECT_NEAR(fb.predicted_ms(), cost_of(opt.prior, chains, 0), 1e-9);
  EXPECT_GT(fb.predicted_ms(), fb.budget_ms());
  // Once the budget allows it again, a feasible answer returns.
  fb.set_budget_ms(2.0 * cost_of(opt.prior, chains, 0));
  EXPECT_EQ(fb.choose(perceptual, view, out), "");
  EXPECT_FALSE(fb.infeasible());
}

TEST(FrameBudget, CalibrationConvergesOnSyntheticFrameTimes) {
  // The renderer really costs 1 ms + 25 ns/triangle + 12 ns/vertex; the prior is off by 2-3x.
  const budget::CostCoefficients truth{1e-3, 2.5e-8, 1.2e-8, 0.0};
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.005);  // 0.5 % timing noise
  const Chains chains = random_chains(rng, 100, 5);
  const FrameBudgetOptions opt;  // prior {0, 1e-8, 5e-9, 0}
  const double lo = cost_of(truth, chains, 0), hi = cost_of(truth, chains, 4);
  const double budget = lo + 0.5 * (hi - lo);
  FrameBudget fb(chains, budget, opt);
  std::vector<std::uint8_t> perceptual(chains.size()), out(chains.size());
  std::vector<BudgetObjectView> view(chains.size(), {5000.0, 1.0});
  auto frame = [&](double* rel_error, double* measured_ms) {
    for (auto& p : perceptual) p = u(rng) < 0.5 ? 0 : static_cast<std::uint8_t>(u(rng) * 5);
    ASSERT_EQ(fb.choose(perceptual, view, out), "");
    const double measured = predicted_by_hand(truth, chains, out) * (1.0 + noise(rng));
    *rel_error = std::fabs(fb.predicted_ms() - measured) / measured;
    *measured_ms = measured;
    ASSERT_TRUE(fb.observe(measured));
  };
  double err = 0, meas = 0;
  frame(&err, &meas);
  EXPECT_GT(err, 0.3);  // the prior predicts badly
  for (int f = 0; f < 300; ++f) frame(&err, &meas);
  double sum_err = 0;
  int over = 0;
  for (int f = 0; f < 100; ++f) {
    frame(&err, &meas);
    sum_err += err;
    over += meas > budget * 1.02;  // beyond the timing noise
  }
  EXPECT_LT(sum_err / 100, 0.02);
  EXPECT_LE(over, 2);
  // (The split between C0 and the per-triangle terms is not checked: in closed loop the solver
  // holds the load near the budget, so the data barely separates them; the prediction at the
  // operating point is what the budget needs.)
  // Garbage measurements are refused.
  EXPECT_FALSE(fb.observe(std::nan("")));
  EXPECT_FALSE(fb.observe(-1.0));
}

TEST(FrameBudget, BadInputIsNamed) {
  const Chains one(1, {level(10, 10)});
  EXPECT_THROW(FrameBudget(one, 0.0), std::invalid_argument);
  EXPECT_THROW(FrameBudget(one, std::nan("")), std::invalid_argument);
  Chains empty(2, {level(10, 10)});
  empty[1].clear();
  try {
    FrameBudget fb(empty, 5.0);
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("object 1"), std::string::npos) << e.what();
  }
  FrameBudget fb(Chains(2, {level(10, 10), level(5, 5)}), 5.0);
  std::vector<std::uint8_t> out(2, 7);
  const std::vector<BudgetObjectView> view(2);
  // Per frame: refused with the reason, never thrown, nothing written.
  std::string why;
  EXPECT_NO_THROW(why = fb.choose(std::vector<std::uint8_t>{0, 2}, view, out));
  EXPECT_NE(why.find("perceptual_lod[1] = 2"), std::string::npos) << why;
  EXPECT_NO_THROW(why = fb.choose(std::vector<std::uint8_t>{0}, view, out));
  EXPECT_NE(why.find("needs 2 objects"), std::string::npos) << why;
  EXPECT_EQ(out, (std::vector<std::uint8_t>{7, 7}));
  EXPECT_FALSE(fb.observe(1.0));  // no frame chosen yet
}

TEST(FrameBudget, BadOptionsAreRefusedAtConstructionNotReplaced) {
  const Chains one(1, {level(10, 10)});
  EXPECT_EQ(budget::validate_frame_budget_options(FrameBudgetOptions{}), "");
  const auto refused = [&](const FrameBudgetOptions& o, const std::string& field) {
    const std::string why = budget::validate_frame_budget_options(o);
    EXPECT_EQ(why.rfind(field + " must be", 0), 0u) << why;
    try {
      FrameBudget fb(one, 5.0, o);
      ADD_FAILURE() << field << ": no throw";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  FrameBudgetOptions o;
  o.headroom = 0.95;  // was clamped to 0.9 each frame
  refused(o, "headroom");
  o.headroom = std::nan("");  // was read as 0
  refused(o, "headroom");
  o = {};
  o.forgetting = 0.2;  // was raised to 0.5
  refused(o, "forgetting");
  o = {};
  o.prior.c1_s_per_tri = -1e-8;
  refused(o, "prior.c1_s_per_tri");
  o = {};
  o.solve_time_limit = std::chrono::nanoseconds(0);
  refused(o, "solve_time_limit");
}

}  // namespace
}  // namespace gazelod::budget
