// SPDX-License-Identifier: Apache-2.0
// The Reddy 1998 scenarios `gazelod eval` writes: valid for the simulator, the paper's figures,
// reproducible layouts.
#include "apps/gazelod/eval/scenario.hpp"
#include "sim/simulator.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace gazelod::cli {
namespace {

TEST(EvalScenario, LoadsWithThePapersFigures) {
  ReddyScenario s;
  s.objects = 50;
  const sim::Scenario sc = sim::load_scenario_json(reddy_scenario_json(s), "reddy");
  ASSERT_EQ(sc.objects.size(), 50u);
  for (const auto& o : sc.objects) {
    ASSERT_EQ(o.lods.size(), 4u);
    EXPECT_EQ(o.lods[0].triangles, 3928u);
    EXPECT_EQ(o.lods[1].triangles, 834u);
    EXPECT_EQ(o.lods[2].triangles, 254u);
    EXPECT_EQ(o.lods[3].triangles, 76u);
    EXPECT_NEAR(o.lods[1].detail, std::sqrt(834.0) / 2.0, 1e-9);
  }
  EXPECT_NEAR(sc.head_path.velocity_m_s.z, -4.36, 1e-12);
  EXPECT_NEAR(sc.duration_s, 5.0, 1e-12);
  EXPECT_NEAR(sc.frame_rate_hz, 72.0, 1e-12);
  EXPECT_TRUE(sc.effects.empty());
}

TEST(EvalScenario, LayoutsAreReproducibleAndDistinct) {
  ReddyScenario a;
  EXPECT_EQ(reddy_scenario_json(a), reddy_scenario_json(a));
  ReddyScenario b = a;
  b.layout_seed = 2;
  EXPECT_NE(reddy_scenario_json(a), reddy_scenario_json(b));
}

TEST(EvalScenario, SurroundPlacesObjectsAllAroundWithAHeadTurn) {
  ReddyScenario s;
  s.objects = 400;
  s.surround = true;
  s.head_turn_deg_s = 180.0;
  const sim::Scenario sc = sim::load_scenario_json(reddy_scenario_json(s), "reddy");
  ASSERT_EQ(sc.effects.size(), 1u);
  EXPECT_EQ(sc.effects[0].type, "head_turn");
  int behind = 0;
  for (const auto& o : sc.objects) {
    const double horizontal = std::hypot(o.position_m.x, o.position_m.z);
    EXPECT_GE(horizontal, 5.0 - 1e-9);
    EXPECT_LE(horizontal, 80.0 + 1e-9);
    if (o.position_m.z > 0.0) ++behind;
  }
  EXPECT_GT(behind, 100);  // about half of 400 behind the start direction
  EXPECT_LT(behind, 300);
}

}  // namespace
}  // namespace gazelod::cli
