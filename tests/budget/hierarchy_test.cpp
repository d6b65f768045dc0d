// SPDX-License-Identifier: Apache-2.0
// The hierarchical MCKP (Mason 1999 Ch. 4, 6, 7) against brute force over every valid level of
// detail of random hierarchies built to satisfy hierarchical convexity.
#include "budget/knapsack.hpp"
#include "budget/knapsack_incremental.hpp"
#include "mckp_test_util.hpp"

#include <gtest/gtest.h>

namespace gazelod::budget {
namespace {

struct HOpt {
  bool feasible = false;
  double profit = 0;
};

HOpt brute_force_lods(const MckpInstance& inst) {
  std::vector<std::uint32_t> order, offsets;
  cost_order(inst, order, offsets);
  HmckpTree t;
  build_hmckp_tree(inst, order, offsets, t);
  HOpt best;
  for (const auto& lod : test::all_lods(t)) {
    double p = 0, w = 0;
    for (std::uint32_t n : lod) {
      p += test::node_item(inst, t.nodes[n]).profit;
      w += test::node_item(inst, t.nodes[n]).cost;
    }
    if (w <= inst.capacity && (!best.feasible || p > best.profit)) best = {true, p};
  }
  return best;
}

TEST(BudgetHierarchy, CheckHierarchyNamesTheProblem) {
  MckpInstance inst = test::make_instance(1, {{{1, 1}}, {{1, 1}}});
  inst.groups.push_back({{0, 1}, {}, {}});
  inst.groups.push_back({{1}, {}, {}});
  EXPECT_EQ(check_hierarchy(inst), "groups[1].subsets[0]: subset 1 is already in groups[0]");
  inst.groups[1] = {{}, {0}, {}};
  inst.groups[0].groups.push_back(1);
  EXPECT_NE(check_hierarchy(inst).find("cycle"), std::string::npos);
  inst.groups[0] = {{0, 1}, {}, {}};
  inst.groups[1] = {{}, {7}, {}};
  EXPECT_EQ(check_hierarchy(inst), "groups[1].groups[0]: no group 7");
}

TEST(BudgetHierarchy, GreedyHalfOptimalAndWithinBoundOnConvexHierarchies) {
  std::mt19937 rng(2024);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const MckpInstance inst = test::random_hierarchical(rng);
    ASSERT_EQ(check_hierarchy(inst), "");
    const HOpt opt = brute_force_lods(inst);
    if (!opt.feasible) continue;
    for (SolverKind k : {SolverKind::mason_hierarchical, SolverKind::mason_incremental}) {
      const MckpSolution s = solve(k, inst);
      ASSERT_TRUE(s.feasible) << solver_name(k) << " trial " << trial;
      MckpSolution copy = s;
      evaluate(inst, copy);  // valid LOD: every leaf represented exactly once
      EXPECT_TRUE(copy.feasible) << solver_name(k) << " trial " << trial;
      EXPECT_NEAR(copy.profit, s.profit, 1e-9);
      EXPECT_LE(s.profit, opt.profit + 1e-9);
      EXPECT_GE(s.profit, 0.5 * opt.profit - 1e-9) << solver_name(k) << " trial " << trial;
      EXPECT_LE(opt.profit - s.profit, s.error_bound + 1e-9) << solver_name(k) << " trial " << trial;
    }
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace gazelod::budget
