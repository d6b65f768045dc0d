// SPDX-License-Identifier: Apache-2.0
// The scenario family (sim/scenario_family.hpp): every seed gives a scenario the loader
// accepts, the same text for the same seed, and the family spans the ranges it promises.
#include "sim/scenario_family.hpp"
#include "sim/simulator.hpp"

#include <gtest/gtest.h>
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

}  // namespace
}  // namespace gazelod::sim
