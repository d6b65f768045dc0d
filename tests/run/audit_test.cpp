// SPDX-License-Identifier: Apache-2.0
// The visibility audit of `gazelod run` end to end on the simulated runtime: the simulator's
// ground truth (Simulator::eye_truth_at), the audit's outputs and their consistency (summary.json
// against frames.csv), what a perfect tracker gives, the --decisions file, and that the audit
// never changes what the plugin decides.
#include "apps/gazelod/run/audit.hpp"
#include "run_test_util.hpp"
#include "sim/simulator.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace gazelod::test {
namespace {

// The pursued object's name needs RFC 4180 quoting in the decisions file.
constexpr const char* kPursued = "drone, \"blue\"";

std::string scenario_json(bool perfect_tracker) {
  nlohmann::json objects = nlohmann::json::array();
  objects.push_back({{"name", kPursued},
                     {"position_m", {-3.0, 0.0, -8.0}},
                     {"velocity_m_s", {1.5, 0.0, 0.0}},
                     {"radius_m", 0.3},
                     {"lods",
                      {{{"triangles", 20000}, {"vertices", 10002}, {"detail", 0}},
                       {{"triangles", 5000}, {"vertices", 2502}, {"detail", 35.36}},
                       {{"triangles", 1250}, {"vertices", 627}, {"detail", 17.68}},
                       {{"triangles", 312}, {"vertices", 158}, {"detail", 8.83}}}}});
  nlohmann::json effects = {
      {{"type", "head_sweep"}, {"yaw_amplitude_deg", 15}, {"yaw_period_s", 4}},
      {{"type", "saccades"},
       {"fixation_min_ms", 150},
       {"fixation_max_ms", 350},
       {"amplitude_min_deg", 3},
       {"amplitude_max_deg", 15}},
      {{"type", "smooth_pursuit"}, {"object", kPursued}, {"gain", 0.9}, {"start_s", 1.5}, {"end_s", 2.5}}};
  if (!perfect_tracker) {
    effects.push_back({{"type", "tracker_rate"}, {"rate_hz", 90}});
    effects.push_back({{"type", "tracker_latency"}, {"latency_ms", 12}});
    effects.push_back({{"type", "tracker_noise"}, {"std_deg", 0.3}});
    effects.push_back({{"type", "blinks"}, {"rate_per_min", 30}, {"duration_ms", 150}});
  }
  nlohmann::json j = {{"version", 1},
                      {"name", perfect_tracker ? "audit-perfect" : "audit"},
                      {"display", "questpro"},
                      {"duration_s", 3},
                      {"frame_rate_hz", 90},
                      {"seed", 5},
                      {"scene",
                       {{"objects", objects},
                        {"generators",
                         {{{"type", "random_field"},
                           {"count", 80},
                           {"min_m", {-10, -3, -40}},
                           {"max_m", {10, 3, -4}},
                           {"radius_min_m", 0.2},
                           {"radius_max_m", 1.0},
                           {"lod_count", 4},
                           {"triangles", 20000},
                           {"triangle_ratio", 4},
                           {"forward_speed_m_s", 1.0}}}}}},
                      {"effects", effects}};
  return j.dump(2);
}

std::filesystem::path write_scenario(const std::filesystem::path& dir, bool perfect_tracker) {
  const auto file = dir / (perfect_tracker ? "perfect.json" : "audit.json");
  std::ofstream(file) << scenario_json(perfect_tracker);
  return file;
}

// RFC 4180 fields of one line (no embedded line breaks here).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        cells.back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        cells.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t col(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  }
};

Csv read_csv(const std::filesystem::path& file) {
  Csv csv;
  std::ifstream in(file);
  std::string line;
  if (std::getline(in, line)) csv.header = csv_fields(line);
  while (std::getline(in, line)) csv.rows.push_back(csv_fields(line));
  return csv;
}

TEST(RunAudit, OutputsExistAndTheSummaryAddsUpFromFramesCsv) {
  const auto dir = scratch_dir();
  const auto scenario = write_scenario(dir, false);
  use_simulated_runtime("");
  const CliResult r = run_cli({"run", "--scenario", scenario.string(), "--no-render", "--frames", "240", "--out",
                               (dir / "out").string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  for (const char* line : {"audit           oracle at the true gaze", "audit           visible degradations",
                           "audit           triangles in view drawn / oracle", "audit           LOD switches",
                           "audit           pursued object"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  EXPECT_NE(r.out.find("audit.svg"), std::string::npos) << r.out;
  EXPECT_GT(std::filesystem::file_size(dir / "out" / "audit.svg"), 1000u);

  const auto summary = nlohmann::json::parse(read_text(dir / "out" / "summary.json"));
  const auto& a = summary.at("audit");
  ASSERT_TRUE(a.at("available").get<bool>()) << a.dump();
  EXPECT_EQ(a.at("frames").get<int>(), 240);
  EXPECT_EQ(a.at("suppression_window").at("after_saccade_ms").get<double>(), 50.0);

  const Csv csv = read_csv(dir / "out" / "frames.csv");
  ASSERT_EQ(csv.rows.size(), 240u);
  const std::size_t c_view = csv.col("objects_in_view"), c_sup = csv.col("audit_suppressed"),
                    c_deg = csv.col("audit_degraded"), c_exc = csv.col("audit_excess_levels"),
                    c_max = csv.col("audit_excess_max"), c_drawn = csv.col("audit_drawn_triangles"),
                    c_oracle = csv.col("audit_oracle_triangles"), c_sw = csv.col("audit_switches"),
                    c_pur = csv.col("audit_pursued"), c_pursuit = csv.col("audit_pursuit");
  std::int64_t suppressed = 0, view_out = 0, view_in = 0, deg_out = 0, deg_in = 0, excess_out = 0, max_out = 0;
  std::int64_t sw_out = 0, sw_in = 0, pursuit_frames = 0, pursuit_deg = 0, pursuit_active = 0;
  std::uint64_t drawn = 0, oracle = 0;
  for (const auto& row : csv.rows) {
    ASSERT_EQ(row.size(), csv.header.size());
    const auto n = [&](std::size_t c) { return std::stoll(row[c]); };
    const bool sup = n(c_sup) == 1;
    suppressed += sup;
    (sup ? view_in : view_out) += n(c_view);
    (sup ? deg_in : deg_out) += n(c_deg);
    (sup ? sw_in : sw_out) += n(c_sw);
    if (!sup) {
      excess_out += n(c_exc);
      max_out = std::max<std::int64_t>(max_out, n(c_max));
    }
    EXPECT_LE(n(c_deg), n(c_view));
    drawn += static_cast<std::uint64_t>(n(c_drawn));
    oracle += static_cast<std::uint64_t>(n(c_oracle));
    pursuit_active += n(c_pursuit);
    if (n(c_pur) >= 0) {
      ++pursuit_frames;
      pursuit_deg += n(c_pur);
      EXPECT_EQ(n(c_pursuit), 1);
    }
  }
  EXPECT_EQ(csv.rows[0][c_sw], "0") << "no switch on the first frame";
  EXPECT_EQ(a.at("suppression_window").at("frames").get<std::int64_t>(), suppressed);
  EXPECT_GT(suppressed, 0) << "saccades and blinks open suppression windows";
  EXPECT_LT(suppressed, 240);
  const auto& v = a.at("visible_degradations");
  EXPECT_EQ(v.at("object_frames").get<std::int64_t>(), view_out);
  EXPECT_EQ(v.at("degraded").get<std::int64_t>(), deg_out);
  EXPECT_NEAR(v.at("share").get<double>(),
              view_out > 0 ? static_cast<double>(deg_out) / static_cast<double>(view_out) : 0.0, 1e-12);
  EXPECT_NEAR(v.at("excess_levels_mean").get<double>(),
              deg_out > 0 ? static_cast<double>(excess_out) / static_cast<double>(deg_out) : 0.0, 1e-12);
  EXPECT_EQ(v.at("excess_levels_max").get<std::int64_t>(), max_out);
  EXPECT_EQ(a.at("suppressed_degradations").at("object_frames").get<std::int64_t>(), view_in);
  EXPECT_EQ(a.at("suppressed_degradations").at("degraded").get<std::int64_t>(), deg_in);
  EXPECT_EQ(a.at("triangles_in_view").at("oracle").get<std::uint64_t>(), oracle);
  EXPECT_EQ(a.at("triangles_in_view").at("drawn").get<std::uint64_t>(), drawn);
  // The audit's objects in view are the report's: its drawn triangles are the in-view "drawn" set.
  EXPECT_EQ(summary.at("in_view").at("drawn").at("triangles").get<std::uint64_t>(), drawn);
  EXPECT_EQ(a.at("switches").at("outside_suppression").at("switches").get<std::int64_t>(), sw_out);
  EXPECT_EQ(a.at("switches").at("inside_suppression").at("switches").get<std::int64_t>(), sw_in);
  // Object-seconds: objects in view x 1/90 s per frame after the first (unpaced: exact periods).
  const double period = 1.0 / 90.0;
  EXPECT_NEAR(a["switches"]["outside_suppression"].at("object_seconds").get<double>() +
                  a["switches"]["inside_suppression"].at("object_seconds").get<double>(),
              static_cast<double>(view_out + view_in - std::stoll(csv.rows[0][c_view])) * period,
              1e-6 * static_cast<double>(view_out + view_in) * period);  // 11111111 ns, not 1/90 s
  EXPECT_EQ(a.at("pursuit").at("frames").get<std::int64_t>(), pursuit_frames);
  EXPECT_EQ(a.at("pursuit").at("degraded").get<std::int64_t>(), pursuit_deg);
  EXPECT_NEAR(static_cast<double>(pursuit_active), 90.0, 2.0) << "the pursuit lasts 1 s";
  EXPECT_GT(pursuit_frames, 0);
}

TEST(RunAudit, PerfectTrackerMeasured) {
  // No tracker effects: the runtime delivers the true gaze at the display time; the oracle
  // differs from the plugin only in using the true eye velocity and no tracker error. Zero
  // visible degradations does NOT hold with today's plugin: about 0.1 % of the in-view
  // object-frames outside suppression are drawn one level coarser than the oracle's (1-2
  // objects per frame, during fixations near the head sweep's reversal and during pursuit).
  // What is asserted is what holds today: rare (under 1 %) and never more than one level.
  const auto dir = scratch_dir();
  const auto scenario = write_scenario(dir, true);
  use_simulated_runtime("");
  const CliResult r =
      run_cli({"run", "--scenario", scenario.string(), "--no-render", "--out", (dir / "out").string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto a = nlohmann::json::parse(read_text(dir / "out" / "summary.json")).at("audit");
  ASSERT_TRUE(a.at("available").get<bool>());
  std::cout << "[ perfect tracker ] " << a.dump() << "\n";
  EXPECT_GT(a.at("visible_degradations").at("object_frames").get<std::int64_t>(), 0);
  EXPECT_LT(a.at("visible_degradations").at("share").get<double>(), 0.01) << a.dump(2);
  EXPECT_LE(a.at("visible_degradations").at("excess_levels_max").get<int>(), 1) << a.dump(2);
}

TEST(RunAudit, DecisionsFileFormatAndTheAuditNeverChangesThem) {
  const auto dir = scratch_dir();
  const auto scenario = write_scenario(dir, false);
  use_simulated_runtime("");
  const auto with = dir / "with.csv", without = dir / "without.csv";
  CliResult r = run_cli({"run", "--scenario", scenario.string(), "--no-render", "--frames", "150", "--out",
                         (dir / "a").string(), "--quiet", "--decisions", with.string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find(with.string()), std::string::npos) << r.out;
  r = run_cli({"run", "--scenario", scenario.string(), "--no-render", "--frames", "150", "--out", (dir / "b").string(),
               "--quiet", "--decisions", without.string(), "--no-audit"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("audit           unavailable (switched off with --no-audit)"), std::string::npos) << r.out;
  const std::string a = read_text(with), b = read_text(without);
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the plugin's decisions differ with the audit on";
  const auto off = nlohmann::json::parse(read_text(dir / "b" / "summary.json")).at("audit");
  EXPECT_FALSE(off.at("available").get<bool>());
  EXPECT_FALSE(std::filesystem::exists(dir / "b" / "audit.svg"));

  // Format: frame,t_ns,<object names as in the scenario, RFC 4180>.
  const sim::Scenario s = sim::load_scenario_file(scenario.string());
  const Csv csv = read_csv(with);
  ASSERT_EQ(csv.header.size(), 2 + s.objects.size());
  EXPECT_EQ(csv.header[0], "frame");
  EXPECT_EQ(csv.header[1], "t_ns");
  for (std::size_t i = 0; i < s.objects.size(); ++i) EXPECT_EQ(csv.header[2 + i], s.objects[i].name);
  EXPECT_EQ(csv.header[2], kPursued);
  EXPECT_NE(a.find("\"drone, \"\"blue\"\"\""), std::string::npos) << "quoted, quotes doubled";
  ASSERT_EQ(csv.rows.size(), 150u);
  std::map<int, std::uint64_t> levels;
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    const auto& row = csv.rows[k];
    ASSERT_EQ(row.size(), csv.header.size());
    EXPECT_EQ(std::stoll(row[0]), static_cast<long long>(k));
    // The predicted display time on the scenario's clock: one 90 Hz period per frame.
    const long long t_ns = std::stoll(row[1]);
    EXPECT_NEAR(static_cast<double>(t_ns), static_cast<double>(k + 1) * 1e9 / 90.0, 2.0 * static_cast<double>(k + 1))
        << k;
    for (std::size_t c = 2; c < row.size(); ++c) ++levels[std::stoi(row[c])];
  }
  // The same levels as the report's histogram.
  const auto hist = nlohmann::json::parse(read_text(dir / "a" / "summary.json")).at("lod_histogram");
  for (std::size_t l = 0; l < hist.size(); ++l)
    EXPECT_EQ(hist[l].get<std::uint64_t>(), levels[static_cast<int>(l)]) << "level " << l;
}

// The product's promise, as deterministic counts over whole 20 s runs (gaze conditioning and
// the switch policy on, their defaults): at most 0.5 % of in-view object-frames outside
// saccadic suppression drawn coarser than the true gaze allows, at most 1.35 times the
// triangles the true gaze needs, at most one LOD switch per object-second outside
// suppression, and the pursued object never coarser than its oracle level while pursued.
// The default scenario (90 Hz, 12 ms, 0.3 deg tracker), its variant with a 120 Hz, 50 ms,
// 0.5 deg tracker, and a still head with that tracker.
TEST(RunAudit, TargetsHoldOnTheDefaultAndItsLateNoisyAndStillHeadVariants) {
  use_simulated_runtime("");
  const std::string scenarios = std::string(GAZELOD_SOURCE_DIR) + "/sim/scenarios/";
  for (const std::string& scenario :
       {std::string(), scenarios + "default-120hz-50ms.json", scenarios + "still-head-120hz-50ms.json"}) {
    SCOPED_TRACE(scenario.empty() ? "the default scenario" : scenario);
    const auto dir = scratch_dir() / (scenario.empty() ? "default" : std::filesystem::path(scenario).stem());
    std::vector<std::string> args{"run", "--no-render", "--quiet", "--out", dir.string()};
    if (!scenario.empty()) args.insert(args.end(), {"--scenario", scenario});
    const CliResult r = run_cli(args);
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto audit = nlohmann::json::parse(read_text(dir / "summary.json")).at("audit");
    ASSERT_TRUE(audit.at("available").get<bool>());
    EXPECT_EQ(audit.at("frames").get<int>(), 1800);
    const auto& visible = audit.at("visible_degradations");
    EXPECT_GT(visible.at("object_frames").get<std::int64_t>(), 100000);
    EXPECT_LE(visible.at("share").get<double>(), 0.005);
    const double ratio = audit.at("triangles_in_view").at("drawn_over_oracle").get<double>();
    EXPECT_LE(ratio, 1.35);
    EXPECT_GE(ratio, 1.0) << "drawing less than the true gaze needs would show as degradations";
    EXPECT_LE(audit.at("switches").at("outside_suppression").at("per_object_second").get<double>(), 1.0);
    const auto& pursuit = audit.at("pursuit");
    if (pursuit.at("frames").get<int>() > 0) {
      EXPECT_EQ(pursuit.at("degraded").get<int>(), 0);
    }
  }
}

// --breakdown also prints the offline optimum (run/offline_bound.hpp): at the policy's own
// switches, what a policy knowing the run's future could have drawn. Under the oracle's levels
// it can never draw less than the oracle (every level is at most the oracle's: a check that the
// ceilings are wired as documented). That the better policy draws less than the plugin did is
// measured, not a theorem (1.150 against 1.165 here): its sequence also has to respect the
// oracle's levels, where the plugin degraded 0.14 % of the object-frames.
TEST(RunAudit, BreakdownAddsTheOfflineOptimum) {
  use_simulated_runtime("");
  const auto dir = scratch_dir();
  const CliResult r = run_cli({"run", "--no-render", "--quiet", "--breakdown", "--out", (dir / "b").string()});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("offline         the future known, at most the policy's"), std::string::npos) << r.out;
  const auto audit = nlohmann::json::parse(read_text(dir / "b" / "summary.json")).at("audit");
  const auto& bound = audit.at("offline_optimum");
  const std::int64_t budget = audit.at("switches").at("outside_suppression").at("switches").get<std::int64_t>();
  EXPECT_EQ(bound.at("max_switches").get<std::int64_t>(), budget);
  const auto& perceptual = bound.at("better_policy");
  const auto& oracle = bound.at("perfect_tracker");
  ASSERT_TRUE(perceptual.at("available").get<bool>()) << bound.dump(2);
  ASSERT_TRUE(oracle.at("available").get<bool>()) << bound.dump(2);
  EXPECT_LE(perceptual.at("switches").get<std::int64_t>(), budget);
  EXPECT_LE(oracle.at("switches").get<std::int64_t>(), budget);
  EXPECT_LE(perceptual.at("triangles").get<std::uint64_t>(),
            audit.at("triangles_in_view").at("drawn").get<std::uint64_t>());
  EXPECT_GE(oracle.at("triangles").get<std::uint64_t>(),
            audit.at("triangles_in_view").at("oracle").get<std::uint64_t>());
  EXPECT_GE(oracle.at("over_oracle").get<double>(), 1.0);
  EXPECT_LE(perceptual.at("triangles_lower_bound").get<double>(),
            static_cast<double>(perceptual.at("triangles").get<std::uint64_t>()));

  // The same two at the switch target's pop rate: the budget is the target's rate over the
  // audit's own object-seconds. Here the policy switched less than that (0.09 per object-second
  // against 1), so the wider budget can only buy triangles: never more than at the policy's own.
  const auto& at = bound.at("at_switch_target");
  const double object_s = audit.at("switches").at("outside_suppression").at("object_seconds").get<double>();
  const std::int64_t target_budget = at.at("max_switches").get<std::int64_t>();
  EXPECT_EQ(target_budget, static_cast<std::int64_t>(std::floor(cli::kTargetSwitchesPerObjectS * object_s)));
  ASSERT_GT(target_budget, budget);
  const auto& perceptual_at = at.at("better_policy");
  const auto& oracle_at = at.at("perfect_tracker");
  ASSERT_TRUE(perceptual_at.at("available").get<bool>()) << at.dump(2);
  ASSERT_TRUE(oracle_at.at("available").get<bool>()) << at.dump(2);
  EXPECT_LE(perceptual_at.at("switches").get<std::int64_t>(), target_budget);
  EXPECT_LE(perceptual_at.at("per_object_s").get<double>(), cli::kTargetSwitchesPerObjectS);
  EXPECT_LE(perceptual_at.at("triangles").get<std::uint64_t>(), perceptual.at("triangles").get<std::uint64_t>());
  EXPECT_LE(oracle_at.at("triangles").get<std::uint64_t>(), oracle.at("triangles").get<std::uint64_t>());
  EXPECT_GE(oracle_at.at("over_oracle").get<double>(), 1.0);
  EXPECT_EQ(perceptual_at.at("degraded").get<std::int64_t>(), 0) << "never coarser than the oracle";
  EXPECT_NE(r.out.find("offline         at the switch target's"), std::string::npos) << r.out;

  const CliResult plain = run_cli({"run", "--no-render", "--quiet", "--frames", "30", "--out", (dir / "p").string()});
  ASSERT_EQ(plain.rc, 0) << plain.err;
  EXPECT_TRUE(nlohmann::json::parse(read_text(dir / "p" / "summary.json")).at("audit").at("offline_optimum").is_null())
      << "kept only when asked for";
}

TEST(RunAudit, DecisionsIntoAMissingFolderFailsWithTheReasonAndWritesNothing) {
  const auto dir = scratch_dir();
  use_simulated_runtime("");
  const CliResult r = run_cli({"run", "--no-render", "--frames", "5", "--out", (dir / "out").string(), "--quiet",
                               "--decisions", (dir / "nope" / "d.csv").string()});
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find("d.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "nope"));
}

TEST(RunAudit, SystemRuntimeHasNoGroundTruthAndSaysSo) {
  // The loader still finds gazelod's runtime (XR_RUNTIME_JSON), but `--runtime system` means
  // "whatever runtime is active": the run's simulator cannot be assumed to be the runtime's.
  const auto dir = scratch_dir();
  use_simulated_runtime("");
  const CliResult r = run_cli(
      {"run", "--runtime", "system", "--no-render", "--frames", "20", "--out", (dir / "out").string(), "--quiet"});
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("audit           unavailable (no ground truth: not the simulated runtime)"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("visible degradations"), std::string::npos) << "no zeros printed";
  const auto a = nlohmann::json::parse(read_text(dir / "out" / "summary.json")).at("audit");
  EXPECT_FALSE(a.at("available").get<bool>());
  EXPECT_EQ(a.at("reason"), "no ground truth: not the simulated runtime");
  const Csv csv = read_csv(dir / "out" / "frames.csv");
  ASSERT_FALSE(csv.rows.empty());
  EXPECT_EQ(csv.rows[0][csv.col("audit_degraded")], "");
}

TEST(SimulatorTruth, SaccadesBlinksAndPursuitMatchTheGazeTheyMake) {
  sim::Simulator simulator(sim::load_scenario_json(scenario_json(false), "audit.json"));
  const sim::Scenario& s = simulator.scenario();
  int pursued = -1;
  for (std::size_t i = 0; i < s.objects.size(); ++i)
    if (s.objects[i].name == kPursued) pursued = static_cast<int>(i);
  ASSERT_EQ(pursued, 0);
  int saccade_ms = 0, blink_ms = 0, pursuit_ms = 0, still_in_fixation = 0, fixation_ms = 0;
  for (std::int64_t t = 0; t < 3'000'000'000; t += 1'000'000) {
    const sim::EyeTruth e = simulator.eye_truth_at(t);
    const sim::EyeTruth next = simulator.eye_truth_at(t + 1'000'000);
    const glm::dvec3 g0 = simulator.true_gaze_at(t).direction, g1 = simulator.true_gaze_at(t + 1'000'000).direction;
    const bool in_pursuit = t >= 1'500'000'000 && t < 2'500'000'000;
    EXPECT_EQ(e.pursuit_object, in_pursuit ? pursued : -1) << t;
    if (in_pursuit) {
      ++pursuit_ms;
      EXPECT_FALSE(e.in_saccade) << "the pursuit owns the eye (later in the list)";
    }
    saccade_ms += e.in_saccade;
    EXPECT_LE(e.last_saccade_end_ns, t);
    // Outside pursuit, a fixation (no saccade now or 1 ms later, the same one) holds the eye still.
    if (!in_pursuit && !e.in_saccade && !next.in_saccade && e.last_saccade_end_ns == next.last_saccade_end_ns &&
        t + 1'000'000 < 1'500'000'000) {
      ++fixation_ms;
      still_in_fixation += glm::length(g1 - g0) < 1e-12;
    }
    // Blinks close the eye: the sample the tracker took then is invalid, and only then.
    blink_ms += e.in_blink;
    const gaze::GazeSample g = simulator.tracker_at(t);
    if (g.t_ns > 0) {
      EXPECT_EQ(g.valid, !simulator.eye_truth_at(g.t_ns).in_blink) << t;
    }
  }
  EXPECT_GT(saccade_ms, 30);
  EXPECT_GT(fixation_ms, 500);
  EXPECT_EQ(still_in_fixation, fixation_ms);
  EXPECT_EQ(pursuit_ms, 1000);
  EXPECT_GE(blink_ms, 150) << "30 a minute, 150 ms each: at least the blink of the first 2 s";
}

}  // namespace
}  // namespace gazelod::test
