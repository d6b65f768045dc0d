// SPDX-License-Identifier: Apache-2.0
// gazelod eval family --against: the comparison's counts on members with known figures, the
// report end to end, and every way an earlier report can be unusable (refused before any seed
// runs, naming the file and the JSON path).
#include "apps/gazelod/eval/family_against.hpp"
#include "tests/eval/eval_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace gazelod::cli {
namespace {

using testing::Result;

FamilyMember member(std::uint64_t seed, double degraded, double triangles, double switches) {
  FamilyMember m;
  m.seed = seed;
  m.audit.degraded_share = degraded;
  m.audit.triangle_ratio = triangles;
  m.audit.switches_fixation.per_object_s = switches;
  return m;
}

TEST(FamilyAgainst, CountsWhoEnteredAndWhoLeftEachTarget) {
  FamilyBaseline base;
  base.source = "before.json";
  base.settings_changed = {"switch.coarsen_hold_s=0.3"};
  base.rows = {{10, 0.001, 1.40, 0.5},                                // over the triangle target
               {11, 0.002, 1.20, 1.20},                               // over the switch target
               {12, 0.006, 1.10, 0.3},                                // over the degradation target
               {13, 0.001, 1.20, 0.4}};                               // within all three
  const std::vector<FamilyMember> now{member(10, 0.001, 1.30, 0.5),   // enters triangles, and all three
                                      member(11, 0.002, 1.20, 1.10),  // still over switches
                                      member(12, 0.004, 1.10, 0.3),   // enters degradations, and all three
                                      member(13, 0.001, 1.36, 0.4)};  // leaves triangles, and all three
  const nlohmann::json j = against_json(now, base);
  const auto& tri = j.at("targets").at("triangles drawn / oracle");
  EXPECT_EQ(tri.at("within_before"), 3);
  EXPECT_EQ(tri.at("within_now"), 3);
  EXPECT_EQ(tri.at("entered"), nlohmann::json::array({10}));
  EXPECT_EQ(tri.at("left"), nlohmann::json::array({13}));
  const auto& deg = j.at("targets").at("visible degradations (fixation object-frames)");
  EXPECT_EQ(deg.at("within_before"), 3);
  EXPECT_EQ(deg.at("within_now"), 4);
  EXPECT_EQ(deg.at("entered"), nlohmann::json::array({12}));
  const auto& sw = j.at("targets").at("switches per object-second outside suppression");
  EXPECT_EQ(sw.at("within_before"), 3);
  EXPECT_EQ(sw.at("within_now"), 3);
  EXPECT_TRUE(sw.at("entered").empty());
  EXPECT_TRUE(sw.at("left").empty());
  const auto& all = j.at("targets").at("all three");
  EXPECT_EQ(all.at("within_before"), 1);
  EXPECT_EQ(all.at("within_now"), 2);
  EXPECT_EQ(all.at("entered"), nlohmann::json::array({10, 12}));
  EXPECT_EQ(all.at("left"), nlohmann::json::array({13}));
  EXPECT_DOUBLE_EQ(tri.at("before").at("worst").get<double>(), 1.40);
  EXPECT_EQ(tri.at("before").at("worst_seed"), 10);

  const std::string md = against_markdown(now, base);
  EXPECT_NE(md.find("`switch.coarsen_hold_s=0.3`"), std::string::npos) << md;
  EXPECT_NE(md.find("| all three | 1 | 2 | 10, 12 | 13 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 13 | 0.100% -> 0.100% | 1.200 -> 1.360 | 0.400 -> 0.400 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| 11 |"), std::string::npos) << "11 stayed where it was\n" << md;
}

TEST(FamilyAgainst, SeedsAndDurationMustBeTheSame) {
  FamilyBaseline base;
  base.source = "b.json";
  base.duration_s = 20.0;
  base.rows = {{5, 0, 1, 0}, {6, 0, 1, 0}};
  EXPECT_NO_THROW(check_same_run(base, 5, 2, 20.0));
  try {
    check_same_run(base, 5, 3, 20.0);
    FAIL() << "a seed missing from the earlier run";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(),
                 "--against: b.json: its seeds are 5-6 (2 seeds), this run's 5-7 (3 seeds): compare runs of "
                 "the same seeds");
  }
  EXPECT_THROW(check_same_run(base, 6, 2, 20.0), UsageError);
  try {
    check_same_run(base, 5, 2, 3.0);
    FAIL() << "the same seeds run for another time are other scenarios";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(),
                 "--against: b.json: its scenarios last 20 s, this run's 3 s: the same seeds would be other "
                 "scenarios");
  }
  // The comparison itself refuses members that are not the baseline's seeds.
  EXPECT_THROW(against_json({member(5, 0, 1, 0)}, base), UsageError);
}

Result cli(const std::vector<std::string>& args) {
  testing::use_simulated_runtime();
  return testing::cli(args);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

TEST(FamilyAgainst, AgainstItselfNothingMovesAndAgainstAChangeTheCountsAgree) {
  const auto dir = testing::scratch("family.");
  const std::vector<std::string> base{"eval",       "family", "--seeds", "3-5",
                                      "--duration", "3",      "--out",   (dir / "a").string()};
  ASSERT_EQ(cli(base).rc, 0);
  const std::string a = (dir / "a" / "family.json").string();
  EXPECT_EQ(nlohmann::json::parse(read(dir / "a" / "family.json")).at("duration_s"), 3.0);
  const Result same =
      cli({"eval", "family", "--seeds", "3-5", "--duration", "3", "--against", a, "--out", (dir / "b").string()});
  ASSERT_EQ(same.rc, 0) << same.err;
  EXPECT_NE(same.out.find("## Against `" + a + "`"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("| (none) | | | |"), std::string::npos) << "nothing changed\n" << same.out;
  const nlohmann::json b = nlohmann::json::parse(read(dir / "b" / "family.json"));
  for (const auto& [name, t] : b.at("against").at("targets").items()) {
    EXPECT_EQ(t.at("within_before"), t.at("within_now")) << name;
    EXPECT_TRUE(t.at("entered").empty() && t.at("left").empty()) << name;
  }
  // A real change: the counts before and now are each run's own.
  const Result changed = cli({"eval", "family", "--seeds", "3-5", "--duration", "3", "--set", "switch.coarsen_hold_s=0",
                              "--against", a, "--out", (dir / "c").string()});
  ASSERT_EQ(changed.rc, 0) << changed.err;
  const nlohmann::json before = nlohmann::json::parse(read(dir / "a" / "family.json"));
  const nlohmann::json c = nlohmann::json::parse(read(dir / "c" / "family.json"));
  for (const char* name : {"visible degradations (fixation object-frames)", "triangles drawn / oracle",
                           "switches per object-second outside suppression"}) {
    const auto& t = c.at("against").at("targets").at(name);
    EXPECT_EQ(t.at("within_before"), before.at("distribution").at(name).at("within_target")) << name;
    EXPECT_EQ(t.at("within_now"), c.at("distribution").at(name).at("within_target")) << name;
    EXPECT_EQ(t.at("within_now").get<int>() - t.at("within_before").get<int>(),
              static_cast<int>(t.at("entered").size()) - static_cast<int>(t.at("left").size()))
        << name;
  }
  EXPECT_EQ(c.at("against").at("targets").at("all three").at("within_now"), c.at("within_all_targets"));
  EXPECT_EQ(c.at("against").at("targets").at("all three").at("within_before"), before.at("within_all_targets"));
}

TEST(FamilyAgainst, AnUnusableEarlierReportIsRefusedBeforeAnySeedRuns) {
  const auto dir = testing::scratch("family.");
  const auto refused = [&](const std::string& text, const std::string& expected, const std::string& seeds = "1-2") {
    const auto file = dir / "base.json";
    write(file, text);
    const auto out = dir / "out";
    const Result r =
        cli({"eval", "family", "--seeds", seeds, "--duration", "3", "--against", file.string(), "--out", out.string()});
    EXPECT_EQ(r.rc, 2) << text;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "expected: " << expected << "\ngot: " << r.err;
    EXPECT_EQ(r.err.find("[1/"), std::string::npos) << "no seed ran\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << "nothing written";
  };
  const std::string audit =
      R"({"visible_degradations": {"share": 0.001}, "triangles_in_view": {"drawn_over_oracle": 1.2},
    "switches": {"outside_suppression": {"per_object_second": 0.3}}})";
  const auto doc = [&](const std::string& members) {
    return R"({"settings_changed": [], "duration_s": 3, "members": [)" + members + "]}";
  };
  const std::string one = R"({"seed": 1, "audit": )" + audit + "}";
  const std::string two = R"({"seed": 2, "audit": )" + audit + "}";
  refused("{\n  \"members\": [,]\n}", "base.json:2:15: JSON syntax error: syntax error while parsing value");
  refused(R"({"settings_changed": [], "settings_changed": []})", "base.json: settings_changed: ");
  refused("[]", "base.json: (top level): expected an object, got array");
  refused(R"({"members": []})", "base.json: settings_changed: missing");
  refused(R"({"settings_changed": [], "members": []})", "base.json: duration_s: missing");
  refused(R"({"settings_changed": [], "duration_s": 0, "members": []})",
          "base.json: duration_s: expected a number > 0, got 0");
  refused(doc(""), "base.json: members: expected a non-empty array");
  refused(doc(R"({"seed": -1, "audit": {}})"), "base.json: members[0].seed: expected an integer >= 0, got -1");
  refused(doc(R"({"seed": 1.5, "audit": {}})"), "base.json: members[0].seed: expected an integer >= 0, got 1.5");
  refused(doc(R"({"seed": 1})"), "base.json: members[0].audit: missing");
  refused(doc(one + R"(, {"seed": 2, "audit": {"visible_degradations": {"share": "0.1"}}})"),
          "base.json: members[1].audit.visible_degradations.share: expected a number >= 0, got string");
  refused(doc(R"({"seed": 1, "audit": {"visible_degradations": {"share": -0.1}}})"),
          "members[0].audit.visible_degradations.share: expected a number >= 0, got a negative or non-finite one");
  refused(doc(R"({"seed": 1, "audit": {"visible_degradations": {"share": 1e400}}})"),
          "base.json:1:111: the number 1e400 is past the range of a double");
  refused(doc(R"({"seed": 1, "audit": {"visible_degradations": {"share": 0}, "triangles_in_view": {}}})"),
          "base.json: members[0].audit.triangles_in_view.drawn_over_oracle: missing");
  refused(doc(two + ", " + one), "base.json: members[1].seed: seeds must increase (1 after 2)");
  refused(doc(one + ", " + two), "its seeds are 1-2 (2 seeds), this run's 1-3 (3 seeds)", "1-3");
  // Another duration: the same seeds, other scenarios.
  refused(R"({"settings_changed": [], "duration_s": 20, "members": [)" + one + ", " + two + "]}",
          "its scenarios last 20 s, this run's 3 s");
  // Before it is read: missing, a folder, too large (a sparse file), an empty path.
  const auto file_refused = [&](const std::string& path, const std::string& expected) {
    const auto out = dir / "out";
    const Result r =
        cli({"eval", "family", "--seeds", "1", "--duration", "3", "--against", path, "--out", out.string()});
    EXPECT_EQ(r.rc, 2) << path;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "expected: " << expected << "\ngot: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << "nothing written";
  };
  file_refused((dir / "none.json").string(), "none.json: no such file");
  file_refused(dir.string(), "not a regular file");
  const auto big = dir / "big.json";
  std::ofstream(big).close();
  std::filesystem::resize_file(big, kMaxBaselineBytes + 1);
  file_refused(big.string(), "big.json: larger than 256 MiB");
  file_refused("", "--against: expected a family.json, got an empty path");
}

}  // namespace
}  // namespace gazelod::cli
