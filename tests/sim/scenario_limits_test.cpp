// SPDX-License-Identifier: Apache-2.0
// The limits on a scenario as a whole (sim/scene_json.hpp, docs/hardening.md "Scenario
// limits") and the checks that `gazelod run`, the plugin's registration and the simulated
// runtime make, all refused while parsing with the JSON path: a memory bomb of generators, a
// chain the plugin refuses, a one-view display, a duration under one frame, tracker latencies
// adding up past 1000 ms, deep nesting, text too large.
#include "lod/display.hpp"
#include "lod/object_set.hpp"
#include "sim/scene_json.hpp"
#include "sim/simulator.hpp"
#include "tests/sim/sim_test_util.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace gazelod::sim {
namespace {

using test::base_scenario;
using ::testing::HasSubstr;

std::string error_of(const std::string& text) {
  try {
    (void)load_scenario_json(text, "bad.json");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}
std::string error_of(const nlohmann::json& j) {
  return error_of(j.dump());
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

nlohmann::json field(std::int64_t count, int lods, const std::string& prefix) {
  return {{"type", "random_field"}, {"count", count}, {"lod_count", lods}, {"name_prefix", prefix}};
}

TEST(ScenarioLimits, ManyLargeGeneratorsAreRefusedBeforeAnythingIsAllocated) {
  // The report's file: 50 generators of 1e6 objects and 16 levels each (~1.5 KB of JSON).
  nlohmann::json j = base_scenario();
  nlohmann::json gens = nlohmann::json::array();
  for (int i = 0; i < 50; ++i)
    gens.push_back(field(1'000'000, 16, std::string("g").append(std::to_string(i)).append("_")));
  j["scene"] = {{"generators", gens}};
  const long before = peak_rss_kib();
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = error_of(j);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_THAT(msg,
              HasSubstr("bad.json: scene.generators[0].count: must keep the LOD levels in all <= 4000000 (0 before)"));
  EXPECT_THAT(msg, HasSubstr("got 1000000 x 16 = 16000000 levels"));
  EXPECT_LT(seconds, 1.0);
  EXPECT_LT(peak_rss_kib() - before, 64 * 1024) << "the objects were made before the limit was checked";
}

TEST(ScenarioLimits, ObjectsInAllLevelsInAllAndMemory) {
  nlohmann::json j = base_scenario();  // one explicit object
  j["scene"]["generators"] = {field(1'000'000, 1, "a")};
  EXPECT_THAT(error_of(j), HasSubstr("scene.generators[0].count: must be <= 999999 objects (a scenario has at most "
                                     "1000000 objects in all, 1 before), got 1000000"));
  j["scene"]["generators"] = {field(600'000, 4, "a"), field(500'000, 4, "b")};
  EXPECT_THAT(error_of(j), HasSubstr("scene.generators[1].count: must be <= 399999 objects"));
  j["scene"]["generators"] = {field(200'000, 4, "a"), field(100'000, 4, "b")};
  EXPECT_EQ(load_scenario_json(j.dump(), "ok.json").objects.size(), 300'001u);
  // Memory: long names.
  j["scene"] = {{"generators", {field(100'000, 1, std::string(20'000, 'n'))}}};
  EXPECT_THAT(error_of(j), HasSubstr("scene.generators[0].count: must keep the scenario's estimated memory <= 1 GiB"));
}

TEST(ScenarioLimits, TheChainChecksOfThePluginWithTheirPath) {
  auto with_lods = [](nlohmann::json lods) {
    nlohmann::json j = base_scenario();
    j["scene"]["objects"][0]["lods"] = std::move(lods);
    return j;
  };
  nlohmann::json many = nlohmann::json::array();
  for (int k = 0; k < 256; ++k) many.push_back({{"triangles", 10}, {"detail", k == 0 ? 0.0 : 1000.0 / k}});
  EXPECT_THAT(error_of(with_lods(many)),
              HasSubstr("bad.json: scene.objects[0].lods: a chain needs 1 to 255 levels, got 256"));
  many.erase(many.size() - 1);
  EXPECT_EQ(error_of(with_lods(many)), "") << "255 levels are fine";
  EXPECT_THAT(error_of(with_lods(
                  {{{"triangles", 100}}, {{"triangles", 50}, {"detail", 4}}, {{"triangles", 20}, {"detail", 9}}})),
              HasSubstr("scene.objects[0].lods[2]: must remove no finer detail than level 1"));
  EXPECT_THAT(error_of(with_lods({{{"triangles", 100}, {"detail_kind", "geometric_error_m"}},
                                  {{"triangles", 50}, {"detail_kind", "geometric_error_m"}, {"detail", 0}}})),
              HasSubstr("scene.objects[0].lods[1]: detail must be finite and > 0, got 0"));
  EXPECT_THAT(error_of(with_lods(
                  {{{"triangles", 100}}, {{"triangles", 50}, {"detail_kind", "geometric_error_m"}, {"detail", 1}}})),
              HasSubstr("scene.objects[0].lods[1]: detail kind differs from level 0"));
  EXPECT_THAT(error_of(with_lods({{{"triangles", 100}, {"detail_kind", "geometric_error_m"}},
                                  {{"triangles", 50}, {"detail_kind", "geometric_error_m"}, {"detail", 1e-31}}})),
              HasSubstr("scene.objects[0].lods[1]: detail 1e-31 gives a weight of 1e+31"));
  // Every accepted chain is one the plugin registers.
  const Scenario sc = load_scenario_json(default_scenario_json(), "<default>");
  for (const SceneObject& o : sc.objects) ASSERT_EQ(lod::validate_chain(o.lods), "") << o.name;
}

TEST(ScenarioLimits, DisplaysNeedTwoViewsAndDescribedFovLimits) {
  nlohmann::json j = base_scenario();
  j["display"] = {{"width_px", 1000}, {"height_px", 800}, {"views", 1}, {"fov_h_deg", 90}, {"fov_v_deg", 90}};
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: display.views: must be 2 (gazelod's plugin uses the stereo view "
                                     "configuration"));
  EXPECT_THAT(error_of(j), HasSubstr("got 1"));
  j["display"] = "desktop";
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: display: the preset \"desktop\" has 1 view"));
  j["display"] = {{"preset", "desktop"}};
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: display.preset: must be 2"));
  j["display"] = {{"preset", "desktop"}, {"views", 2}};
  EXPECT_EQ(error_of(j), "") << "a desktop preset made stereo";
  // The described-FOV rule of lod::validate_described_view, also in `gazelod thresholds`.
  j["display"] = {{"width_px", 100},
                  {"height_px", 100},
                  {"fov_deg", {{"left", -89.9}, {"right", 89.9}, {"up", 30}, {"down", -30}}}};
  EXPECT_THAT(error_of(j), HasSubstr("display.fov_deg: horizontal FOV must be in [0.001, 179] deg, got 179.8"));
  j["display"] = {{"width_px", 100}, {"height_px", 100}, {"fov_h_deg", 179}, {"fov_v_deg", 0.001}};
  EXPECT_EQ(error_of(j), "") << "the limits themselves are valid";
  j["display"]["fov_h_deg"] = 179.5;
  EXPECT_THAT(error_of(j), HasSubstr("display.fov_h_deg: must be in [0.001, 179], got 179.5"));
  EXPECT_EQ(lod::kMaxFovDeg, 179.0);
}

TEST(ScenarioLimits, DurationOfAtLeastOneFrame) {
  nlohmann::json j = base_scenario();
  j["frame_rate_hz"] = 90;
  j["duration_s"] = 0.005;
  EXPECT_THAT(error_of(j),
              HasSubstr("bad.json: duration_s: must be at least one frame (1 / 90 Hz = 0.0111111 s), got 0.005"));
  j["duration_s"] = 0.0112;
  EXPECT_EQ(error_of(j), "");
  // The range message as the scenario README writes it.
  j["duration_s"] = 2e6;
  EXPECT_THAT(error_of(j), HasSubstr("duration_s: must be in [0.001, 1e6], got 2e6"));
}

TEST(ScenarioLimits, TrackerLatenciesTogetherAtMost1000Ms) {
  nlohmann::json j = base_scenario({{{"type", "tracker_latency"}, {"latency_ms", 600}},
                                    {{"type", "tracker_noise"}, {"std_deg", 0.1}},
                                    {{"type", "tracker_latency"}, {"latency_ms", 600}}});
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: effects[2]: the tracker latency of all effects together must be <= "
                                     "1000 ms, got 1200 ms"));
  j["effects"][2]["latency_ms"] = 400;
  EXPECT_EQ(error_of(j), "");
}

TEST(ScenarioLimits, EffectsNestingAndSize) {
  nlohmann::json j = base_scenario();
  j["effects"] = nlohmann::json::array();
  for (std::size_t i = 0; i <= kMaxEffects; ++i) j["effects"].push_back({{"type", "tracker_noise"}, {"std_deg", 0.1}});
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: effects: must have at most 256 effects, got 257"));
  // Nesting: refused while parsing, however deep.
  const std::string deep = "{\"version\": 1, \"x\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}";
  EXPECT_THAT(error_of(deep), HasSubstr("bad.json: JSON nesting must be at most 64 levels"));
  // A number past a double's range: located, not nlohmann's raw text.
  EXPECT_THAT(error_of(std::string("{\"version\": 1,\n  \"frame_rate_hz\": 1e999}")),
              HasSubstr("bad.json:2:20: the number 1e999 is past the range of a double"));
  // Size.
  const std::string big = "{\"version\": 1, \"name\": \"" + std::string(kMaxScenarioBytes, 'x') + "\"}";
  EXPECT_THAT(error_of(big), HasSubstr("bad.json: (top level): must be at most 64 MiB of JSON, got 64 MiB"));
}

TEST(ScenarioLimits, FilesThatAreNotScenarios) {
  const auto expect_error = [](const std::string& path, const std::string& what) {
    try {
      (void)load_scenario_file(path);
      ADD_FAILURE() << path << " loaded";
    } catch (const ScenarioError& e) {
      EXPECT_THAT(e.what(), HasSubstr(what));
    }
  };
  expect_error(std::string(GAZELOD_SOURCE_DIR) + "/sim", "/sim: is a directory, not a scenario file");
  expect_error("/dev/zero", "/dev/zero: is not a regular file");
  expect_error("/nonexistent/s.json", "/nonexistent/s.json: cannot open the scenario file: No such file or directory");
}

TEST(ScenarioLimits, ReplayedTracesCountAgainstMemory) {
  // A sparse file: big on paper, no disk used.
  const std::string path = std::string(GAZELOD_BINARY_DIR) + "/tests/sim/limits_huge_head.csv";
  { std::ofstream(path) << "t_ns,gaze_x,gaze_y,gaze_z,head_qw,head_qx,head_qy,head_qz\n"; }
  std::filesystem::resize_file(path, std::uintmax_t{1} << 29);  // 512 MiB: 2 GiB estimated
  nlohmann::json j = base_scenario({{{"type", "head_track"}, {"file", path}}});
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: effects[0].file: must take at most"));
  EXPECT_THAT(error_of(j), HasSubstr("got 2 GiB"));
  // In any format, and for gaze_track too (both went unchecked: 1.4-1.6 GB resident for a
  // 311 MB trace).
  j = base_scenario({{{"type", "head_track"}, {"file", path}, {"format", "auto"}}});
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: effects[0].file: must take at most"));
  j = base_scenario({{{"type", "gaze_track"}, {"file", path}}});
  EXPECT_THAT(error_of(j), HasSubstr("bad.json: effects[0].file: must take at most"));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace gazelod::sim
