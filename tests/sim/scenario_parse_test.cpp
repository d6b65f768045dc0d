// SPDX-License-Identifier: Apache-2.0
// Scenario loading: the default, explicit displays and scenes, and every error path naming
// its JSON path and source.
#include "sim/simulator.hpp"
#include "tests/sim/sim_test_util.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

namespace gazelod::sim {
namespace {

using test::base_scenario;
using ::testing::HasSubstr;

// Loads `j` and returns the error message ("" when it loads).
std::string error_of(const nlohmann::json& j) {
  try {
    (void)load_scenario_json(j.dump(), "bad.json");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioParse, DefaultScenarioIsAnEyeTrackedHmdWithAFieldOfFourLodObjects) {
  const Scenario sc = load_scenario_json(default_scenario_json(), "<default>");
  EXPECT_EQ(sc.version, 1);
  EXPECT_GT(sc.display.eye_tracking_hz, 0.0);
  EXPECT_EQ(sc.display.view_count, 2);
  EXPECT_NEAR(sc.duration_s, 20.0, 5.0);
  EXPECT_DOUBLE_EQ(sc.frame_rate_hz, 90.0);
  EXPECT_DOUBLE_EQ(sc.display.refresh_hz, 90.0);
  ASSERT_GE(sc.objects.size(), 150u);
  for (const SceneObject& o : sc.objects) {
    ASSERT_EQ(o.lods.size(), 4u) << o.name;
    EXPECT_EQ(o.lods[0].detail, 0.0);
    for (std::size_t l = 1; l < 4; ++l) {
      const double ratio = double(o.lods[l - 1].triangles) / o.lods[l].triangles;
      EXPECT_NEAR(ratio, 4.0, 0.1) << o.name << " level " << l;
      EXPECT_GT(o.lods[l].detail, 0.0);
      if (l > 1) {
        EXPECT_LT(o.lods[l].detail, o.lods[l - 1].detail) << "coarser levels keep less";
      }
      EXPECT_EQ(o.lods[l].detail_kind, lod::DetailKind::removed_cycles_per_diameter);
    }
  }
  EXPECT_LT(sc.head_path.velocity_m_s.z, 0.0) << "a forward path through the field";
  std::set<std::string> types;
  for (const EffectSpec& e : sc.effects) types.insert(e.type);
  for (const char* t : {"head_sweep", "saccades", "smooth_pursuit"}) EXPECT_TRUE(types.count(t)) << t;
}

TEST(ScenarioParse, GeneratedFieldLiesInsideItsBoxAndFollowsTheSeed) {
  nlohmann::json j = base_scenario();
  j["scene"] = {{"generators",
                 {{{"type", "random_field"},
                   {"count", 50},
                   {"min_m", {-1, -2, -30}},
                   {"max_m", {1, 2, -10}},
                   {"radius_min_m", 0.1},
                   {"radius_max_m", 0.2},
                   {"forward_speed_m_s", 2.0}}}}};
  const Scenario a = load_scenario_json(j.dump(), "a");
  ASSERT_EQ(a.objects.size(), 50u);
  for (const SceneObject& o : a.objects) {
    EXPECT_GE(o.position_m.x, -1.0);
    EXPECT_LE(o.position_m.x, 1.0);
    EXPECT_GE(o.position_m.z, -30.0);
    EXPECT_LE(o.position_m.z, -10.0);
    EXPECT_GE(o.radius_m, 0.1);
    EXPECT_LE(o.radius_m, 0.2);
  }
  EXPECT_EQ(a.head_path.velocity_m_s, glm::dvec3(0, 0, -2.0));
  j["seed"] = 43;
  const Scenario b = load_scenario_json(j.dump(), "b");
  EXPECT_NE(a.objects[0].position_m, b.objects[0].position_m);
}

TEST(ScenarioParse, ExplicitDisplayInDegrees) {
  nlohmann::json j = base_scenario();
  j["display"] = {{"width_px", 1000}, {"height_px", 800},
                  {"views", 2},       {"fov_deg", {{"left", -45}, {"right", 40}, {"up", 30}, {"down", -35}}},
                  {"refresh_hz", 60}, {"eye_tracking_hz", 250}};
  j.erase("duration_s");
  const Scenario sc = load_scenario_json(j.dump(), "d");
  EXPECT_EQ(sc.display.view_count, 2);
  EXPECT_EQ(sc.display.views[0].width_px, 1000);
  EXPECT_NEAR(sc.display.views[0].fov.angle_left_rad, -45.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(sc.display.views[0].fov.angle_up_rad, 30.0 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(sc.frame_rate_hz, 60.0) << "frame rate defaults to the display's refresh";
  EXPECT_DOUBLE_EQ(sc.display.eye_tracking_hz, 250.0);
}

TEST(ScenarioParse, RuntimeOptions) {
  nlohmann::json j = base_scenario();
  j["runtime"] = {{"eye_gaze_supported", false}, {"gaze_delivery", "sample_time_zero"}, {"paced", false}};
  const Scenario sc = load_scenario_json(j.dump(), "r");
  EXPECT_FALSE(sc.runtime.eye_gaze_supported);
  EXPECT_EQ(sc.runtime.gaze_delivery, GazeDelivery::sample_time_zero);
  EXPECT_FALSE(sc.runtime.paced);
}

// A preset without an eye tracker offers no eye gaze unless the scenario says so; a custom
// display (the project's own test rigs) and a tracked preset do. Every display had a perfect
// tracker, so `compare --hmd quest3` reported gaze-contingent savings.
TEST(ScenarioParse, EyeGazeFollowsThePresetsTracker) {
  nlohmann::json j = base_scenario();
  j.erase("runtime");
  j["display"] = "quest3";
  EXPECT_FALSE(load_scenario_json(j.dump(), "q").runtime.eye_gaze_supported);
  j["display"] = {{"preset", "index"}};
  EXPECT_FALSE(load_scenario_json(j.dump(), "i").runtime.eye_gaze_supported);
  j["display"] = {{"preset", "index"}, {"eye_tracking_hz", 120.0}};
  EXPECT_TRUE(load_scenario_json(j.dump(), "i+").runtime.eye_gaze_supported);
  j["display"] = "questpro";
  EXPECT_TRUE(load_scenario_json(j.dump(), "p").runtime.eye_gaze_supported);
  j["display"] = "quest3";
  j["runtime"] = {{"eye_gaze_supported", true}};  // what if it had one: as the scenario says
  EXPECT_TRUE(load_scenario_json(j.dump(), "q+").runtime.eye_gaze_supported);
}

// The gaze effects compose in list order; the orders that undo one another are refused with
// both places named (they ran without a word: saccades after the reflex overwrote it).
TEST(ScenarioParse, GazeEffectsInAnOrderThatUndoesThemAreRefused) {
  const auto error_of = [](const nlohmann::json& effects) -> std::string {
    try {
      (void)load_scenario_json(base_scenario(effects).dump(), "o.json");
    } catch (const ScenarioError& e) {
      return e.what();
    }
    return "";
  };
  const nlohmann::json saccades = {{"type", "saccades"}}, vor = {{"type", "vor"}},
                       pursuit = {{"type", "smooth_pursuit"}, {"object", "target"}};
  EXPECT_EQ(error_of({vor, saccades}),
            "o.json: effects[1]: saccades must come before vor (effects[0]), which turns them into saccades of an "
            "eye holding the world; list vor after it");
  EXPECT_EQ(error_of({saccades, pursuit, vor}),
            "o.json: effects[2]: vor must come before smooth_pursuit (effects[1]), which wins while it is active; "
            "list smooth_pursuit after it");
  EXPECT_EQ(error_of({saccades, vor, pursuit}), "");
  EXPECT_EQ(error_of({saccades, pursuit}), "");  // no reflex: nothing to order
}

// A sweep's peak rate is bounded as head_turn's rate is (300 deg/s): the seam from both sides.
TEST(ScenarioParse, HeadSweepPeakRateIsBounded) {
  const auto error_of = [](double amplitude_deg, double period_s) -> std::string {
    const nlohmann::json sweep = {
        {"type", "head_sweep"}, {"pitch_amplitude_deg", amplitude_deg}, {"pitch_period_s", period_s}};
    try {
      (void)load_scenario_json(base_scenario({sweep}).dump(), "s.json");
    } catch (const ScenarioError& e) {
      return e.what();
    }
    return "";
  };
  const double period_at_300 = 2.0 * M_PI * 30.0 / 300.0;  // 30 deg: 300 deg/s at this period
  EXPECT_EQ(error_of(30.0, period_at_300 * (1 + 1e-9)), "");
  EXPECT_EQ(error_of(30.0, period_at_300 * 0.99),
            "s.json: effects[0].pitch_period_s: gives a peak head rate of 303 deg/s (amplitude x 2 pi / period), "
            "more than 300");
}

TEST(ScenarioParse, ToJsonRoundTrips) {
  const Scenario a = load_scenario_json(default_scenario_json(), "<default>");
  const Scenario b = load_scenario_json(scenario_to_json(a), "<written>");
  EXPECT_EQ(b.display.name, a.display.name);
  EXPECT_EQ(b.display.views[0].fov.angle_left_rad, a.display.views[0].fov.angle_left_rad);
  EXPECT_EQ(b.duration_s, a.duration_s);
  EXPECT_EQ(b.seed, a.seed);
  ASSERT_EQ(b.objects.size(), a.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(b.objects[i].name, a.objects[i].name);
    EXPECT_EQ(b.objects[i].position_m, a.objects[i].position_m);
    EXPECT_EQ(b.objects[i].radius_m, a.objects[i].radius_m);
    ASSERT_EQ(b.objects[i].lods.size(), a.objects[i].lods.size());
    EXPECT_EQ(b.objects[i].lods.back().detail, a.objects[i].lods.back().detail);
  }
  ASSERT_EQ(b.effects.size(), a.effects.size());
  for (std::size_t i = 0; i < a.effects.size(); ++i) EXPECT_EQ(b.effects[i].type, a.effects[i].type);
  EXPECT_EQ(b.head_path.velocity_m_s, a.head_path.velocity_m_s);
  // And the same simulation.
  Simulator sa(a), sb(b);
  for (std::int64_t t = 0; t < 3'000'000'000; t += 77'777'777)
    EXPECT_EQ(sa.tracker_at(t).direction, sb.tracker_at(t).direction);
}

struct ErrorCase {
  const char* what;
  nlohmann::json (*make)();
  const char* expected;  // must appear in the message
};

const ErrorCase kErrors[] = {
    {"unknown effect",
     [] {
       return base_scenario(
           {{{"type", "head_sweep"}}, {{"type", "tracker_noise"}, {"std_deg", 1}}, {{"type", "wobble"}}});
     },
     "bad.json: effects[2].type: unknown effect \"wobble\""},
    {"unknown effect key",
     [] {
       return base_scenario({{{"type", "head_sweep"}, {"amplitude_deg", 3}}});
     },
     "bad.json: effects[0].amplitude_deg: unknown key"},
    {"out of range",
     [] {
       return base_scenario({{{"type", "tracker_noise"}, {"std_deg", 1}},
                             {{"type", "head_turn"}, {"rate_deg_s", 400}, {"duration_s", 1}}});
     },
     "effects[1].rate_deg_s: must be in [-300, 300], got 400"},
    {"type mismatch",
     [] {
       return base_scenario({{{"type", "tracker_noise"}, {"std_deg", "big"}}});
     },
     "effects[0].std_deg: expected a number, got string"},
    {"missing parameter",
     [] {
       return base_scenario({{{"type", "tracker_latency"}}});
     },
     "effects[0].latency_ms: missing"},
    {"effect without type",
     [] {
       return base_scenario({{{"latency_ms", 3}}});
     },
     "effects[0].type: missing"},
    {"effect not an object", [] { return base_scenario({3}); }, "effects[0]: expected an object, got number"},
    {"unknown pursuit object",
     [] {
       return base_scenario({{{"type", "smooth_pursuit"}, {"object", "ghost"}}});
     },
     "effects[0].object: no scene object named \"ghost\""},
    {"end before start",
     [] {
       return base_scenario({{{"type", "saccades"}, {"start_s", 2}, {"end_s", 1}}});
     },
     "effects[0].end_s: must be after start_s"},
    {"blink longer than period",
     [] {
       return base_scenario({{{"type", "blinks"}, {"rate_per_min", 120}, {"duration_ms", 600}}});
     },
     "effects[0].duration_ms"},
    {"bad axis",
     [] {
       return base_scenario({{{"type", "head_turn"}, {"rate_deg_s", 10}, {"duration_s", 1}, {"axis", "roll"}}});
     },
     "effects[0].axis: expected \"yaw\" or \"pitch\""},
    {"effects not an array",
     [] {
       auto j = base_scenario();
       j["effects"] = {{"type", "x"}};
       return j;
     },
     "bad.json: effects: expected an array"},
    {"missing version",
     [] {
       auto j = base_scenario();
       j.erase("version");
       return j;
     },
     "bad.json: version: missing"},
    {"wrong version",
     [] {
       auto j = base_scenario();
       j["version"] = 2;
       return j;
     },
     "version: unsupported version 2"},
    {"unknown top-level key",
     [] {
       auto j = base_scenario();
       j["durration_s"] = 3;
       return j;
     },
     "bad.json: durration_s: unknown key"},
    {"negative duration",
     [] {
       auto j = base_scenario();
       j["duration_s"] = -1;
       return j;
     },
     "duration_s: must be in"},
    {"seed not an integer",
     [] {
       auto j = base_scenario();
       j["seed"] = 1.5;
       return j;
     },
     "seed: expected a non-negative integer"},
    {"unknown preset",
     [] {
       auto j = base_scenario();
       j["display"] = "rift9";
       return j;
     },
     "display: unknown display preset \"rift9\""},
    {"display pixels missing",
     [] {
       auto j = base_scenario();
       j["display"] = {{"height_px", 100}, {"fov_h_deg", 90}, {"fov_v_deg", 90}};
       return j;
     },
     "display.width_px: missing"},
    {"display fov inverted",
     [] {
       auto j = base_scenario();
       j["display"] = {{"width_px", 100},
                       {"height_px", 100},
                       {"fov_deg", {{"left", 40}, {"right", -40}, {"up", 30}, {"down", -30}}}};
       return j;
     },
     "display: view 0: horizontal FOV"},
    {"display fov out of range",
     [] {
       auto j = base_scenario();
       j["display"] = {{"width_px", 100},
                       {"height_px", 100},
                       {"fov_deg", {{"left", -95}, {"right", 40}, {"up", 30}, {"down", -30}}}};
       return j;
     },
     "display.fov_deg.left: must be in [-90, 90]"},
    {"lod detail negative",
     [] {
       auto j = base_scenario();
       j["scene"]["objects"][0]["lods"] = {{{"triangles", 10}}, {{"triangles", 5}, {"detail", -2}}};
       return j;
     },
     "scene.objects[0].lods[1].detail: must be in"},
    {"lod detail kind",
     [] {
       auto j = base_scenario();
       j["scene"]["objects"][0]["lods"][0]["detail_kind"] = "pixels";
       return j;
     },
     "scene.objects[0].lods[0].detail_kind"},
    {"object position not a vector",
     [] {
       auto j = base_scenario();
       j["scene"]["objects"][0]["position_m"] = {1, 2};
       return j;
     },
     "scene.objects[0].position_m: expected [x, y, z]"},
    {"object position element",
     [] {
       auto j = base_scenario();
       j["scene"]["objects"][0]["position_m"] = {1, "a", 2};
       return j;
     },
     "scene.objects[0].position_m[1]: expected a number, got string"},
    {"duplicate object names",
     [] {
       auto j = base_scenario();
       j["scene"]["objects"].push_back(j["scene"]["objects"][0]);
       return j;
     },
     "two objects are named \"target\""},
    {"unknown generator",
     [] {
       auto j = base_scenario();
       j["scene"]["generators"] = {{{"type", "forest"}}};
       return j;
     },
     "scene.generators[0].type: unknown generator \"forest\""},
    {"generator box inverted",
     [] {
       auto j = base_scenario();
       j["scene"]["generators"] = {{{"type", "random_field"}, {"min_m", {0, 0, 0}}, {"max_m", {1, -1, 1}}}};
       return j;
     },
     "scene.generators[0].max_m"},
    {"unknown gaze delivery",
     [] {
       auto j = base_scenario();
       j["runtime"] = {{"gaze_delivery", "sometimes"}};
       return j;
     },
     "runtime.gaze_delivery: unknown \"sometimes\""},
    {"runtime flag type",
     [] {
       auto j = base_scenario();
       j["runtime"] = {{"paced", 1}};
       return j;
     },
     "runtime.paced: expected true or false, got number"},
    {"top level not an object",
     [] {
       return nlohmann::json::array({1, 2});
     },
     "bad.json: (top level): expected an object"},
};

TEST(ScenarioParse, EveryErrorNamesItsJsonPath) {
  for (const ErrorCase& c : kErrors) {
    SCOPED_TRACE(c.what);
    const std::string msg = error_of(c.make());
    EXPECT_THAT(msg, HasSubstr(c.expected));
    EXPECT_THAT(msg, HasSubstr("bad.json"));
  }
}

TEST(ScenarioParse, SyntaxErrorNamesLineAndColumn) {
  try {
    (void)load_scenario_json("{\n  \"version\": 1,\n  \"display\": questpro\n}", "s.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr("s.json:3:"));
    EXPECT_THAT(e.what(), HasSubstr("JSON syntax error"));
  }
}

TEST(ScenarioParse, KeyGivenTwiceIsRefusedWithItsPath) {
  // nlohmann would keep the last value silently: a 2 s scenario would run for 3.
  try {
    (void)load_scenario_json(R"({"version": 1, "display": "questpro", "duration_s": 2, "duration_s": 3})", "s.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_STREQ(e.what(), "s.json: duration_s: the key appears twice in one object (which one counts is undefined)");
  }
  try {
    (void)load_scenario_json(R"({"version": 1, "display": "questpro", "effects": [{"type": "saccades"},
                                {"type": "blinks", "rate_per_min": 5, "rate_per_min": 50}]})",
                             "s.json");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr("s.json: effects[1].rate_per_min: the key appears twice"));
  }
}

TEST(ScenarioParse, FileErrors) {
  EXPECT_THROW((void)load_scenario_file("/nonexistent/dir/none.json"), ScenarioError);
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/parse_test_bad.json";
  std::ofstream(path)
      << R"({"version": 1, "display": "questpro", "effects": [{"type": "blinks", "rate_per_min": -1}]})";
  try {
    (void)load_scenario_file(path);
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path + ": effects[0].rate_per_min: must be in"));
  }
}

TEST(ScenarioParse, ExampleScenariosLoad) {
  for (const char* name : {"still.json", "all_effects.json", "fast_turn.json"}) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW((void)load_scenario_file(std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/" + name));
  }
}

}  // namespace
}  // namespace gazelod::sim
