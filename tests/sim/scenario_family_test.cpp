// SPDX-License-Identifier: Apache-2.0
// The scenario family (sim/scenario_family.hpp): every seed gives a scenario the loader
// accepts, the same text for the same seed, and the family spans the ranges it promises.
#include "sim/scenario_family.hpp"
#include "sim/simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace gazelod::sim {
namespace {

const nlohmann::json* effect(const nlohmann::json& sc, const std::string& type) {
  for (const nlohmann::json& e : sc.at("effects"))
    if (e.at("type") == type) return &e;
  return nullptr;
}

TEST(ScenarioFamily, EverySeedLoadsAndIsReproducible) {
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    const FamilyScenario f = family_scenario(seed);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + f.summary);
    Scenario sc;
    ASSERT_NO_THROW(sc = load_scenario_json(f.json, "family")) << f.json;
    EXPECT_EQ(sc.seed, seed);
    EXPECT_EQ(sc.duration_s, 20.0);
    EXPECT_GE(sc.objects.size(), 100u);
    EXPECT_EQ(family_scenario(seed).json, f.json) << "the same seed, the same text";
  }
  EXPECT_NE(family_scenario(1).json, family_scenario(2).json);
  EXPECT_EQ(load_scenario_json(family_scenario(3, 2.5).json, "short").duration_s, 2.5);
}

TEST(ScenarioFamily, SpansTheHeadGazeTrackerAndFieldRanges) {
  std::set<std::string> heads, displays, fields;
  int vor = 0, carried = 0, pursuits = 0, walks = 0;
  double rate_lo = 1e9, rate_hi = 0, lat_lo = 1e9, lat_hi = 0, noise_lo = 1e9, noise_hi = 0;
  double pursuit_lo = 1e9, pursuit_hi = 0;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    const FamilyScenario f = family_scenario(seed);
    const nlohmann::json sc = nlohmann::json::parse(f.json);
    heads.insert(f.summary.substr(0, f.summary.find_first_of(", ")));
    displays.insert(sc.at("display").at("preset").get<std::string>());
    fields.insert(f.summary.substr(f.summary.rfind(", ") + 2));
    if (f.summary.find("eyes carried") != std::string::npos) ++carried;
    if (effect(sc, "vor")) ++vor;
    if (sc.at("scene").at("generators")[0].at("forward_speed_m_s").get<double>() > 0) ++walks;
    const double rate = effect(sc, "tracker_rate")->at("rate_hz");
    EXPECT_EQ(sc.at("display").at("eye_tracking_hz").get<double>(), rate) << "the display's tracker rate too";
    rate_lo = std::min(rate_lo, rate), rate_hi = std::max(rate_hi, rate);
    const double lat = effect(sc, "tracker_latency")->at("latency_ms");
    lat_lo = std::min(lat_lo, lat), lat_hi = std::max(lat_hi, lat);
    const double noise = effect(sc, "tracker_noise")->at("std_deg");
    noise_lo = std::min(noise_lo, noise), noise_hi = std::max(noise_hi, noise);
    if (effect(sc, "smooth_pursuit")) {
      ++pursuits;
      // The target's angular speed at its distance, as the summary states it.
      const nlohmann::json& t = sc.at("scene").at("objects")[0];
      const double speed = std::abs(t.at("velocity_m_s")[0].get<double>()) / -t.at("position_m")[2].get<double>() *
                           180.0 / 3.14159265358979;
      pursuit_lo = std::min(pursuit_lo, speed), pursuit_hi = std::max(pursuit_hi, speed);
    }
  }
  EXPECT_EQ(heads, (std::set<std::string>{"still", "sweeps", "sweeps+turns", "walk"}));
  EXPECT_EQ(displays.size(), 6u);
  EXPECT_EQ(fields, (std::set<std::string>{"near clutter", "open field", "deep field"}));
  EXPECT_GT(vor, 100);
  EXPECT_GT(carried, 20);
  EXPECT_GT(walks, 40);
  EXPECT_GT(pursuits, 120);
  EXPECT_LT(pursuits, 240);
  const auto spans = [](double lo, double hi, double min, double max, double margin, const char* what) {
    EXPECT_GE(lo, min - 1e-9) << what;
    EXPECT_LE(hi, max + 1e-9) << what;
    EXPECT_LT(lo, min + margin) << what << ": the low end is reached";
    EXPECT_GT(hi, max - margin) << what << ": the high end is reached";
  };
  spans(rate_lo, rate_hi, 60.0, 250.0, 10.0, "tracker rate");
  spans(lat_lo, lat_hi, 5.0, 80.0, 5.0, "latency");
  spans(noise_lo, noise_hi, 0.2, 1.5, 0.1, "noise");
  spans(pursuit_lo, pursuit_hi, 5.0, 30.0, 2.0, "pursuit speed");
}

// The what-if of `gazelod eval family --ideal`: only the named tracker values change; every
// other draw of the seed (head, eyes, blinks, display, field) stays as it was.
TEST(ScenarioFamily, IdealTrackerChangesOnlyTheTracker) {
  const auto without_tracker = [](nlohmann::json sc) {
    nlohmann::json kept = nlohmann::json::array();
    for (const nlohmann::json& e : sc.at("effects"))
      if (!e.at("type").get<std::string>().starts_with("tracker_")) kept.push_back(e);
    sc["effects"] = kept;
    sc["display"].erase("eye_tracking_hz");
    return sc;
  };
  for (std::uint64_t seed = 2000; seed < 2020; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const nlohmann::json drawn = nlohmann::json::parse(family_scenario(seed).json);
    const FamilyScenario f = family_scenario(seed, 20.0, IdealTracker{true, true, true});
    const nlohmann::json ideal = nlohmann::json::parse(f.json);
    ASSERT_NO_THROW((void)load_scenario_json(f.json, "ideal"));
    EXPECT_EQ(without_tracker(ideal), without_tracker(drawn));
    EXPECT_EQ(effect(ideal, "tracker_latency")->at("latency_ms").get<double>(), 0.0);
    EXPECT_EQ(effect(ideal, "tracker_noise")->at("std_deg").get<double>(), 0.0);
    EXPECT_EQ(effect(ideal, "tracker_rate")->at("rate_hz").get<double>(), 1000.0);
    EXPECT_EQ(ideal.at("display").at("eye_tracking_hz").get<double>(), 1000.0);
    EXPECT_NE(f.summary.find("1000 Hz 0 ms 0.00 deg"), std::string::npos) << f.summary;
    // One part alone leaves the other two as drawn.
    const nlohmann::json late =
        nlohmann::json::parse(family_scenario(seed, 20.0, IdealTracker{true, false, false}).json);
    EXPECT_EQ(effect(late, "tracker_latency")->at("latency_ms").get<double>(), 0.0);
    EXPECT_EQ(*effect(late, "tracker_noise"), *effect(drawn, "tracker_noise"));
    EXPECT_EQ(*effect(late, "tracker_rate"), *effect(drawn, "tracker_rate"));
  }
}

// The calibration-error what-if (eval family --tracker-offset) adds one calibration_offset
// effect of that size, in a direction of the seed's own, and changes nothing else.
TEST(ScenarioFamily, CalibrationOffsetAddsOnlyTheOffset) {
  int pointing_right = 0;
  for (std::uint64_t seed = 2000; seed < 2020; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::string drawn_text = family_scenario(seed).json;
    EXPECT_EQ(family_scenario(seed, 20.0, {}, 0.0).json, drawn_text);
    const FamilyScenario f = family_scenario(seed, 20.0, {}, 1.5);
    ASSERT_NO_THROW((void)load_scenario_json(f.json, "offset"));
    nlohmann::json offset = nlohmann::json::parse(f.json);
    const nlohmann::json* e = effect(offset, "calibration_offset");
    ASSERT_NE(e, nullptr);
    const double yaw = e->at("yaw_deg").get<double>(), pitch = e->at("pitch_deg").get<double>();
    EXPECT_NEAR(std::hypot(yaw, pitch), 1.5, 0.002);
    pointing_right += yaw > 0.0 ? 1 : 0;
    nlohmann::json kept = nlohmann::json::array();
    for (const nlohmann::json& x : offset.at("effects"))
      if (x.at("type") != "calibration_offset") kept.push_back(x);
    offset["effects"] = kept;
    EXPECT_EQ(offset, nlohmann::json::parse(drawn_text));
    EXPECT_NE(f.summary.find(" offset 1.50 deg"), std::string::npos) << f.summary;
  }
  // Directions of the seeds' own, not one for all.
  EXPECT_GT(pointing_right, 2);
  EXPECT_LT(pointing_right, 18);
}

TEST(ScenarioFamily, IdealTrackerNames) {
  IdealTracker t;
  ASSERT_TRUE(parse_ideal_tracker("noise,latency", t));
  EXPECT_TRUE(t.latency && t.noise && !t.rate);
  ASSERT_TRUE(parse_ideal_tracker("all", t));
  EXPECT_TRUE(t.latency && t.noise && t.rate);
  ASSERT_TRUE(parse_ideal_tracker("", t));
  EXPECT_FALSE(t.any());
  ASSERT_TRUE(parse_ideal_tracker("rate", t));
  for (const char* bad : {"latency,", ",noise", "speed", "all,noise", "LATENCY", "latency,,rate"}) {
    EXPECT_FALSE(parse_ideal_tracker(bad, t)) << bad;
    EXPECT_TRUE(t.rate && !t.latency && !t.noise) << bad << ": left as it was";
  }
}

}  // namespace
}  // namespace gazelod::sim
