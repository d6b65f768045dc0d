// SPDX-License-Identifier: Apache-2.0
// The visibility audit's arithmetic (apps/gazelod/run/audit.hpp) on synthetic frames, its
// report columns and plot, and the --decisions file (RFC 4180 names, atomic write).
#include "apps/gazelod/run/audit.hpp"
#include "apps/gazelod/run/decisions_file.hpp"
#include "apps/gazelod/run/report.hpp"
#include "apps/gazelod/plots/svg_plot.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

std::vector<std::vector<lod::LodLevel>> chains(std::size_t n) {
  std::vector<lod::LodLevel> chain(4);
  const std::uint32_t tri[4] = {1000, 250, 60, 15};
  for (int k = 0; k < 4; ++k) chain[k].triangles = tri[k];
  return std::vector<std::vector<lod::LodLevel>>(n, chain);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("gazelod_audit_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(RunAudit, SuppressionWindowIsSaccadeBlinkAndFiftyMsAfter) {
  const std::int64_t after = 50'000'000;
  sim::EyeTruth t;
  EXPECT_FALSE(in_suppression(t, 1'000'000'000, after)) << "no saccade yet";
  t.in_saccade = true;
  EXPECT_TRUE(in_suppression(t, 0, after));
  t = {};
  t.in_blink = true;
  EXPECT_TRUE(in_suppression(t, 0, after));
  t = {};
  t.last_saccade_end_ns = 1'000'000'000;
  EXPECT_TRUE(in_suppression(t, 1'000'000'000, after)) << "the landing itself";
  EXPECT_TRUE(in_suppression(t, 1'049'999'999, after));
  EXPECT_FALSE(in_suppression(t, 1'050'000'000, after)) << "50 ms after: sensitive again";
  EXPECT_FALSE(in_suppression(t, 900'000'000, after)) << "a time before the end is no window";
}

TEST(RunAudit, FrameCountsDegradationsExcessTrianglesSwitchesAndPursuit) {
  const auto c = chains(4);
  const std::uint8_t drawn[] = {2, 0, 3, 1}, oracle[] = {1, 0, 1, 0}, view[] = {1, 1, 1, 0}, prev[] = {2, 1, 3, 3};
  AuditFrameInput in;
  in.chains = &c;
  in.drawn = drawn;
  in.previous = prev;
  in.oracle = oracle;
  in.in_view = view;
  in.pursuit_object = 2;
  in.frame_s = 0.01;
  const AuditFrame f = audit_frame(in);
  EXPECT_TRUE(f.available);
  EXPECT_TRUE(f.pursuit);
  EXPECT_FALSE(f.suppressed);
  EXPECT_EQ(f.in_view, 3);
  EXPECT_EQ(f.degraded, 2) << "objects 0 and 2; object 3 is coarser but out of view";
  EXPECT_EQ(f.excess_levels, 3u);
  EXPECT_EQ(f.excess_max, 2u);
  EXPECT_EQ(f.drawn_triangles, 60u + 1000u + 15u);
  EXPECT_EQ(f.oracle_triangles, 250u + 1000u + 250u);
  EXPECT_EQ(f.switches, 1) << "object 1 changed; object 3 changed out of view";
  EXPECT_DOUBLE_EQ(f.object_s, 0.03);
  EXPECT_EQ(f.pursued, 1);

  in.pursuit_object = 3;  // pursued object out of view: not counted
  EXPECT_EQ(audit_frame(in).pursued, -1);
  in.pursuit_object = 1;
  EXPECT_EQ(audit_frame(in).pursued, 0);
  in.previous = {};  // the first frame: no switch, no time
  in.frame_s = 0.0;
  const AuditFrame first = audit_frame(in);
  EXPECT_EQ(first.switches, 0);
  EXPECT_EQ(first.object_s, 0.0);
}

TEST(RunAudit, FinerThanTheOracleIsNoDegradationAndLevelsBeyondTheChainClamp) {
  const auto c = chains(2);
  const std::uint8_t drawn[] = {0, 9}, oracle[] = {3, 9}, view[] = {1, 1};
  AuditFrameInput in;
  in.chains = &c;
  in.drawn = drawn;
  in.oracle = oracle;
  in.in_view = view;
  const AuditFrame f = audit_frame(in);
  EXPECT_EQ(f.degraded, 0);
  EXPECT_EQ(f.drawn_triangles, 1000u + 15u);
  EXPECT_EQ(f.oracle_triangles, 15u + 15u);
}

TEST(RunAudit, SummarySplitsInsideAndOutsideSuppression) {
  std::vector<AuditFrame> frames(5);
  for (auto& f : frames) f.available = true;
  frames[0].in_view = 10;  // outside: 1 degraded (excess 1), 2 switches over 0.1 object-s
  frames[0].degraded = 1;
  frames[0].excess_levels = 1;
  frames[0].excess_max = 1;
  frames[0].switches = 2;
  frames[0].object_s = 0.1;
  frames[0].drawn_triangles = 100;
  frames[0].oracle_triangles = 200;
  frames[1].in_view = 10;  // outside: 3 degraded (excess 5, max 3), pursuit degraded
  frames[1].degraded = 3;
  frames[1].excess_levels = 5;
  frames[1].excess_max = 3;
  frames[1].object_s = 0.1;
  frames[1].pursuit = true;
  frames[1].pursued = 1;
  frames[1].drawn_triangles = 100;
  frames[1].oracle_triangles = 200;
  frames[2].in_view = 10;  // inside: degradations do not count as visible
  frames[2].suppressed = true;
  frames[2].degraded = 7;
  frames[2].excess_levels = 20;
  frames[2].excess_max = 3;
  frames[2].switches = 4;
  frames[2].object_s = 0.1;
  frames[2].pursued = 0;
  frames[3].in_view = 10;  // outside, clean
  frames[3].object_s = 0.1;
  frames[3].pursued = -1;
  frames[4].available = false;  // not audited: ignored
  frames[4].in_view = 1000;
  frames[4].degraded = 1000;

  const AuditSummary s = summarize_audit(frames);
  ASSERT_TRUE(s.available);
  EXPECT_EQ(s.frames, 4);
  EXPECT_EQ(s.suppressed_frames, 1);
  EXPECT_EQ(s.object_frames, 30);
  EXPECT_EQ(s.degraded, 4);
  EXPECT_DOUBLE_EQ(s.degraded_share, 4.0 / 30.0);
  EXPECT_DOUBLE_EQ(s.excess_mean, 6.0 / 4.0);
  EXPECT_EQ(s.excess_max, 3u);
  EXPECT_EQ(s.degraded_suppressed, 7);
  EXPECT_EQ(s.object_frames_suppressed, 10);
  EXPECT_EQ(s.drawn_triangles, 200u);
  EXPECT_EQ(s.oracle_triangles, 400u);
  EXPECT_DOUBLE_EQ(s.triangle_ratio, 0.5);
  EXPECT_EQ(s.switches_fixation.switches, 2);
  EXPECT_NEAR(s.switches_fixation.object_s, 0.3, 1e-12);
  EXPECT_NEAR(s.switches_fixation.per_object_s, 2.0 / 0.3, 1e-9);
  EXPECT_EQ(s.switches_suppressed.switches, 4);
  EXPECT_NEAR(s.switches_suppressed.per_object_s, 40.0, 1e-9);
  EXPECT_EQ(s.pursuit_frames, 2);
  EXPECT_EQ(s.pursuit_degraded, 1);
  EXPECT_DOUBLE_EQ(s.pursuit_degraded_share, 0.5);

  const nlohmann::json j = audit_json(s);
  EXPECT_TRUE(j.at("available").get<bool>());
  EXPECT_EQ(j.at("suppression_window").at("after_saccade_ms").get<double>(), 50.0);
  EXPECT_TRUE(j["suppression_window"].at("saccades").get<bool>());
  EXPECT_TRUE(j["suppression_window"].at("blinks").get<bool>());
  EXPECT_EQ(j.at("visible_degradations").at("degraded").get<int>(), 4);
  EXPECT_EQ(j["visible_degradations"].at("excess_levels_max").get<int>(), 3);
  EXPECT_EQ(j.at("switches").at("inside_suppression").at("switches").get<int>(), 4);
  EXPECT_EQ(j.at("pursuit").at("frames").get<int>(), 2);
  std::ostringstream out;
  print_audit(s, out);
  EXPECT_NE(out.str().find("visible degradations 13.33%"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("50 ms after a saccade"), std::string::npos) << out.str();
}

TEST(RunAudit, NothingAuditedIsUnavailableNotZeros) {
  std::vector<AuditFrame> frames(3);
  AuditSummary s = summarize_audit(frames);
  EXPECT_FALSE(s.available);
  s.reason = "no ground truth: not the simulated runtime";
  const nlohmann::json j = audit_json(s);
  EXPECT_FALSE(j.at("available").get<bool>());
  EXPECT_EQ(j.at("reason"), "no ground truth: not the simulated runtime");
  EXPECT_FALSE(j.contains("visible_degradations"));
  std::ostringstream out;
  print_audit(s, out);
  EXPECT_EQ(out.str(), "audit           unavailable (no ground truth: not the simulated runtime)\n");
}

FrameRecord record(std::int64_t i, bool audited, bool suppressed) {
  FrameRecord f;
  f.index = i;
  f.t_s = static_cast<double>(i) / 90.0;
  f.triangles_full = 1000;
  f.triangles_drawn = 500;
  f.objects_in_view = 4;
  f.audit.available = audited;
  f.audit.suppressed = suppressed;
  f.audit.in_view = 4;
  f.audit.degraded = suppressed ? 2 : 1;
  f.audit.oracle_triangles = 600;
  f.audit.drawn_triangles = 500;
  f.audit.switches = 1;
  return f;
}

TEST(RunAudit, ReportWritesColumnsSummaryAndPlotWithShadedWindows) {
  const auto dir = fresh_dir("report");
  std::vector<FrameRecord> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(record(i, true, i >= 3 && i < 6));
  RunInfo info{"default", "questpro", "sim", "none", "size,eccentricity,velocity", 0.0};
  write_report_files(dir, info, summarize(frames, 0.0), frames);
  const auto j = nlohmann::json::parse(read(dir / "summary.json"));
  ASSERT_TRUE(j.at("audit").at("available").get<bool>());
  EXPECT_EQ(j["audit"].at("visible_degradations").at("degraded").get<int>(), 7);
  EXPECT_EQ(j["audit"]["visible_degradations"].at("object_frames").get<int>(), 28);
  EXPECT_EQ(j["audit"].at("suppression_window").at("frames").get<int>(), 3);

  std::istringstream csv(read(dir / "frames.csv"));
  std::string header, row;
  std::getline(csv, header);
  for (const char* col :
       {",objects_in_view", ",audit_suppressed", ",audit_degraded", ",audit_oracle_triangles", ",audit_switches"})
    EXPECT_NE(header.find(col), std::string::npos) << col;
  std::getline(csv, row);
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ','));

  const std::string svg = read(dir / "audit.svg");
  EXPECT_EQ(count(svg, "class=\"span\""), 3u) << "one window, shaded in each of the three panels";
  EXPECT_NE(svg.find("suppression window"), std::string::npos);
}

TEST(RunAudit, PlotHasClusterPanelsOnlyWhenClustersWereAudited) {
  std::vector<FrameRecord> frames;
  for (int i = 0; i < 6; ++i) frames.push_back(record(i, true, i == 2));
  const RunInfo info{"default", "questpro", "sim", "none", "size,eccentricity,velocity", 0.0};
  const RunSummary s = summarize(frames, 0.0);
  EXPECT_EQ(audit_plot(info, s.audit, frames).panels.size(), 3u) << "no cluster audit: objects only";

  for (FrameRecord& f : frames) {
    f.cluster_audit.available = f.index != 4;  // one frame without: a gap, not a zero
    f.cluster_audit.degraded = 2 + f.index;
    f.cluster_audit.excess_depth_max = 1;
    f.cluster_audit.drawn_triangles = 700;
    f.cluster_audit.oracle_triangles = 900;
    f.cluster_audit.switches = 3;
  }
  const Plot plot = audit_plot(info, s.audit, frames);
  ASSERT_EQ(plot.panels.size(), 6u);
  EXPECT_EQ(plot.panels[3].y_label, "in-view cluster leaves");
  EXPECT_EQ(plot.panels[5].y_label, "cluster triangles in view");
  const std::vector<double>& degraded = plot.panels[3].series[0].y;
  ASSERT_EQ(degraded.size(), frames.size());
  EXPECT_EQ(degraded[5], 7.0);
  EXPECT_TRUE(std::isnan(degraded[4]));
  EXPECT_EQ(plot.panels[5].series[1].y[0], 900.0);
  std::ostringstream svg;
  write_svg(plot, svg);
  EXPECT_EQ(count(svg.str(), "class=\"span\""), 6u) << "the window shaded in all six panels";
}

TEST(RunAudit, ReportWithoutGroundTruthLeavesCellsEmptyAndSaysWhy) {
  const auto dir = fresh_dir("unavailable");
  std::ofstream(dir / "audit.svg") << "old";
  std::vector<FrameRecord> frames{record(0, false, false), record(1, false, false)};
  RunSummary s = summarize(frames, 0.0);
  EXPECT_FALSE(s.audit.available);
  s.audit.reason = "no ground truth: not the simulated runtime";
  RunInfo info{"default", "questpro", "system", "none", "size,eccentricity,velocity", 0.0};
  write_report_files(dir, info, s, frames);
  const auto j = nlohmann::json::parse(read(dir / "summary.json"));
  EXPECT_FALSE(j.at("audit").at("available").get<bool>());
  EXPECT_EQ(j["audit"].at("reason"), "no ground truth: not the simulated runtime");
  EXPECT_FALSE(std::filesystem::exists(dir / "audit.svg")) << "no stale plot";
  std::istringstream csv(read(dir / "frames.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_NE(row.find(",4,,,,,,,,,"), std::string::npos) << row;  // objects_in_view, then empty audit cells
  EXPECT_EQ(row.back(), ',');
  std::ostringstream out;
  print_summary(info, s, out);
  EXPECT_NE(out.str().find("audit           unavailable (no ground truth: not the simulated runtime)"),
            std::string::npos)
      << out.str();
}

TEST(SvgPlot, SpansAreShadedInEveryPanel) {
  Plot plot;
  plot.x = {0, 1, 2, 3};
  plot.panels.push_back({"a", {{"s", "#f00", {1, 2, 3, 4}}}});
  plot.panels.push_back({"b", {{"s", "#f00", {1, 2, 3, 4}}}});
  plot.spans = {{0.5, 1.5, "#888"}, {2.0, 2.5, "#888"}};
  plot.span_legend = "window";
  std::ostringstream out;
  write_svg(plot, out);
  EXPECT_EQ(count(out.str(), "class=\"span\""), 4u);
  EXPECT_NE(out.str().find(">window<"), std::string::npos);
}

TEST(DecisionsCsv, FieldsAreQuotedPerRfc4180) {
  EXPECT_EQ(csv_field("drone"), "drone");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
  EXPECT_EQ(csv_field(""), "");
}

TEST(DecisionsCsv, WrittenAtomicallyWithHeaderAndRows) {
  const auto dir = fresh_dir("decisions");
  const auto file = dir / "decisions.csv";
  const std::vector<std::string> names{"drone", "tree, big", "the \"rock\""};
  {
    DecisionsFile d(file, names);
    const std::uint8_t a[] = {0, 1, 3}, b[] = {2, 2, 0};
    d.write(0, 11111111, a);
    d.write(1, 22222222, b);
    EXPECT_FALSE(std::filesystem::exists(file)) << "nothing at the path before commit";
    int temps = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      temps += e.path().filename().string().find(".tmp-") != std::string::npos;
    EXPECT_EQ(temps, 1) << "the rows go to a temporary file in the same folder";
    d.commit();
  }
  EXPECT_EQ(read(file), "frame,t_ns,drone,\"tree, big\",\"the \"\"rock\"\"\"\n0,11111111,0,1,3\n1,22222222,2,2,0\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}), 1)
      << "no temporary file left";
}

TEST(DecisionsCsv, NoCommitLeavesNoPartialFileAndKeepsTheOldOne) {
  const auto dir = fresh_dir("decisions_abort");
  const auto file = dir / "decisions.csv";
  std::ofstream(file) << "old\n";
  {
    DecisionsFile d(file, std::vector<std::string>{"a"});
    const std::uint8_t a[] = {1};
    d.write(0, 1, a);
  }  // destroyed without commit: an error ended the run
  EXPECT_EQ(read(file), "old\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}), 1);
}

TEST(DecisionsCsv, MissingFolderIsAnErrorWithTheSystemsReason) {
  const auto dir = fresh_dir("decisions_missing");
  try {
    DecisionsFile d(dir / "no" / "such" / "decisions.csv", std::vector<std::string>{"a"});
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("decisions.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace gazelod::cli
