// SPDX-License-Identifier: Apache-2.0
// Mason's (1999) worked instances: counterexamples 1 and 2, Figures 21, 23, 27.
#include "budget/knapsack.hpp"
#include "budget/knapsack_incremental.hpp"
#include "mckp_test_util.hpp"

#include <gtest/gtest.h>

namespace gazelod::budget {
namespace {

using test::make_instance;
using Sel = std::vector<std::uint32_t>;

// T1, counterexample 1 (Def. 2.5): p = (100, 9999), w = (1, 100), c = 100. Our MCKP needs one
// item per subset, so object 1 also gets F&S's "draw nothing" level (0/0).
MckpInstance t1() {
  return make_instance(100, {{{0, 0}, {100, 1}}, {{9999, 100}}});
}

TEST(BudgetWorked, T1FunkhouserGreedyLeavesAnObjectEmpty) {
  const MckpSolution fs = solve_funkhouser(t1());
  EXPECT_FALSE(fs.feasible);
  EXPECT_EQ(fs.choice, (Sel{1, kNoItem}));
  EXPECT_DOUBLE_EQ(fs.profit, 100);
  for (SolverKind k : {SolverKind::exact, SolverKind::mason_greedy, SolverKind::mason_full,
                       SolverKind::mason_incremental, SolverKind::mason_hierarchical}) {
    const MckpSolution s = solve(k, t1());
    EXPECT_TRUE(s.feasible) << solver_name(k);
    EXPECT_DOUBLE_EQ(s.profit, 9999) << solver_name(k);
    EXPECT_EQ(s.choice, (Sel{0, 0})) << solver_name(k);
  }
}

// T2, counterexample 2 (Def. 2.6): optimum 1900, F&S greedy 930.
MckpInstance t2() {
  return make_instance(1000, {{{10, 1}, {900, 100}, {910, 700}}, {{10, 1}, {600, 500}}, {{10, 1}, {400, 400}}});
}

TEST(BudgetWorked, T2FunkhouserReaches930) {
  const MckpSolution fs = solve_funkhouser(t2());
  EXPECT_TRUE(fs.feasible);
  EXPECT_DOUBLE_EQ(fs.profit, 930);
  EXPECT_EQ(fs.choice, (Sel{2, 0, 0}));
  const MckpSolution fsi = solve_funkhouser_incremental(t2());  // incr 2, 3, 5, decr 5
  EXPECT_DOUBLE_EQ(fsi.profit, 930);
  EXPECT_EQ(fsi.choice, (Sel{2, 0, 0}));
}

TEST(BudgetWorked, T2MasonSolversReachTheOptimum1900) {
  for (SolverKind k : {SolverKind::exact, SolverKind::mason_greedy, SolverKind::mason_full,
                       SolverKind::mason_incremental, SolverKind::mason_hierarchical}) {
    const MckpSolution s = solve(k, t2());
    EXPECT_TRUE(s.feasible) << solver_name(k);
    EXPECT_DOUBLE_EQ(s.profit, 1900) << solver_name(k);
    EXPECT_DOUBLE_EQ(s.cost, 1000) << solver_name(k);
    EXPECT_EQ(s.choice, (Sel{1, 1, 1})) << solver_name(k);
  }
  // Simplified greedy: 2, 5, 7 accepted, 3 rejected (critical; p_s - p_t = 910 - 900).
  EXPECT_DOUBLE_EQ(solve_mason_greedy(t2()).error_bound, 10);
  EXPECT_TRUE(solve_exact(t2()).proven_optimal);
}

TEST(BudgetWorked, T2IncrementalFromEveryStartState) {
  IncrementalScheduler sched;
  sched.reset(t2());
  MckpSolution out;
  int starts = 0;
  for (std::uint32_t a = 0; a < 3; ++a)
    for (std::uint32_t b = 0; b < 2; ++b)
      for (std::uint32_t c = 0; c < 2; ++c) {
        const Sel prev{a, b, c};
        sched.step(t2(), prev, {}, SolveLimits{}, out);
        EXPECT_DOUBLE_EQ(out.profit, 1900) << a << b << c;
        EXPECT_EQ(out.choice, (Sel{1, 1, 1}));
        ++starts;
      }
  EXPECT_EQ(starts, 12);
}

// T3, Fig. 21 (simplified algorithm), capacity 9: result {3/3, 5/5}, profit 8.
MckpInstance t3() {
  return make_instance(9, {{{1, 2}, {3, 3}, {4, 5}}, {{2, 1}, {3, 2}, {5, 5}, {6, 8}}});
}

TEST(BudgetWorked, T3Figure21) {
  const MckpSolution g = solve_mason_greedy(t3());
  EXPECT_DOUBLE_EQ(g.profit, 8);
  EXPECT_DOUBLE_EQ(g.cost, 8);
  EXPECT_EQ(g.choice, (Sel{1, 2}));
  EXPECT_DOUBLE_EQ(g.error_bound, 4 - 3);  // critical 4/5 against the selected 3/3
  EXPECT_DOUBLE_EQ(solve_exact(t3()).profit, 8);
  EXPECT_DOUBLE_EQ(test::brute_force(t3()).profit, 8);
}

// T4, Fig. 23 (full algorithm), capacity 10: result {7/4, 4/6}, profit 11.
MckpInstance t4() {
  return make_instance(10, {{{1, 1}, {3, 2}, {7, 4}, {8, 7}}, {{1, 2}, {3, 4}, {4, 6}, {8, 9}}});
}

TEST(BudgetWorked, T4Figure23) {
  const MckpSolution f = solve_mason_full(t4());
  EXPECT_DOUBLE_EQ(f.profit, 11);
  EXPECT_DOUBLE_EQ(f.cost, 10);
  EXPECT_EQ(f.choice, (Sel{2, 2}));
  EXPECT_DOUBLE_EQ(solve_exact(t4()).profit, 11);
  EXPECT_DOUBLE_EQ(test::brute_force(t4()).profit, 11);
}

// Ties: two identical objects, room for one upgrade (RV 2 each). The strict order (relative
// value, then the lower stable id) gives it to object 0 in every Mason solver, and the
// incremental one gets there from either start without cycling.
TEST(BudgetWorked, TiesGoToTheLowerStableId) {
  const MckpInstance inst = make_instance(3, {{{1, 1}, {3, 2}}, {{1, 1}, {3, 2}}});
  for (SolverKind k : {SolverKind::mason_greedy, SolverKind::mason_full, SolverKind::mason_incremental,
                       SolverKind::mason_hierarchical}) {
    const MckpSolution s = solve(k, inst);
    EXPECT_EQ(s.choice, (Sel{1, 0})) << solver_name(k);
    EXPECT_DOUBLE_EQ(s.profit, 4) << solver_name(k);
  }
  IncrementalScheduler sched;
  sched.reset(inst);
  MckpSolution out;
  for (const Sel& start : {Sel{0, 1}, Sel{1, 1}, Sel{0, 0}, Sel{1, 0}}) {
    sched.step(inst, start, {}, SolveLimits{}, out);
    EXPECT_FALSE(out.truncated);
    EXPECT_EQ(out.choice, (Sel{1, 0})) << start[0] << start[1];
  }
}

// T5, Fig. 27: root object with impostors 1, 2; children A (4), B (5, 6), C (3) with leaf
// children D (7), E (8). Leaves are subsets A, B, D, E; C and the root are groups.
MckpInstance t5(double capacity) {
  MckpInstance inst = make_instance(capacity, {{{4, 4}}, {{5, 5}, {9, 9}}, {{7, 7}}, {{8, 8}}});
  inst.groups.push_back({{2, 3}, {}, {{3, 3}}});           // C over D, E: impostor 3
  inst.groups.push_back({{0, 1}, {0}, {{1, 1}, {2, 2}}});  // root over A, B, C: impostors 1, 2
  return inst;
}

TEST(BudgetWorked, T5Figure27LevelsOfDetail) {
  const MckpInstance inst = t5(100);
  std::vector<std::uint32_t> order, offsets;
  cost_order(inst, order, offsets);
  HmckpTree tree;
  build_hmckp_tree(inst, order, offsets, tree);
  // Name nodes by their impostor number (= cost here) and list every valid LOD.
  std::vector<std::vector<int>> lods;
  for (const auto& lod : test::all_lods(tree)) {
    std::vector<int> names;
    std::vector<std::uint8_t> sel(tree.nodes.size(), 0);
    for (std::uint32_t n : lod) {
      names.push_back(int(test::node_item(inst, tree.nodes[n]).cost));
      sel[n] = 1;
    }
    EXPECT_TRUE(is_valid_lod(tree, sel));
    std::sort(names.begin(), names.end());
    lods.push_back(names);
  }
  std::sort(lods.begin(), lods.end());
  const std::vector<std::vector<int>> expected{{1}, {2}, {3, 4, 5}, {3, 4, 9}, {4, 5, 7, 8}, {4, 7, 8, 9}};
  EXPECT_EQ(lods, expected);  // 9 stands for impostor 6 (cost 9 keeps B's chain increasing)
  // Invalid: two selections on one path, or a leaf path with none.
  std::vector<std::uint8_t> bad(tree.nodes.size(), 0);
  EXPECT_FALSE(is_valid_lod(tree, bad));
}

TEST(BudgetWorked, T5HierarchicalSolversPickTheBestAffordableLevel) {
  // Capacity 12 affords {3,4,5} (cost 12) but not {4,5,7,8} (24): profit 12 is the optimum.
  for (SolverKind k : {SolverKind::mason_hierarchical, SolverKind::mason_incremental}) {
    const MckpSolution s = solve(k, t5(12));
    EXPECT_TRUE(s.feasible) << solver_name(k);
    EXPECT_DOUBLE_EQ(s.profit, 12) << solver_name(k);
    EXPECT_EQ(s.choice, (Sel{0, 0, kNoItem, kNoItem})) << solver_name(k);
    EXPECT_EQ(s.group_choice, (Sel{0, kNoItem})) << solver_name(k);
  }
  // Below the cheapest level (impostor 1, cost 1): infeasible.
  EXPECT_FALSE(solve_mason_hierarchical(t5(0.5)).feasible);
}

}  // namespace
}  // namespace gazelod::budget
