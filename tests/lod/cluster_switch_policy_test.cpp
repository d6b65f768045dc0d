// SPDX-License-Identifier: Apache-2.0
// The cluster switch policy: a held cut stays consistent after every step of a random gaze walk
// and is never coarser than the perceptual cut; per record, coarsening waits for the hold (and
// for suppression), refinement is immediate; reset and validation.
#include "lod/cluster/cluster_select.hpp"
#include "lod/cluster/cluster_select_store.hpp"
#include "lod/cluster/cluster_switch_policy.hpp"
#include "tests/lod/cluster_test_hierarchy.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace gazelod::lod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct State {
  explicit State(std::size_t n) : held(n), self_start(n), parent_start(n), drawn(n), why(n) {}
  ClusterSwitchState s() { return {held, self_start, parent_start}; }
  std::vector<std::uint8_t> held;
  std::vector<double> self_start, parent_start;
  std::vector<std::uint8_t> drawn, why;
};

TEST(ClusterSwitchPolicy, HeldCutStaysConsistentOnARandomGazeWalk) {
  std::vector<test::TestTree> trees{test::make_tree({5, true, 2}, 1), test::make_tree({7, false, 1}, 2)};
  ClusterStore store;
  InstanceTransform second;
  second.translation_m = {0.0, 0.0, 16.0};
  store.add_mesh(trees[0].h, {}, {}, 3 * trees[0].h.size());
  store.add_mesh(trees[1].h, second, {0.3, 0.0, 0.0}, 3 * trees[1].h.size());
  const ClusterSet cs = store.view();
  const std::size_t n = cs.size();
  State st(n);
  ASSERT_EQ(reset_cluster_switch_state(st.s(), cs.self_error_m, cs.parent_error_m), "");
  std::vector<std::uint8_t> now(n), why_now(n), bits(n);

  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Viewer vw;
  vw.eye_position_m = {6.0, 1.6, 6.0};
  vw.xi_cpd = 20.0;
  glm::dvec3 target{6.0, 0.0, 2.0};
  const SwitchPolicyConfig config;
  int suppressed_left = 0;
  std::size_t differ = 0, coarsened = 0;
  std::vector<int> last_held;
  for (int frame = 0; frame < 1500; ++frame) {
    double t = frame / 72.0;
    if (frame == 700) t = kNaN;  // a frame without a clock
    if (frame >= 900) t -= 0.5;  // the clock steps back once
    if (u(rng) > 0.97) {         // a saccade: a new target, a few suppressed frames
      target = {cs.self_center_x_m[rng() % n], 0.0, cs.self_center_z_m[rng() % n]};
      suppressed_left = 4;
    }
    target += 0.02 * glm::dvec3{u(rng), 0.0, u(rng)};  // fixational drift
    vw.eye_position_m += glm::dvec3{0.01 * u(rng), 0.0, 0.01};
    vw.gaze_direction = target - vw.eye_position_m;
    vw.head_angular_velocity_rad_s = 0.2 * glm::dvec3{u(rng), u(rng), u(rng)};
    ASSERT_EQ(select_clusters(vw, cs, {now, why_now, {}, {}, {}, bits}), "");
    ASSERT_EQ(apply_cluster_switch_policy(config, t, suppressed_left-- > 0, bits, st.s(), st.drawn, st.why), "");
    std::vector<int> held_levels;
    for (std::size_t k = 0; k < trees.size(); ++k) {
      const std::size_t first = store.first_cluster(static_cast<std::uint32_t>(k)), m = trees[k].h.size();
      const std::span<const std::uint8_t> held(st.drawn.data() + first, m), perc(now.data() + first, m);
      ASSERT_EQ(test::check_cut(trees[k], held), "") << "frame " << frame << " mesh " << k;
      ASSERT_EQ(test::check_cut(trees[k], perc), "") << "frame " << frame;
      const std::vector<int> lh = test::cut_levels(trees[k], held), lp = test::cut_levels(trees[k], perc);
      for (std::size_t li = 0; li < lh.size(); ++li) {
        ASSERT_LE(lh[li], lp[li]) << "frame " << frame;  // never coarser than perceptual
        differ += lh[li] != lp[li];
      }
      held_levels.insert(held_levels.end(), lh.begin(), lh.end());
    }
    for (std::size_t li = 0; li < last_held.size(); ++li) coarsened += held_levels[li] > last_held[li];
    last_held = held_levels;
  }
  EXPECT_GT(differ, 1000u);    // the policy held detail back often
  EXPECT_GT(coarsened, 100u);  // and still coarsened
}

// Two clusters: a source cluster under a top one. Bits: the source's self error (0) always
// invisible; the shared record (its parent, the top's self) as given.
std::vector<std::uint8_t> bits_of(bool shared_invisible) {
  return {static_cast<std::uint8_t>(1 | (shared_invisible ? 2 : 0)),
          static_cast<std::uint8_t>(shared_invisible ? 1 : 0)};
}
const std::vector<float> kSelfErr{0.0f, 0.01f}, kParentErr{0.01f, std::numeric_limits<float>::infinity()};

TEST(ClusterSwitchPolicy, CoarsensAfterTheHoldRefinesAtOnce) {
  State st(2);
  ASSERT_EQ(reset_cluster_switch_state(st.s(), kSelfErr, kParentErr), "");
  const SwitchPolicyConfig c{0.2, 1.0, false};
  const auto frame = [&](double t, bool inv, bool suppressed = false) {
    ASSERT_EQ(apply_cluster_switch_policy(c, t, suppressed, bits_of(inv), st.s(), st.drawn, st.why), "");
  };
  frame(0.0, false);
  EXPECT_EQ(st.drawn, (std::vector<std::uint8_t>{1, 0}));  // the finest cut
  frame(0.1, true);
  EXPECT_EQ(st.drawn, (std::vector<std::uint8_t>{1, 0}));
  EXPECT_EQ(static_cast<HoldReason>(st.why[0]), HoldReason::hold_time);
  frame(0.29, true);
  EXPECT_EQ(st.drawn[1], 0);
  frame(0.31, true);  // 0.21 s invisible without a break
  EXPECT_EQ(st.drawn, (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(static_cast<HoldReason>(st.why[0]), HoldReason::none);
  frame(0.32, false);  // visible again: at once
  EXPECT_EQ(st.drawn, (std::vector<std::uint8_t>{1, 0}));
  frame(0.4, true), frame(0.5, false), frame(0.65, true);  // a break restarts the hold
  EXPECT_EQ(st.drawn[0], 1);
  frame(kNaN, true);  // no time: nothing coarsens
  EXPECT_EQ(static_cast<HoldReason>(st.why[0]), HoldReason::no_time);
  frame(0.86, true);
  EXPECT_EQ(st.drawn[1], 1);
}

TEST(ClusterSwitchPolicy, WaitsForSuppressionAtMostTheDeferral) {
  State st(2);
  ASSERT_EQ(reset_cluster_switch_state(st.s(), kSelfErr, kParentErr), "");
  const SwitchPolicyConfig c;  // hold 0.2, deferral 0.6, prefer suppression, 0 inside it
  const auto frame = [&](double t, bool inv, bool suppressed = false) {
    ASSERT_EQ(apply_cluster_switch_policy(c, t, suppressed, bits_of(inv), st.s(), st.drawn, st.why), "");
  };
  frame(0.0, true);
  frame(0.5, true);
  EXPECT_EQ(static_cast<HoldReason>(st.why[0]), HoldReason::awaiting_suppression);
  frame(0.6, true, true);  // a saccade: coarsens now
  EXPECT_EQ(st.drawn[1], 1);
  frame(0.7, false);
  frame(0.71, true, true);  // inside suppression: no hold at all
  EXPECT_EQ(st.drawn[1], 1);
  frame(0.8, false);
  frame(1.0, true);
  const double due = 1.0 + c.coarsen_hold_s + c.max_deferral_s;
  frame(due - 0.01, true);
  EXPECT_EQ(st.drawn[1], 0);
  frame(due + 0.01, true);  // hold + deferral passed without a saccade
  EXPECT_EQ(st.drawn[1], 1);
}

TEST(ClusterSwitchPolicy, RefusesBadConfigAndLengths) {
  State st(2);
  EXPECT_NE(reset_cluster_switch_state(st.s(), kSelfErr, {kParentErr.data(), 1}), "");
  ASSERT_EQ(reset_cluster_switch_state(st.s(), kSelfErr, kParentErr), "");
  SwitchPolicyConfig bad;
  bad.coarsen_hold_s = -1.0;
  const std::vector<std::uint8_t> bits = bits_of(true), before = st.held;
  EXPECT_NE(apply_cluster_switch_policy(bad, 0.0, false, bits, st.s(), st.drawn, st.why).find("coarsen_hold_s"),
            std::string::npos);
  std::vector<std::uint8_t> short_drawn(1);
  EXPECT_NE(apply_cluster_switch_policy({}, 0.0, false, bits, st.s(), short_drawn, st.why), "");
  std::vector<double> short_start(1);
  EXPECT_NE(apply_cluster_switch_policy({}, 0.0, false, bits, {st.held, short_start, st.parent_start}, st.drawn, {}),
            "");
  EXPECT_EQ(st.held, before);
  // The listed pass: the same checks, and an id past the clusters, nothing written.
  std::vector<std::uint32_t> pending;
  const std::vector<std::uint32_t> past{0, 2};
  EXPECT_NE(apply_cluster_switch_policy_listed(bad, 0.0, false, bits, st.s(), st.drawn, st.why, past, pending), "");
  EXPECT_NE(apply_cluster_switch_policy_listed({}, 0.0, false, bits, st.s(), st.drawn, st.why, past, pending)
                .find("cluster 2 is out of range (2 clusters)"),
            std::string::npos);
  EXPECT_EQ(st.held, before);
  EXPECT_TRUE(pending.empty());
}

// Listing a cluster steps it as the full pass does; one left out keeps its state, and a
// coarsening still held back is reported pending until it is drawn.
TEST(ClusterSwitchPolicy, ListedPassStepsTheListAndReportsWhatIsPending) {
  State full(2), listed(2);
  ASSERT_EQ(reset_cluster_switch_state(full.s(), kSelfErr, kParentErr), "");
  ASSERT_EQ(reset_cluster_switch_state(listed.s(), kSelfErr, kParentErr), "");
  const SwitchPolicyConfig c;  // hold 0.2 s, then a saccade or 0.6 s more
  const std::vector<std::uint8_t> bits = bits_of(true);
  const std::vector<std::uint32_t> both{0, 1};
  std::vector<std::uint32_t> pending;
  for (double t_s : {0.0, 0.1, 0.3, 0.9}) {
    pending.clear();
    ASSERT_EQ(apply_cluster_switch_policy(c, t_s, false, bits, full.s(), full.drawn, full.why), "");
    ASSERT_EQ(apply_cluster_switch_policy_listed(c, t_s, false, bits, listed.s(), listed.drawn, listed.why, both,
                                                 pending),
              "");
    EXPECT_EQ(listed.held, full.held) << t_s;
    EXPECT_EQ(listed.drawn, full.drawn) << t_s;
    EXPECT_EQ(listed.why, full.why) << t_s;
    // Pending while a record is invisible and not yet held, i.e. while the coarsening waits.
    EXPECT_EQ(pending.size(), t_s < 0.8 ? 2u : 0u) << t_s;
  }
  // Now held: an empty list changes nothing, as the full pass would not.
  const std::vector<std::uint8_t> held = listed.held, drawn = listed.drawn;
  ASSERT_EQ(apply_cluster_switch_policy_listed(c, 1.0, false, bits, listed.s(), listed.drawn, listed.why, {}, pending),
            "");
  EXPECT_EQ(listed.held, held);
  EXPECT_EQ(listed.drawn, drawn);
}

}  // namespace
}  // namespace gazelod::lod
