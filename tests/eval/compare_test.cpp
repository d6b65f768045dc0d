// SPDX-License-Identifier: Apache-2.0
// gazelod compare end to end on the simulated runtime (headless), and what it takes from a
// run: the JSON contract, no criterion ever adding triangles, errors for bad input.
#include "lod/display.hpp"
#include "apps/gazelod/commands/command.hpp"
#include "apps/gazelod/compare/runs.hpp"
#include "tests/cli/svg_check.hpp"
#include "tests/eval/eval_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

using testing::cli;
using testing::Result;
using testing::scratch;
using testing::use_simulated_runtime;

std::string read_text_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A motion-rich scene: forward flight, head sweeping, saccades, so all criteria have work.
std::filesystem::path write_scenario(const std::filesystem::path& dir) {
  const auto path = dir / "scene.json";
  std::ofstream(path) << R"({"version": 1, "display": "questpro", "duration_s": 2, "frame_rate_hz": 30,
    "scene": {"generators": [{"type": "random_field", "count": 150, "forward_speed_m_s": 3}]},
    "effects": [{"type": "head_sweep", "yaw_amplitude_deg": 40, "yaw_period_s": 1.5},
                {"type": "saccades"}]})";
  return path;
}

TEST(Compare, JsonShapeAndNoCriterionAddsTriangles) {
  use_simulated_runtime();
  const auto dir = scratch();
  const Result r = cli({"compare", "--hmd", "questpro", "--hmd", "iglasses", "--scenario", write_scenario(dir).string(),
                        "--json", "--out", (dir / "out").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_TRUE(doc.at("hmds").is_array());
  ASSERT_EQ(doc.at("hmds").size(), 2u);
  EXPECT_EQ(doc["hmds"][0].at("hmd"), "questpro");
  EXPECT_EQ(doc["hmds"][1].at("hmd"), "iglasses");
  for (const auto& h : doc["hmds"]) {
    const std::string name = h.at("hmd");
    // xi from the preset's pixels and FOV (lod/display.hpp), e.g. the i-glasses' 4.79 c/deg
    // of docs/perceptual-model.md's table.
    EXPECT_NEAR(h.at("xi_cpd").get<double>(), lod::xi_cpd(*lod::find_display_preset(name)), 1e-9);
    if (name == "iglasses") {
      EXPECT_NEAR(h["xi_cpd"].get<double>(), 4.79, 0.01);
      EXPECT_NEAR(h.at("eccentricity_threshold_deg").get<double>(), 28.95, 0.05);
      EXPECT_NEAR(h.at("velocity_threshold_dps").get<double>(), 80.20, 0.05);
    }
    const auto& runs = h.at("runs");
    for (const char* set : kCriteriaSets) {
      ASSERT_TRUE(runs.contains(set)) << name << " " << set;
      ASSERT_TRUE(runs[set].at("triangles").is_number());
      ASSERT_TRUE(runs[set].at("average_lod").is_number());
    }
    const auto tri = [&](const char* s) { return runs[s]["triangles"].get<double>(); };
    const auto lod = [&](const char* s) { return runs[s]["average_lod"].get<double>(); };
    // Each added criterion: never more triangles, never a finer average level.
    const std::pair<const char*, const char*> added[] = {{"none", "size"},
                                                         {"size", "size+eccentricity"},
                                                         {"size", "size+velocity"},
                                                         {"size+eccentricity", "size+eccentricity+velocity"},
                                                         {"size+velocity", "size+eccentricity+velocity"}};
    for (const auto& [without, with] : added) {
      // The last set is what is drawn, after the switch policy; the others are each frame's
      // perceptual choice. Without an eye tracker (the i-glasses: head-fixed gaze, velocity
      // adding nothing) the policy's holds alone make it the larger: not a criterion's doing.
      if (!h.at("eye_tracker").get<bool>() && std::string(with) == "size+eccentricity+velocity") continue;
      EXPECT_LE(tri(with), tri(without)) << name << ": " << with << " vs " << without;
      EXPECT_GE(lod(with), lod(without)) << name << ": " << with << " vs " << without;
    }
    EXPECT_EQ(lod("none"), 0.0);
    EXPECT_GT(tri("none"), 0.0);
    EXPECT_LT(tri("size+eccentricity+velocity"), tri("none")) << name << ": nothing was reduced";
    for (const char* k : {"size", "eccentricity", "velocity"}) {
      EXPECT_GE(h.at("shares").at(k).get<double>(), 0.0) << k;
      EXPECT_LE(h["shares"][k].get<double>(), 1.0 + 1e-12) << k;
    }
    EXPECT_LE(h.at("lod_map").at("triangles").get<double>(), tri("none"));
    // The run's visibility audit, per HMD, as in its summary.json.
    const auto& audit = h.at("audit");
    ASSERT_TRUE(audit.at("available").get<bool>()) << name << ": " << audit.dump();
    EXPECT_GT(audit.at("visible_degradations").at("object_frames").get<double>(), 0.0) << name;
    EXPECT_GE(audit["visible_degradations"].at("share").get<double>(), 0.0) << name;
    EXPECT_LE(audit["visible_degradations"].at("share").get<double>(), 1.0) << name;
    EXPECT_GT(audit.at("triangles_in_view").at("oracle").get<double>(), 0.0) << name;
    EXPECT_TRUE(audit.at("switches").contains("outside_suppression")) << name;
    EXPECT_EQ(audit.at("suppression_window").at("after_saccade_ms").get<double>(), 50.0) << name;
  }
  EXPECT_TRUE(std::filesystem::file_size(dir / "out" / "compare.svg") > 500);
  const std::string svg = read_text_file(dir / "out" / "compare.svg");
  EXPECT_EQ(svgcheck::unround_ticks(svg), std::vector<std::string>{});
  EXPECT_EQ(svgcheck::overlapping_texts(svg), std::vector<std::string>{});
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "questpro" / "summary.json"));
}

// A headset without an eye tracker is compared with the gaze it has: none (the plugin's
// head-fixed fallback), said in the table and the JSON; the default scenario's runtime offers
// eye gaze for the display --hmd replaces.
TEST(Compare, AHeadsetWithoutAnEyeTrackerHasNoEyeGaze) {
  use_simulated_runtime();
  const auto dir = scratch();
  const Result r =
      cli({"compare", "--hmd", "quest3", "--hmd", "questpro", "--frames", "30", "--out", (dir / "out").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("== quest3: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("30 frames, no eye tracker: head-fixed gaze =="), std::string::npos) << r.out;
  std::ifstream in(dir / "out" / "compare.json");
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["hmds"][0]["hmd"], "quest3");
  EXPECT_EQ(doc["hmds"][0]["eye_tracker"], false);
  EXPECT_EQ(doc["hmds"][0]["gaze_valid_share"], 0.0);
  EXPECT_EQ(doc["hmds"][1]["eye_tracker"], true);
  EXPECT_GT(doc["hmds"][1]["gaze_valid_share"].get<double>(), 0.5);
}

TEST(Compare, UnknownHmdIsAnErrorNamingIt) {
  const auto dir = scratch();
  const Result r = cli({"compare", "--hmd", "questpro", "--hmd", "nosuchhmd", "--out", dir.string()});
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find("nosuchhmd"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "questpro")) << "no run before every name is checked";
  // A known preset a run cannot use (one view) is refused up front too, naming --hmd.
  const Result d = cli({"compare", "--hmd", "questpro", "--hmd", "desktop", "--out", dir.string()});
  EXPECT_EQ(d.rc, 2);
  EXPECT_NE(d.err.find("--hmd: the preset 'desktop' has 1 view"), std::string::npos) << d.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "questpro")) << "no run before every preset is checked";
}

TEST(Compare, SharesHaveOneDefinition) {
  // none 1000, size 400, size+ecc 300, size+vel 350, all 250: reduction 750;
  // size (1000-400)/750 = 0.8, eccentricity (350-250)/750, velocity (300-250)/750.
  const ReductionShares s = reduction_shares({1000, 400, 300, 350, 250});
  EXPECT_NEAR(s.size, 0.8, 1e-12);
  EXPECT_NEAR(s.eccentricity, 100.0 / 750.0, 1e-12);
  EXPECT_NEAR(s.velocity, 50.0 / 750.0, 1e-12);
  EXPECT_NEAR(s.interaction, 0.0, 1e-12);
  // Together the criteria remove more than the sum of each last: the interaction is the rest.
  const ReductionShares t = reduction_shares({1000, 600, 500, 550, 250});
  EXPECT_NEAR(t.interaction, 1.0 - (400.0 + 300.0 + 250.0) / 750.0, 1e-12);
  // Nothing reduced (or more drawn than full detail): every share 0, never a division by 0.
  const ReductionShares none = reduction_shares({500, 500, 500, 500, 500});
  EXPECT_EQ(none.size, 0.0);
  EXPECT_EQ(none.interaction, 0.0);
  EXPECT_EQ(reduction_shares({500, 400, 400, 400, 600}).size, 0.0);
}

TEST(Compare, ComparisonCarriesTheRunsSetsSharesAndAudit) {
  RunSummary run;
  run.frames = 10;
  run.set_none = {1000, 0.0};
  run.set_size = {400, 1.0};
  run.set_size_eccentricity = {300, 1.2};
  run.set_size_velocity = {350, 1.1};
  run.set_drawn = {250, 1.5};
  run.set_lod_map = {500, 1.0};
  run.shares = reduction_shares({1000, 400, 300, 350, 260});
  run.audit.available = true;
  run.audit.degraded = 4;
  run.audit.excess_max = 2;
  run.audit.switches_suppressed = {5, 0.2, 25.0};
  const HmdComparison c = comparison_from_run("iglasses", run);
  EXPECT_EQ(c.frames, 10);
  EXPECT_EQ(c.sets[0].triangles, 1000u);
  EXPECT_EQ(c.sets[4].triangles, 250u);
  EXPECT_DOUBLE_EQ(c.sets[2].average_lod, 1.2);
  EXPECT_EQ(c.lod_map.triangles, 500u);
  EXPECT_DOUBLE_EQ(c.shares.size, run.shares.size) << "the run's own shares, not a second computation";
  EXPECT_DOUBLE_EQ(c.shares.interaction, run.shares.interaction);
  EXPECT_EQ(audit_json(c.audit), audit_json(run.audit)) << "the compare document carries the run's audit unchanged";
  EXPECT_GT(c.xi_cpd, 0.0);
  EXPECT_THROW((void)comparison_from_run("no-such-hmd", run), UsageError);
}

}  // namespace
}  // namespace gazelod::cli

namespace gazelod::cli {
namespace {

// Smoke test of `gazelod eval` (selection only, two small points, one layout): the tables
// are written and adding size to eccentricity + velocity never lowers the average level.
TEST(EvalSmoke, HeadlessTablesAreWrittenAndConsistent) {
  use_simulated_runtime();
  const auto dir = scratch();
  const Result r = cli({"eval", "--no-render", "--counts", "10", "50", "--layouts", "1", "--out", dir.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  std::ifstream md(dir / "eval_tables.md");
  ASSERT_TRUE(md.good());
  std::string line;
  int rows = 0;
  bool in_figure6 = false;
  while (std::getline(md, line)) {
    if (line.rfind("### Figure 6", 0) == 0)
      in_figure6 = true;
    else if (line.rfind("###", 0) == 0)
      in_figure6 = false;
    if (!in_figure6 || (line.rfind("| 10 |", 0) != 0 && line.rfind("| 50 |", 0) != 0)) continue;
    // | objects | in view | LOD all | LOD ecc+vel | ...
    std::vector<std::string> cells;
    std::istringstream in(line);
    std::string c;
    while (std::getline(in, c, '|')) cells.push_back(c);
    ASSERT_GE(cells.size(), 5u) << line;
    EXPECT_GE(std::stod(cells[3]), std::stod(cells[4])) << line;
    EXPECT_GE(std::stod(cells[3]), 1.0) << line;
    EXPECT_LE(std::stod(cells[3]), 4.0) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 2);
  EXPECT_TRUE(std::filesystem::exists(dir / "figure6.svg"));
  EXPECT_TRUE(std::filesystem::exists(dir / "head_turns.svg"));
  for (const char* plot : {"figure6.svg", "head_turns.svg"}) {
    const std::string svg = read_text_file(dir / plot);
    EXPECT_EQ(svgcheck::unround_ticks(svg), std::vector<std::string>{}) << plot;
    EXPECT_EQ(svgcheck::overlapping_texts(svg), std::vector<std::string>{}) << plot;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "figure5.svg")) << "--no-render skips Figure 5";
}

}  // namespace
}  // namespace gazelod::cli
