// SPDX-License-Identifier: Apache-2.0
// The offline optimum (apps/gazelod/run/offline_bound.hpp): hand-solved runs, the audit's
// counting rules (suppression, out of view), an exhaustive check of the shortest path and of
// the bisected bound on random small runs, and the refusals.
#include "apps/gazelod/run/offline_bound.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace gazelod::cli {
namespace {

std::vector<std::vector<lod::LodLevel>> chains(std::size_t n, std::vector<std::uint32_t> triangles) {
  std::vector<lod::LodLevel> chain(triangles.size());
  for (std::size_t l = 0; l < triangles.size(); ++l) chain[l].triangles = triangles[l];
  return std::vector<std::vector<lod::LodLevel>>(n, chain);
}

// One object, levels of 1000 and 100 triangles, 10 frames; the ceiling allows the coarse level
// except for a one-frame dip at frame 3.
struct Dip {
  std::vector<std::vector<lod::LodLevel>> levels = chains(1, {1000, 100});
  std::vector<std::uint8_t> ceiling{1, 1, 1, 0, 1, 1, 1, 1, 1, 1};
  std::vector<std::uint8_t> in_view = std::vector<std::uint8_t>(10, 1);
  std::vector<std::uint8_t> suppressed = std::vector<std::uint8_t>(10, 0);
  OfflineBoundInput input() const { return {1, &levels, ceiling, in_view, suppressed}; }
};

TEST(OfflineBound, HandSolvedDip) {
  const Dip d;
  const OfflinePoint free = offline_optimum(d.input(), 0.0);
  ASSERT_TRUE(free.available) << free.reason;
  EXPECT_EQ(free.triangles, 9u * 100 + 1000) << "follows the ceiling";
  EXPECT_EQ(free.switches, 2);
  // One switch: fine until the dip, coarse after it (4 x 1000 + 6 x 100), rather than coarse
  // until the dip and fine after it (3 x 100 + 7 x 1000).
  const OfflinePoint one = offline_bound(d.input(), 1);
  EXPECT_EQ(one.triangles, 4600u);
  EXPECT_EQ(one.switches, 1);
  const OfflinePoint none = offline_bound(d.input(), 0);
  EXPECT_EQ(none.triangles, 10000u) << "no switch: the full level throughout";
  EXPECT_EQ(none.switches, 0);
  EXPECT_EQ(offline_bound(d.input(), 2).triangles, free.triangles);
  EXPECT_EQ(offline_bound(d.input(), -3).triangles, 10000u) << "a negative budget reads as none";
  EXPECT_DOUBLE_EQ(one.lower_triangles, 4600.0) << "the bracket is closed on a hull corner";
}

TEST(OfflineBound, SwitchesInSuppressionAreFree) {
  Dip d;
  d.suppressed[3] = d.suppressed[4] = 1;  // the refinement at 3 and the coarsening at 4 unseen
  const OfflinePoint p = offline_bound(d.input(), 0);
  EXPECT_EQ(p.triangles, 1900u);
  EXPECT_EQ(p.switches, 0);
  d.suppressed[4] = 0;  // the way back is seen: refine unseen at 3 and stay fine (3 x 100 + 7 x 1000)
  EXPECT_EQ(offline_bound(d.input(), 0).triangles, 7300u);
  EXPECT_EQ(offline_bound(d.input(), 1).triangles, 1900u) << "one counted switch buys the way back";
}

// With the oracle's levels given, the sequence's degraded object-frames are counted (in view,
// outside suppression, coarser than the oracle), not avoided.
TEST(OfflineBound, CountsTheDegradationsOfTheSequenceItFinds) {
  Dip d;
  std::vector<std::uint8_t> oracle = d.ceiling;
  oracle[6] = oracle[7] = 0;  // the truth needs the full level at 6 and 7; the ceiling does not know
  OfflineBoundInput in = d.input();
  in.oracle = oracle;
  const OfflinePoint free = offline_optimum(in, 0.0);
  EXPECT_EQ(free.degraded, 2);
  EXPECT_EQ(free.triangles, 1900u) << "counting changes nothing it chooses";
  d.suppressed[6] = 1;
  in = d.input();
  in.oracle = oracle;
  EXPECT_EQ(offline_optimum(in, 0.0).degraded, 1) << "a suppressed frame hides its degradation";
  EXPECT_EQ(offline_optimum(d.input(), 0.0).degraded, 0) << "not counted without the oracle";
  in.oracle = std::span<const std::uint8_t>(oracle).first(5);
  EXPECT_NE(offline_optimum(in, 0.0).reason.find("oracle's levels"), std::string::npos);
}

TEST(OfflineBound, OutOfViewFramesCountNothingAndBindNothing) {
  Dip d;
  d.in_view[3] = 0;
  const OfflinePoint p = offline_bound(d.input(), 0);
  EXPECT_EQ(p.triangles, 9u * 100) << "the dip is out of view: coarse throughout, frame 3 uncounted";
  EXPECT_EQ(p.switches, 0);
}

// Every level sequence of one object, for the exhaustive checks: the cheapest triangles with
// at most `budget` counted switches, and the cheapest cost at a price.
struct Exhaustive {
  std::uint64_t triangles_within(std::int64_t budget) const { return best_within[std::min<std::int64_t>(budget, 64)]; }
  std::vector<std::uint64_t> best_within = std::vector<std::uint64_t>(65, std::numeric_limits<std::uint64_t>::max());
  std::vector<std::pair<std::uint64_t, std::int64_t>> all;  // feasible (triangles, switches)
};

Exhaustive enumerate(const std::vector<std::uint32_t>& tri, const std::vector<std::uint8_t>& ceiling,
                     const std::vector<std::uint8_t>& in_view, const std::vector<std::uint8_t>& suppressed,
                     std::size_t object, std::size_t n) {
  Exhaustive e;
  const std::size_t frames = suppressed.size(), m = tri.size();
  std::vector<std::size_t> seq(frames, 0);
  for (;;) {
    bool ok = true;
    std::uint64_t t = 0;
    std::int64_t s = 0;
    for (std::size_t k = 0; k < frames && ok; ++k) {
      const bool view = in_view[k * n + object] != 0;
      if (view && seq[k] > ceiling[k * n + object]) ok = false;
      if (view) t += tri[seq[k]];
      if (k > 0 && seq[k] != seq[k - 1] && view && !suppressed[k]) ++s;
    }
    if (ok) {
      e.all.push_back({t, s});
      for (std::int64_t b = s; b <= 64; ++b) e.best_within[b] = std::min(e.best_within[b], t);
    }
    std::size_t k = 0;
    while (k < frames && ++seq[k] == m) seq[k++] = 0;
    if (k == frames) break;
  }
  return e;
}

TEST(OfflineBound, MatchesExhaustiveSearchOnRandomRuns) {
  std::mt19937 rng(20261207);
  const std::vector<std::uint32_t> tri{900, 300, 100};
  for (int run = 0; run < 40; ++run) {
    const std::size_t n = 2, frames = 8;
    std::vector<std::uint8_t> ceiling(frames * n), in_view(frames * n), suppressed(frames);
    for (auto& c : ceiling) c = static_cast<std::uint8_t>(rng() % 3);
    for (auto& v : in_view) v = rng() % 5 != 0;
    for (auto& s : suppressed) s = rng() % 4 == 0;
    const auto levels = chains(n, tri);
    const OfflineBoundInput in{n, &levels, ceiling, in_view, suppressed};
    std::vector<Exhaustive> each;
    for (std::size_t i = 0; i < n; ++i) each.push_back(enumerate(tri, ceiling, in_view, suppressed, i, n));
    for (double price : {0.0, 150.0, 450.0, 2000.0}) {
      // The shortest path's cost is the exhaustive minimum of triangles + price x switches.
      double want = 0.0;
      for (const Exhaustive& e : each) {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& [t, s] : e.all) best = std::min(best, static_cast<double>(t) + price * static_cast<double>(s));
        want += best;
      }
      const OfflinePoint p = offline_optimum(in, price);
      ASSERT_TRUE(p.available) << p.reason;
      EXPECT_DOUBLE_EQ(static_cast<double>(p.triangles) + price * static_cast<double>(p.switches), want)
          << "run " << run << " price " << price;
    }
    // The exact constrained optimum: the sum over objects of the best split of the budget.
    const auto exact_within = [&](std::int64_t budget) {
      std::uint64_t exact = std::numeric_limits<std::uint64_t>::max();
      for (std::int64_t a = 0; a <= budget; ++a)
        exact = std::min(exact, each[0].triangles_within(a) + each[1].triangles_within(budget - a));
      return exact;
    };
    for (std::int64_t budget = 0; budget <= 6; ++budget) {
      // The sequence found fits the budget and is the exact optimum for its own switch count
      // (a Lagrangian minimiser); the exact optimum at the budget lies in [lower, triangles].
      const OfflinePoint b = offline_bound(in, budget);
      EXPECT_LE(b.switches, budget) << "run " << run;
      EXPECT_EQ(b.triangles, exact_within(b.switches)) << "run " << run << " budget " << budget;
      EXPECT_LE(b.lower_triangles, static_cast<double>(exact_within(budget))) << "run " << run << " budget " << budget;
      EXPECT_GE(b.lower_triangles, 0.0);
    }
  }
}

TEST(OfflineBound, RefusesInputThatDoesNotFit) {
  Dip d;
  OfflineBoundInput in = d.input();
  in.ceiling = std::span<const std::uint8_t>(d.ceiling).first(9);
  EXPECT_FALSE(offline_optimum(in, 0.0).available);
  EXPECT_NE(offline_bound(in, 1).reason.find("frames x objects"), std::string::npos);
  in = d.input();
  in.chains = nullptr;
  EXPECT_NE(offline_bound(in, 1).reason.find("levels are missing"), std::string::npos);
  in = d.input();
  EXPECT_FALSE(offline_optimum(in, -1.0).available);
  EXPECT_FALSE(offline_optimum(in, std::nan("")).available) << "no NaN price reaches a sum";
  in.suppressed = {};
  in.ceiling = {};
  in.in_view = {};
  EXPECT_NE(offline_bound(in, 0).reason.find("no object-frames"), std::string::npos);
}

}  // namespace
}  // namespace gazelod::cli
