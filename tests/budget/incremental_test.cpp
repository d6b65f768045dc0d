// SPDX-License-Identifier: Apache-2.0
// Mason's incremental algorithm (1999 Fig. 41, sec. 7.2): from any start state it reaches the
// greedy answer under convexity; every intermediate state is a valid level of detail; time
// truncation still yields a complete, affordable selection; a frame allocates nothing.
#include "budget/knapsack.hpp"
#include "budget/knapsack_incremental.hpp"
#include "mckp_test_util.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

// The replacement new/delete pair is malloc/free on both sides; GCC cannot see that.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
// Counts heap allocations while `g_count_allocations` is set (replaces global new).
static std::atomic<bool> g_count_allocations{false};
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  if (g_count_allocations) ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (g_count_allocations) ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n) {
  return operator new(n);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept {
  return operator new(n, t);
}
// Every form of delete pairs with one of the mallocs above (std::stable_sort, for one, uses the
// nothrow new: replacing only some forms mismatches under AddressSanitizer).
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace gazelod::budget {
namespace {

std::vector<std::uint32_t> random_choice(std::mt19937& rng, const MckpInstance& inst) {
  std::vector<std::uint32_t> c(inst.subset_count());
  for (std::size_t k = 0; k < c.size(); ++k)
    c[k] = std::uniform_int_distribution<std::uint32_t>(0, inst.subset_size(k) - 1)(rng);
  return c;
}

TEST(BudgetIncremental, EqualsGreedyFromAnyStartUnderConvexity) {
  std::mt19937 rng(5);
  IncrementalScheduler sched;
  MckpSolution out;
  int compared = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const MckpInstance inst = test::random_convex(rng);
    const MckpSolution greedy = solve_mason_greedy(inst, /*fill_after_critical=*/false);
    IncrementalScheduler::Options opt;
    opt.drop_ip_dominated = true;
    sched.reset(inst, opt);
    for (int start = 0; start < 6; ++start) {
      const auto prev = random_choice(rng, inst);
      sched.step(inst, prev, {}, SolveLimits{}, out);
      EXPECT_FALSE(out.truncated);
      EXPECT_EQ(out.choice, greedy.choice) << "trial " << trial << " start " << start;
      EXPECT_NEAR(out.profit, greedy.profit, 1e-9);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 3000);
}

// The frame-budget use: one scheduler over many frames whose profits drift (items given in
// cost order, nothing dropped: the flat fast path with its key band). Every frame must still
// equal the greedy answer computed from scratch.
TEST(BudgetIncremental, CoherentFramesEqualGreedyEveryFrame) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> z(0.0, 0.03);
  MckpInstance inst;
  std::vector<double> scale;
  for (int k = 0; k < 300; ++k) {
    std::vector<MckpItem> items;
    double w = 1 + u(rng), p = 1, slope = 1 + 3 * u(rng);
    for (int j = 0; j < 5; ++j) {
      items.push_back({p, w});
      const double dw = 0.5 + 2 * u(rng);
      w += dw;
      p += slope * dw;
      slope *= 0.3 + 0.6 * u(rng);
    }
    inst.add_subset(items);
    scale.push_back(1.0);
  }
  const std::vector<MckpItem> base = inst.items;
  inst.capacity = lowest_cost(inst) * 2.5;
  IncrementalScheduler sched;
  sched.reset(inst);
  MckpSolution prev, cur;
  int frames = 0, changed = 0;
  for (int f = 0; f < 120; ++f) {
    for (std::size_t k = 0; k < inst.subset_count(); ++k) {
      scale[k] *= std::exp(z(rng));  // concave chains stay concave under a positive scale
      for (std::uint32_t j = inst.subset_offsets[k]; j < inst.subset_offsets[k + 1]; ++j)
        inst.items[j].profit = base[j].profit * scale[k];
    }
    if (f == 60) inst.capacity *= 1.1;  // a budget change mid-run
    sched.step(inst, prev.choice, {}, SolveLimits{}, cur);
    const MckpSolution greedy = solve_mason_greedy(inst, /*fill_after_critical=*/false);
    ASSERT_FALSE(cur.truncated);
    ASSERT_EQ(cur.choice, greedy.choice) << "frame " << f;
    EXPECT_NEAR(cur.profit, greedy.profit, 1e-9 * greedy.profit);
    EXPECT_LE(cur.cost, inst.capacity);
    changed += f > 0 && cur.choice != prev.choice;
    ++frames;
    std::swap(prev, cur);
  }
  EXPECT_EQ(frames, 120);
  EXPECT_GT(changed, 60);  // the answer really moves from frame to frame
}

// A fill-bound object: every level costs the same, the first two are identical. The step
// between identical levels must not block the free gains behind it (it ranks as free), and a
// previous choice maps to its own level, so from any start the object ends at its best level,
// as the greedy answer (which drops the dominated levels first) has it.
TEST(BudgetIncremental, IdenticalLevelDoesNotBlockFreeGains) {
  const MckpInstance inst = test::make_instance(7, {{{5, 2}, {5, 2}, {7, 2}, {9, 2}}, {{1, 1}, {4, 3}, {6, 6}}});
  const MckpSolution greedy = solve_mason_greedy(inst, false);
  ASSERT_EQ(greedy.choice, (std::vector<std::uint32_t>{3, 1}));
  IncrementalScheduler sched;
  sched.reset(inst);  // every level kept, as in the frame-budget use
  MckpSolution out;
  for (std::uint32_t a = 0; a < 4; ++a)
    for (std::uint32_t b = 0; b < 3; ++b) {
      sched.step(inst, std::vector<std::uint32_t>{a, b}, {}, SolveLimits{}, out);
      EXPECT_EQ(out.choice, greedy.choice) << a << b;
    }
}

TEST(BudgetIncremental, HierarchicalEqualsGreedyFromEveryValidStart) {
  std::mt19937 rng(11);
  IncrementalScheduler sched;
  MckpSolution out;
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const MckpInstance inst = test::random_hierarchical(rng);
    const MckpSolution greedy = solve_mason_hierarchical(inst, /*fill_after_critical=*/false);
    sched.reset(inst);
    for (const auto& lod : test::all_lods(sched.tree())) {
      // Express the start LOD as an answer (the API's input), then step.
      MckpSolution start;
      start.choice.assign(inst.subset_count(), kNoItem);
      start.group_choice.assign(inst.groups.size(), kNoItem);
      for (std::uint32_t n : lod) {
        const HmckpNode& nd = sched.tree().nodes[n];
        (nd.subset != kNoItem ? start.choice[nd.subset] : start.group_choice[nd.group]) = nd.index;
      }
      sched.step(inst, start.choice, start.group_choice, SolveLimits{}, out);
      EXPECT_EQ(out.choice, greedy.choice) << "trial " << trial;
      EXPECT_EQ(out.group_choice, greedy.group_choice) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 400);
}

struct Watch {
  long calls = 0;
  long invalid = 0;
};

TEST(BudgetIncremental, EveryIntermediateStateIsAValidLod) {
  std::mt19937 rng(17);
  IncrementalScheduler sched;
  Watch watch;
  sched.set_observer(
      [](void* ctx, const IncrementalScheduler& s) {
        auto* w = static_cast<Watch*>(ctx);
        ++w->calls;
        w->invalid += !is_valid_lod(s.tree(), s.selected());
      },
      &watch);
  MckpSolution out;
  for (int trial = 0; trial < 300; ++trial) {
    const MckpInstance inst = trial % 2 ? test::random_hierarchical(rng) : test::random_general(rng);
    sched.reset(inst);
    sched.step(inst, trial % 2 ? std::vector<std::uint32_t>{} : random_choice(rng, inst), {}, SolveLimits{}, out);
  }
  EXPECT_GT(watch.calls, 1000);
  EXPECT_EQ(watch.invalid, 0);
}

TEST(BudgetIncremental, TruncatedFrameIsStillCompleteAndAffordable) {
  std::mt19937 rng(3);
  MckpInstance inst;
  for (int k = 0; k < 2000; ++k) {
    std::vector<MckpItem> items;
    double w = 1, p = 1, slope = 2 + std::uniform_real_distribution<double>(0, 1)(rng);
    for (int j = 0; j < 6; ++j) {
      items.push_back({p, w});
      w += 1 + j;
      p += slope * (1 + j);
      slope *= 0.6;
    }
    inst.add_subset(items);
  }
  inst.capacity = lowest_cost(inst) * 3;
  IncrementalScheduler sched;
  sched.reset(inst);
  MckpSolution out;
  const SolveLimits no_time{.wall_clock_limit = std::chrono::nanoseconds(0)};  // the outer option
  sched.step(inst, {}, {}, no_time, out);                                      // stop at the first check
  EXPECT_TRUE(out.truncated);
  EXPECT_TRUE(out.feasible);
  EXPECT_LE(out.cost, inst.capacity);
  for (std::uint32_t c : out.choice) EXPECT_NE(c, kNoItem);
  // The next frames continue from there and converge (the skipped work is repaid).
  MckpSolution next;
  for (int f = 0; f < 200 && (f == 0 || next.truncated); ++f) {
    sched.step(inst, out.choice, {}, no_time, next);
    out = next;
  }
  sched.step(inst, out.choice, {}, SolveLimits{}, next);
  EXPECT_FALSE(next.truncated);
  EXPECT_NEAR(next.profit, solve_mason_greedy(inst, false).profit, 1e-6 * next.profit);
}

TEST(BudgetIncremental, LowestLevelOverCapacityIsReportedInfeasible) {
  const MckpInstance inst = test::make_instance(1, {{{1, 2}, {2, 3}}, {{1, 1}}});
  IncrementalScheduler sched;
  sched.reset(inst);
  MckpSolution out;
  sched.step(inst, {}, {}, SolveLimits{}, out);
  EXPECT_FALSE(out.feasible);
  EXPECT_EQ(out.choice, (std::vector<std::uint32_t>{0, 0}));
}

TEST(BudgetIncremental, AFrameAllocatesNothingAfterSetup) {
  std::mt19937 rng(8);
  MckpInstance inst;
  for (int k = 0; k < 500; ++k) {
    std::vector<MckpItem> items;
    double w = 1, p = 1;
    for (int j = 0; j < 5; ++j) {
      items.push_back({p, w});
      w *= 2;
      p += 10.0 / (j + 1);
    }
    inst.add_subset(items);
  }
  inst.capacity = lowest_cost(inst) * 4;
  IncrementalScheduler sched;
  sched.reset(inst);
  MckpSolution out, next;
  sched.step(inst, {}, {}, SolveLimits{}, out);  // first frame sizes `out`
  next = out;
  std::normal_distribution<double> noise(0.0, 0.02);
  for (MckpItem& it : inst.items) it.profit *= 1.0 + noise(rng);
  g_allocations = 0;
  g_count_allocations = true;
  for (int f = 0; f < 10; ++f) sched.step(inst, out.choice, {}, SolveLimits{}, next);
  g_count_allocations = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_TRUE(next.feasible);
}

}  // namespace
}  // namespace gazelod::budget
