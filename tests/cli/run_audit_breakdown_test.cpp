// SPDX-License-Identifier: Apache-2.0
// The audit's breakdown (apps/gazelod/run/audit_breakdown.hpp) on synthetic frames: the true
// gaze state's seams, the object classes, the excess split between the switch policy and the
// selection, visible and oracle switches, and the JSON round trip.
#include "apps/gazelod/run/audit_breakdown.hpp"

#include "gaze/gaze_conditioner.hpp"
#include "lod/criterion.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

namespace gazelod::cli {
namespace {

std::vector<std::vector<lod::LodLevel>> chains(std::size_t n) {
  std::vector<lod::LodLevel> chain(4);
  const std::uint32_t tri[4] = {1000, 250, 60, 15};
  for (int k = 0; k < 4; ++k) chain[k].triangles = tri[k];
  return std::vector<std::vector<lod::LodLevel>>(n, chain);
}

TEST(AuditBreakdown, TrueGazeStateAtItsSeams) {
  sim::EyeTruth t;
  EXPECT_EQ(classify_true_gaze(t, false, 0.0, 0.0), TrueGaze::fixation);
  EXPECT_EQ(classify_true_gaze(t, false, kHeadStillDps - 1e-9, 100.0), TrueGaze::fixation) << "head still";
  EXPECT_EQ(classify_true_gaze(t, false, kHeadStillDps, 0.0), TrueGaze::vor) << "the seam belongs to moving";
  EXPECT_EQ(classify_true_gaze(t, false, 20.0, 9.999), TrueGaze::vor);
  EXPECT_EQ(classify_true_gaze(t, false, 20.0, 10.0), TrueGaze::carried) << "half the head's speed";
  EXPECT_EQ(classify_true_gaze(t, false, std::nan(""), 0.0), TrueGaze::fixation) << "no NaN reaches a state";
  t.pursuit_object = 3;
  EXPECT_EQ(classify_true_gaze(t, false, 20.0, 20.0), TrueGaze::pursuit);
  EXPECT_EQ(classify_true_gaze(t, true, 20.0, 20.0), TrueGaze::saccade) << "the window after a catch-up saccade";
  t.in_saccade = true;
  EXPECT_EQ(classify_true_gaze(t, false, 0.0, 0.0), TrueGaze::saccade);
  t.in_blink = true;
  EXPECT_EQ(classify_true_gaze(t, true, 0.0, 0.0), TrueGaze::blink) << "a blink wins";
  EXPECT_STREQ(to_string(TrueGaze::carried), "carried");
  EXPECT_STREQ(to_string(ObjectClass::far_outside), "far_outside");
}

TEST(AuditBreakdown, SwitchVisibleOnlyWhenTheCoarserLevelIsNotAllowed) {
  EXPECT_FALSE(switch_visible(1, 1, 0)) << "no switch";
  EXPECT_FALSE(switch_visible(1, 2, 2)) << "both levels allowed: the change is below threshold";
  EXPECT_FALSE(switch_visible(2, 1, 3));
  EXPECT_TRUE(switch_visible(1, 2, 1)) << "level 2 removes visible detail";
  EXPECT_TRUE(switch_visible(2, 0, 1)) << "a refinement from a level that was itself too coarse";
}

TEST(AuditBreakdown, ClassesExcessSplitAndSwitches) {
  const auto c = chains(4);
  // Object 0: near, in the cone, drawn 0, perceptual 1, oracle 2 (held 1000 -> 250, chosen 250 -> 60).
  // Object 1: far, outside, drawn 3 over oracle 1 (degraded), switched from 2 (visible).
  // Object 2: far, outside, drawn 1 = perceptual = oracle, the oracle switched from 2.
  // Object 3: out of view (ignored).
  const std::uint8_t drawn[] = {0, 3, 1, 0}, prev[] = {0, 2, 1, 3}, perceptual[] = {1, 3, 1, 0},
                     oracle[] = {2, 1, 1, 3}, prev_oracle[] = {2, 1, 2, 0},
                     limited[] = {static_cast<std::uint8_t>(lod::Criterion::eccentricity),
                                  static_cast<std::uint8_t>(lod::Criterion::size),
                                  static_cast<std::uint8_t>(lod::Criterion::size),
                                  static_cast<std::uint8_t>(lod::Criterion::velocity)},
                     view[] = {1, 1, 1, 0};
  const float ecc[] = {2.0f, 30.0f, 6.0f, 0.0f}, dist[] = {3.0f, 50.0f, 10.0f, 1.0f};
  BreakdownFrameInput in;
  in.chains = &c;
  in.drawn = drawn;
  in.previous = prev;
  in.perceptual = perceptual;
  in.oracle = oracle;
  in.previous_oracle = prev_oracle;
  in.oracle_limited_by = limited;
  in.in_view = view;
  in.eccentricity_deg = ecc;
  in.distance_m = dist;
  in.gaze = TrueGaze::vor;
  in.estimate = static_cast<std::uint8_t>(gaze::EyeMotion::fixation);
  in.frame_s = 0.01;
  AuditBreakdown b;
  add_breakdown_frame(in, b);

  const BreakdownCell& vor = b.gaze[static_cast<std::size_t>(TrueGaze::vor)];
  EXPECT_EQ(vor.object_frames, 3);
  EXPECT_EQ(vor.degraded, 1);
  EXPECT_EQ(vor.drawn_triangles, 1000u + 15u + 250u);
  EXPECT_EQ(vor.oracle_triangles, 60u + 250u + 250u);
  EXPECT_EQ(vor.excess_held, 750u) << "drawn 0 where the plugin's own level was 1";
  EXPECT_EQ(vor.excess_selected, 190u) << "the plugin's level 1 where the oracle allowed 2";
  EXPECT_EQ(vor.switches, 1);
  EXPECT_EQ(vor.visible_switches, 1);
  EXPECT_EQ(vor.oracle_switches, 1);
  EXPECT_DOUBLE_EQ(vor.object_s, 0.03);
  for (std::size_t g = 0; g < kTrueGazeCount; ++g) {
    if (g != static_cast<std::size_t>(TrueGaze::vor)) {
      EXPECT_EQ(b.gaze[g].object_frames, 0) << g;
    }
  }

  EXPECT_EQ(b.objects[static_cast<std::size_t>(ObjectClass::near_in_cone)].object_frames, 1);
  EXPECT_EQ(b.objects[static_cast<std::size_t>(ObjectClass::far_outside)].object_frames, 2)
      << "10 m is far (the seam), 6 deg outside the 5.79 deg cone";
  EXPECT_EQ(b.objects[static_cast<std::size_t>(ObjectClass::far_outside)].degraded, 1);
  EXPECT_EQ(b.criterion[static_cast<std::size_t>(lod::Criterion::eccentricity)].excess_held, 750u);
  EXPECT_EQ(b.criterion[static_cast<std::size_t>(lod::Criterion::size)].object_frames, 2);
  EXPECT_EQ(b.criterion[static_cast<std::size_t>(lod::Criterion::velocity)].object_frames, 0) << "out of view";
  EXPECT_EQ(b.estimate[static_cast<std::size_t>(gaze::EyeMotion::fixation)].object_frames, 3);

  // The first frame has no previous levels: no switches of either kind.
  in.previous = {};
  in.previous_oracle = {};
  AuditBreakdown first;
  add_breakdown_frame(in, first);
  EXPECT_EQ(first.gaze[static_cast<std::size_t>(TrueGaze::vor)].switches, 0);
  EXPECT_EQ(first.gaze[static_cast<std::size_t>(TrueGaze::vor)].oracle_switches, 0);
}

TEST(AuditBreakdown, JsonNamesEveryGroupAndCell) {
  AuditBreakdown b;
  b.gaze[2].object_frames = 7;
  b.gaze[2].excess_held = 123;
  b.objects[3].visible_switches = 4;
  b.estimate[1].object_s = 2.5;
  b.criterion[4].oracle_switches = 9;
  const nlohmann::json j = breakdown_json(b);
  EXPECT_EQ(j.at("by_true_gaze").at("carried").at("object_frames").get<int>(), 7);
  EXPECT_EQ(j.at("by_true_gaze").at("carried").at("excess_held_triangles").get<int>(), 123);
  EXPECT_EQ(j.at("by_object").at("far_outside").at("visible_switches").get<int>(), 4);
  EXPECT_EQ(j.at("by_oracle_criterion").at("combined").at("oracle_switches").get<int>(), 9);
}

TEST(AuditBreakdown, PrintShowsOnlyCellsWithFrames) {
  AuditBreakdown empty;
  std::ostringstream none;
  print_breakdown(empty, none);
  EXPECT_EQ(none.str(), "") << "nothing to break down";
  AuditBreakdown b;
  b.gaze[0].object_frames = 10;
  b.gaze[0].drawn_triangles = 200;
  b.gaze[0].oracle_triangles = 100;
  b.gaze[0].object_s = 1.0;
  b.gaze[0].switches = 3;
  b.objects[1].object_frames = 10;
  std::ostringstream out;
  print_breakdown(b, out);
  EXPECT_NE(out.str().find("gaze      fixation"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("2.000"), std::string::npos) << "drawn / oracle\n" << out.str();
  EXPECT_EQ(out.str().find("pursuit"), std::string::npos) << "an empty cell is not printed\n" << out.str();
}

}  // namespace
}  // namespace gazelod::cli
