// SPDX-License-Identifier: Apache-2.0
// gazelod eval family end to end on the simulated runtime: the report's shape, determinism,
// bad options, and the audit's distribution on held-out seeds (docs/evaluation.md, "Scenario
// family"), which the defaults were not tuned on.
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/eval/family.hpp"
#include "tests/eval/eval_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

using testing::Result;

Result cli(const std::vector<std::string>& args) {
  testing::use_simulated_runtime();
  return testing::cli(args);
}

std::filesystem::path scratch() {
  return testing::scratch("family.");
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(EvalFamily, ReportShapeDeterminismAndSettings) {
  const auto dir = scratch();
  const std::vector<std::string> args{"eval",       "family",
                                      "--seeds",    "7-9",
                                      "--duration", "3",
                                      "--out",      (dir / "a").string(),
                                      "--set",      "switch.coarsen_hold_s=0.3"};
  const Result r = cli(args);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.err.find("[3/3] seed 9"), std::string::npos) << "a progress line per seed\n" << r.err;
  EXPECT_NE(r.out.find("| 8 | "), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(read(dir / "a" / "family.json"));
  ASSERT_EQ(j.at("members").size(), 3u);
  EXPECT_EQ(j.at("settings_changed")[0], "switch.coarsen_hold_s=0.3");
  for (const auto& [name, d] : j.at("distribution").items()) {
    EXPECT_LE(d.at("median").get<double>(), d.at("p90").get<double>()) << name;
    EXPECT_LE(d.at("p90").get<double>(), d.at("worst").get<double>()) << name;
  }
  EXPECT_TRUE(read(dir / "a" / "family.md").starts_with("<!-- written by: gazelod eval family --seeds 7-9"));
  std::vector<std::string> again = args;
  again[7] = (dir / "b").string();
  ASSERT_EQ(cli(again).rc, 0);
  EXPECT_EQ(read(dir / "b" / "family.json"), read(dir / "a" / "family.json")) << "the same seeds, the same figures";
}

TEST(EvalFamily, BadOptionsAreRefusedWithTheReason) {
  const auto dir = scratch();
  const auto refused = [&](std::vector<std::string> extra, const std::string& says) {
    std::vector<std::string> args{"eval", "family", "--out", (dir / "x").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = cli(args);
    EXPECT_EQ(r.rc, 2) << says;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  };
  refused({"--set", "switch.nope=1"}, "unknown setting 'switch.nope'");
  refused({"--set", "switch.coarsen_hold_s=abc"}, "is not a number");
  refused({"--set", "switch.coarsen_hold_s=nan"}, "is not a number");
  refused({"--set", "switch.coarsen_hold_s=-1"}, "must be in [0, 10]");
  refused({"--set", "switch.prefer_suppression=0.5"}, "must be 0 or 1");
  refused({"--set", "switch.coarsen_hold_s"}, "expected NAME=VALUE");
  refused({"--seeds", "9-3"}, "ends before it starts");
  refused({"--seeds", "0x10"}, "expected A-B or A");
  refused({"--seeds", "0-20000"}, "at most 10000 seeds");
  refused({"--ideal", "latency,speed"}, "--ideal: expected latency, noise, rate");
  EXPECT_FALSE(std::filesystem::exists(dir / "x" / "family.md")) << "nothing written on a refusal";
  const Result list = cli({"eval", "family", "--list-settings"});
  ASSERT_EQ(list.rc, 0);
  EXPECT_NE(list.out.find("switch.max_deferral_s=0.6"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("conditioner.carried_evidence=12"), std::string::npos) << list.out;
}

// The conditioner's own rules are checked on the settings before any seed runs: a setting it
// refuses stops the family with its name and value (exit 2), never replaced by a default.
TEST(EvalFamily, ConditionerSettingsItRefusesStopTheFamilyBeforeAnySeed) {
  FamilySettings settings;
  settings.conditioning.pursuit_exit_fraction = 1.5;
  try {
    (void)run_family(7, 1, 1.0, settings, (scratch() / "w").string(),
                     [](const std::string& line) { ADD_FAILURE() << "a seed ran: " << line; });
    ADD_FAILURE() << "accepted";
  } catch (const UsageError& e) {
    EXPECT_EQ(e.exit_code, 2);
    const std::string what = e.what();
    EXPECT_NE(what.find("conditioner.pursuit_exit_fraction must be in [0, 1], got 1.5"), std::string::npos) << what;
  }
}

// Held-out seeds (the defaults were tuned on 1000-1039): the bulk of the family within the
// targets. Not every seed is (docs/evaluation.md lists the ones outside and why); the counts
// are those of 2026-12-07, so a change that loses one fails here.
TEST(EvalFamily, HeldOutSeedsMostlyWithinTheTargets) {
  const auto dir = scratch();
  const Result r = cli({"eval", "family", "--seeds", "2000-2019", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  const nlohmann::json d = nlohmann::json::parse(read(dir / "family.json")).at("distribution");
  const auto& degraded = d.at("visible degradations (fixation object-frames)");
  const auto& triangles = d.at("triangles drawn / oracle");
  const auto& switches = d.at("switches per object-second outside suppression");
  EXPECT_LE(degraded.at("median").get<double>(), kTargetDegradedShare);
  EXPECT_GE(degraded.at("within_target").get<int>(), 20);
  EXPECT_LE(triangles.at("median").get<double>(), kTargetTriangleRatio);
  EXPECT_GE(triangles.at("median").get<double>(), 1.0) << "below the oracle would be degradations";
  // 15 before saccades ended at their landing (saccade_ends_at_landing, 2026-12-07): seed 2012
  // now waits for a suppression it used to take 50-110 ms after a landing, when vision was back
  // (1.34 -> 1.40 times the oracle's triangles; its switches 1.55 -> 0.72 per object-second).
  // 14 then; 16 with the release by regret (release_regret_s, 2026-12-07: 2003 and 2009 come
  // within, 1.39 -> 1.33 and 1.37 -> 1.31). 17 with the saccade's path ahead capped by the path
  // behind (saccade_ahead_of_travelled, 2026-12-07: 2012, 1.37 -> 1.34).
  EXPECT_GE(triangles.at("within_target").get<int>(), 17);
  EXPECT_LE(switches.at("median").get<double>(), kTargetSwitchesPerObjectS);
  // 16 before the landing (18 before the carried habit, which made the carried seeds 2002 and
  // 2014 switch as the head's sweep requires), then all 20. 19 with the release by regret:
  // the carried seed 2002 goes from 0.97 to 1.02 (its triangles 1.70 -> 1.62 times the
  // oracle's; the true gaze itself needs 1.4). 20 again with the saccade's path ahead capped
  // (2002: 1.02 -> 0.97).
  EXPECT_GE(switches.at("within_target").get<int>(), 20);
}

// The carried habit (docs/evaluation.md, "Scenario family", item 10): on a seed whose eyes the
// head carries (2002), the fixations after a run of carried ones are read as carried from
// their landing, so the plugin draws much less beyond the oracle, without visible
// degradations and without switching more than the true gaze itself requires.
TEST(EvalFamily, CarriedHabitWhatIf) {
  const auto dir = scratch();
  const auto member = [&](const std::vector<std::string>& extra, const std::string& name) {
    std::vector<std::string> args{"eval", "family", "--seeds", "2002-2002", "--out", (dir / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = cli(args);
    EXPECT_EQ(r.rc, 0) << r.err;
    return nlohmann::json::parse(read(dir / name / "family.json")).at("members").at(0);
  };
  const nlohmann::json with = member({}, "with"),
                       without = member({"--set", "conditioner.carried_prior_fixations=0"}, "without");
  ASSERT_NE(with.at("scenario").get<std::string>().find("eyes carried"), std::string::npos);
  const auto ratio = [](const nlohmann::json& m) {
    return m.at("audit").at("triangles_in_view").at("drawn_over_oracle").get<double>();
  };
  EXPECT_LT(ratio(with), ratio(without) - 0.5) << "measured 1.69 against 2.39";
  EXPECT_GE(ratio(with), 1.0);
  const nlohmann::json& audit = with.at("audit");
  EXPECT_LE(audit.at("visible_degradations").at("share").get<double>(), kTargetDegradedShare);
  EXPECT_LE(audit.at("switches").at("outside_suppression").at("per_object_second").get<double>(),
            audit.at("switches").at("oracle_outside_suppression").at("per_object_second").get<double>());
}

// --bound: each seed's offline optimum beside its figures. On seed 2002 (eyes carried by the
// head) most of the excess over the oracle is the online policy's not knowing the future:
// measured 1.62 drawn, 1.28 for a policy that knew it at the same switches (never coarser than
// the plugin's perceptual level nor the oracle's), 1.01 with a perfect tracker too
// (docs/evaluation.md, "Scenario family", item 13).
TEST(EvalFamily, BoundSaysWhatKnowingTheFutureWouldSave) {
  const auto dir = scratch();
  const Result r = cli({"eval", "family", "--seeds", "2002", "--bound", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("| triangles / oracle for a better policy: the future known, the same switches |"),
            std::string::npos)
      << r.out;
  const nlohmann::json j = nlohmann::json::parse(read(dir / "family.json"));
  const nlohmann::json& audit = j.at("members").at(0).at("audit");
  const double drawn = audit.at("triangles_in_view").at("drawn_over_oracle").get<double>();
  const double known = audit.at("offline_optimum").at("better_policy").at("over_oracle").get<double>();
  const double perfect = audit.at("offline_optimum").at("perfect_tracker").at("over_oracle").get<double>();
  EXPECT_LT(known, drawn - 0.25);
  EXPECT_LE(known, kTargetTriangleRatio) << "within the target, had the policy known the future";
  EXPECT_GE(perfect, 1.0);
  EXPECT_LT(perfect, 1.05);
  EXPECT_TRUE(
      j.at("distribution").contains("triangles / oracle for a better policy: the future known, the same switches"));

  // At the switch target's pop rate (here more switches than the policy's 0.97 per object-second
  // would allow only a little more): still within the triangle target, so with the future known
  // this seed meets all three targets; the plugin's run does not (1.61 drawn).
  const nlohmann::json& at = audit.at("offline_optimum").at("at_switch_target");
  const double known_at = at.at("better_policy").at("over_oracle").get<double>();
  EXPECT_LE(known_at, kTargetTriangleRatio);
  EXPECT_LE(at.at("better_policy").at("per_object_s").get<double>(), kTargetSwitchesPerObjectS);
  EXPECT_GE(at.at("perfect_tracker").at("over_oracle").get<double>(), 1.0);
  EXPECT_EQ(j.at("within_all_targets").get<int>(), 0);
  EXPECT_EQ(j.at("within_all_targets_known_future").at("better_policy").get<int>(), 1);
  EXPECT_EQ(j.at("within_all_targets_known_future").at("perfect_tracker").get<int>(), 1);
  EXPECT_NE(r.out.find("With the future known, at the switch target's pop rate and never coarser than the oracle: 1 "
                       "/ 1 (a better policy), 1 / 1 (a perfect tracker too)."),
            std::string::npos)
      << r.out;
}

// family.json of `gazelod eval family --seeds 2000-2009 EXTRA --out dir/name`.
nlohmann::json figures(const std::filesystem::path& dir, const std::vector<std::string>& extra,
                       const std::string& name) {
  std::vector<std::string> args{"eval", "family", "--seeds", "2000-2009", "--out", (dir / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const Result r = cli(args);
  EXPECT_EQ(r.rc, 0) << r.err;
  return nlohmann::json::parse(read(dir / name / "family.json"));
}

// What the tracker costs (docs/evaluation.md, "What the tracker costs"): the same seeds with
// the tracker's latency removed draw fewer triangles and switch less, and the run says so.
TEST(EvalFamily, IdealTrackerWhatIf) {
  const auto dir = scratch();
  const nlohmann::json drawn = figures(dir, {}, "drawn"), ideal = figures(dir, {"--ideal", "latency"}, "ideal");
  EXPECT_EQ(ideal.at("settings_changed")[0], "ideal=latency");
  EXPECT_NE(ideal.at("members")[0].at("scenario").get<std::string>().find(" 0 ms "), std::string::npos);
  const auto median = [](const nlohmann::json& j, const char* figure) {
    return j.at("distribution").at(figure).at("median").get<double>();
  };
  for (const char* figure : {"visible degradations (fixation object-frames)", "triangles drawn / oracle",
                             "switches per object-second outside suppression"})
    EXPECT_LT(median(ideal, figure), median(drawn, figure)) << figure;
  EXPECT_TRUE(read(dir / "ideal" / "family.md")
                  .starts_with("<!-- written by: gazelod eval family --seeds 2000-2009 --ideal latency"));
}

// What a calibration error costs (docs/evaluation.md, "What the tracker costs"): beyond the
// plugin's accuracy margin (1.5 deg), the same seeds are drawn coarser than the true gaze
// allows more often, and the run says what it changed.
TEST(EvalFamily, TrackerOffsetWhatIf) {
  const auto dir = scratch();
  const nlohmann::json drawn = figures(dir, {}, "drawn"), off = figures(dir, {"--tracker-offset", "3"}, "off");
  EXPECT_EQ(off.at("settings_changed")[0], "tracker_offset_deg=3");
  EXPECT_NE(off.at("members")[0].at("scenario").get<std::string>().find(" offset 3.00 deg"), std::string::npos);
  const char* degraded = "visible degradations (fixation object-frames)";
  EXPECT_GT(off.at("distribution").at(degraded).at("median").get<double>(),
            2.0 * drawn.at("distribution").at(degraded).at("median").get<double>());
  EXPECT_TRUE(read(dir / "off" / "family.md")
                  .starts_with("<!-- written by: gazelod eval family --seeds 2000-2009 --tracker-offset 3"));
  const Result bad =
      cli({"eval", "family", "--seeds", "2000", "--tracker-offset", "-1", "--out", (dir / "bad").string()});
  EXPECT_NE(bad.rc, 0);
  EXPECT_NE(bad.err.find("--tracker-offset"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace gazelod::cli
