// SPDX-License-Identifier: Apache-2.0
// The `gazelod budget` command: the contract's JSON output, exit codes and error messages.
#include "apps/gazelod/commands/command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string_view>

namespace gazelod::cli {
namespace {

struct Result {
  int code;
  std::string out, err;
};

Result budget(const std::string& json_text, const std::string& solver, bool as_json = true) {
  static int counter = 0;
  const auto path = std::filesystem::temp_directory_path() /
                    ("gazelod_budget_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".json");
  std::ofstream(path) << json_text;
  std::ostringstream out, err;
  std::vector<std::string> args{"budget", "--instance", path.string(), "--solver", solver};
  if (as_json) args.push_back("--json");
  const int code = run(args, out, err);
  std::filesystem::remove(path);
  return {code, out.str(), err.str()};
}

const char* kT2 = R"({"capacity": 1000, "subsets": [
  [{"profit": 10, "cost": 1}, {"profit": 900, "cost": 100}, {"profit": 910, "cost": 700}],
  [{"profit": 10, "cost": 1}, {"profit": 600, "cost": 500}],
  [{"profit": 10, "cost": 1}, {"profit": 400, "cost": 400}]]})";

TEST(BudgetCli, AllSolversAnswerT2) {
  for (const char* solver : {"exact", "mason-greedy", "mason-full", "mason-incremental", "mason-hierarchical"}) {
    const Result r = budget(kT2, solver);
    ASSERT_EQ(r.code, 0) << solver << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["profit"].get<double>(), 1900) << solver;
    EXPECT_EQ(j["cost"].get<double>(), 1000) << solver;
    EXPECT_EQ(j["selection"], nlohmann::json::parse("[1,1,1]")) << solver;
    EXPECT_TRUE(j["feasible"].get<bool>());
  }
  for (const char* solver : {"funkhouser", "funkhouser-incremental"}) {
    const Result r = budget(kT2, solver);
    ASSERT_EQ(r.code, 0) << solver << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["profit"].get<double>(), 930) << solver;
  }
  const Result text = budget(kT2, "exact", false);
  EXPECT_NE(text.out.find("profit:    1900"), std::string::npos) << text.out;
}

TEST(BudgetCli, FunkhouserInfeasibleAnswerIsReported) {
  const Result r = budget(R"({"capacity": 100, "subsets": [[{"profit": 0, "cost": 0}, {"profit": 100, "cost": 1}],
                              [{"profit": 9999, "cost": 100}]]})",
                          "funkhouser");
  EXPECT_EQ(r.code, 4);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["feasible"].get<bool>());
  EXPECT_TRUE(j["selection"][1].is_null());
  EXPECT_NE(r.err.find("infeasible answer"), std::string::npos) << r.err;
}

TEST(BudgetCli, InfeasibleInstanceExits3) {
  const Result r = budget(R"({"capacity": 1, "subsets": [[{"profit": 1, "cost": 2}]]})", "mason-greedy");
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("infeasible instance"), std::string::npos) << r.err;
}

TEST(BudgetCli, ErrorsNameTheJsonPath) {
  auto expect_error = [](const std::string& text, const std::string& what) {
    const Result r = budget(text, "exact");
    EXPECT_EQ(r.code, 2) << text;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  };
  expect_error(
      R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}], [{"profit": 1, "cost": 1}, {"profit": 2, "cost": -1}]]})",
      "subsets[1][1].cost: must be a finite number >= 0");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": "a", "cost": 1}]]})",
               "subsets[0][0].profit: must be a finite number");
  expect_error(R"({"capacity": 5, "subsets": [[]]})", "subsets[0]: must be a non-empty array");
  expect_error(R"({"capacity": -1, "subsets": [[{"profit": 1, "cost": 1}]]})",
               "capacity: must be a finite number >= 0");
  expect_error(R"({"subsets": [[{"profit": 1, "cost": 1}]]})", "capacity: missing");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1, "x": 2}]]})", "subsets[0][0].x: unknown key");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]], "groups": [{"subsets": [3]}]})",
               "groups[0].subsets[0]: must be a subset index in [0, 1)");
  expect_error(
      R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]], "groups": [{"subsets": [0]}, {"subsets": [0]}]})",
      "groups[1].subsets[0]: subset 0 is already in groups[0]");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]] )",
               ":1:57: JSON syntax error: syntax error while parsing object");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1, "cost": 9}]]})",
               "subsets[0][0].cost: the key appears twice in one object");
  const Result unknown = budget(kT2, "simplex");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("unknown solver 'simplex'"), std::string::npos);
  std::ostringstream out, err;
  EXPECT_EQ(run({"budget", "--instance", "/nonexistent/x.json", "--solver", "exact"}, out, err), 2);
  EXPECT_NE(err.str().find("no such file"), std::string::npos) << err.str();
  // A directory (a libstdc++ message before) and a FIFO (it would block) are named as such.
  std::ostringstream out2, err2;
  EXPECT_EQ(run({"budget", "--instance", "/tmp", "--solver", "exact"}, out2, err2), 2);
  EXPECT_NE(err2.str().find("/tmp: not a regular file"), std::string::npos) << err2.str();
}

TEST(BudgetCli, ProfitsAreAtLeastZeroAndTheirSumsDoNotOverflow) {
  // Negative profits: refused as docs/budget.md says (impostors too).
  Result r = budget(R"({"capacity": 5, "subsets": [[{"profit": -1, "cost": 1}]]})", "exact");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("subsets[0][0].profit: must be a finite number >= 0"), std::string::npos) << r.err;
  r = budget(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]],
                 "groups": [{"subsets": [0], "impostors": [{"profit": -2, "cost": 0}]}]})",
             "mason-hierarchical");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("groups[0].impostors[0].profit: must be a finite number >= 0"), std::string::npos) << r.err;
  // Profits each finite, their sum not: was "profit": null, "optimal": true, exit 0.
  for (const char* solver : {"exact", "mason-greedy", "funkhouser"}) {
    r = budget(R"({"capacity": 10, "subsets": [[{"profit": 1e308, "cost": 1}], [{"profit": 1e308, "cost": 1}]]})",
               solver);
    EXPECT_EQ(r.code, 2) << solver;
    EXPECT_NE(r.err.find("subsets: the largest profits of the subsets (and impostors) must add up to at most the "
                         "largest double, 1.8e308, got an overflow"),
              std::string::npos)
        << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["exit_code"].get<int>(), 2);
    EXPECT_EQ(j["kind"], "bad_input");
    EXPECT_FALSE(j.contains("profit"));
  }
  r = budget(R"({"capacity": 1e308, "subsets": [[{"profit": 1, "cost": 1e308}], [{"profit": 1, "cost": 1e308}]]})",
             "exact");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("subsets: the largest costs of the subsets (and impostors) must add up to at most"),
            std::string::npos)
      << r.err;
  // Text output: no "inf" left to print.
  r = budget(R"({"capacity": 10, "subsets": [[{"profit": 1e308, "cost": 1}], [{"profit": 1e308, "cost": 1}]]})",
             "exact", false);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
}

TEST(BudgetCli, JsonErrorsAreOneObjectOnStdout) {
  Result r = budget(R"({"capacity": 1, "subsets": [[{"profit": 1, "cost": 2}]]})", "mason-greedy");
  EXPECT_EQ(r.code, 3);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "infeasible_instance");
  EXPECT_EQ(j["exit_code"].get<int>(), 3);
  EXPECT_NE(
      j["error"].get<std::string>().find("infeasible instance: the cheapest level of detail costs 2 > capacity 1"),
      std::string::npos);
  EXPECT_NE(r.err.find("infeasible instance"), std::string::npos) << "stderr keeps its line";
  r = budget(kT2, "simplex");
  EXPECT_EQ(r.code, 2);
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "bad_input");
  EXPECT_NE(j["error"].get<std::string>().find("unknown solver 'simplex'"), std::string::npos);
  std::ostringstream out, err;
  EXPECT_EQ(run({"budget", "--instance", "/nonexistent/x.json", "--solver", "exact", "--json"}, out, err), 2);
  j = nlohmann::json::parse(out.str());
  EXPECT_NE(j["error"].get<std::string>().find("no such file"), std::string::npos);
  // Without --json, errors stay on stderr only.
  r = budget(R"({"capacity": 1, "subsets": [[{"profit": 1, "cost": 2}]]})", "mason-greedy", false);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.out, "");
}

TEST(BudgetCli, HierarchyOutputsGroupChoices) {
  // Fig. 27: leaves A, B, D, E; C = group 0 over D, E; the root object = group 1.
  const Result r = budget(R"({"capacity": 12, "subsets": [[{"profit": 4, "cost": 4}],
      [{"profit": 5, "cost": 5}, {"profit": 9, "cost": 9}], [{"profit": 7, "cost": 7}], [{"profit": 8, "cost": 8}]],
      "groups": [{"subsets": [2, 3], "impostors": [{"profit": 3, "cost": 3}]},
                 {"subsets": [0, 1], "groups": [0], "impostors": [{"profit": 1, "cost": 1}, {"profit": 2, "cost": 2}]}]})",
                          "mason-hierarchical");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["profit"].get<double>(), 12);
  EXPECT_EQ(j["selection"], nlohmann::json::parse("[0, 0, null, null]"));
  EXPECT_EQ(j["groups"], nlohmann::json::parse("[0, null]"));
}

// A frame-budget-like instance large enough for the incremental solvers to need many moves.
std::string big_instance() {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  nlohmann::json subsets = nlohmann::json::array();
  double lowest = 0;
  for (int k = 0; k < 300; ++k) {
    nlohmann::json items = nlohmann::json::array();
    double w = 1 + u(rng), p = 1, slope = 1 + 3 * u(rng);
    lowest += w;
    for (int j = 0; j < 5; ++j) {
      items.push_back({{"profit", p}, {"cost", w}});
      const double dw = 0.5 + 2 * u(rng);
      w += dw;
      p += slope * dw;
      slope *= 0.3 + 0.6 * u(rng);
    }
    subsets.push_back(items);
  }
  return nlohmann::json{{"capacity", 2.5 * lowest}, {"subsets", subsets}}.dump();
}

struct InstanceFile {
  explicit InstanceFile(const std::string& text)
      : path(std::filesystem::temp_directory_path() / ("gazelod_budget_det_" + std::to_string(::getpid()) + ".json")) {
    std::ofstream(path) << text;
  }
  ~InstanceFile() { std::filesystem::remove(path); }
  Result run_budget(std::vector<std::string> extra) const {
    std::vector<std::string> args{"budget", "--instance", path.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    std::ostringstream out, err;
    const int code = run(args, out, err);
    return {code, out.str(), err.str()};
  }
  std::filesystem::path path;
};

void expect_same_output_every_run(const InstanceFile& file, std::initializer_list<std::string_view> solvers) {
  for (std::string_view solver : solvers) {
    for (const bool as_json : {false, true}) {
      std::vector<std::string> args{"--solver", std::string(solver)};
      if (as_json) args.push_back("--json");
      const Result first = file.run_budget(args);
      // Funkhouser & Sequin's greedy may answer infeasibly (exit 4, the answer still printed).
      if (solver == "funkhouser")
        ASSERT_TRUE(first.code == 0 || first.code == 4) << first.err;
      else
        ASSERT_EQ(first.code, 0) << solver << first.err;
      for (int again = 0; again < 2; ++again) {
        const Result r = file.run_budget(args);
        EXPECT_EQ(r.code, first.code) << solver;
        EXPECT_EQ(r.out, first.out) << solver;
        EXPECT_EQ(r.err, first.err) << solver;
      }
    }
  }
}

TEST(BudgetCli, SameInstanceFilePrintsIdenticalOutputEveryRun) {
  // Every solver but branch and bound (too slow on this size) on a 300-object instance; then
  // every solver on T2.
  expect_same_output_every_run(InstanceFile(big_instance()), {"funkhouser", "funkhouser-incremental", "mason-greedy",
                                                              "mason-full", "mason-incremental", "mason-hierarchical"});
  expect_same_output_every_run(InstanceFile(kT2), {"exact", "funkhouser", "funkhouser-incremental", "mason-greedy",
                                                   "mason-full", "mason-incremental", "mason-hierarchical"});
}

TEST(BudgetCli, MaxMovesTruncatesDeterministically) {
  const InstanceFile file(big_instance());
  const Result full = file.run_budget({"--solver", "mason-incremental", "--json"});
  ASSERT_EQ(full.code, 0) << full.err;
  const auto fj = nlohmann::json::parse(full.out);
  EXPECT_FALSE(fj["truncated"].get<bool>());
  const auto needed = fj["moves"].get<std::uint64_t>();
  ASSERT_GT(needed, 100u);
  const Result a = file.run_budget({"--solver", "mason-incremental", "--json", "--max-moves", "50"});
  const Result b = file.run_budget({"--solver", "mason-incremental", "--json", "--max-moves", "50"});
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  const auto aj = nlohmann::json::parse(a.out);
  EXPECT_TRUE(aj["truncated"].get<bool>());
  EXPECT_TRUE(aj["feasible"].get<bool>());
  EXPECT_GE(aj["moves"].get<std::uint64_t>(), 50u);
  EXPECT_LT(aj["profit"].get<double>(), fj["profit"].get<double>());
  for (const auto& c : aj["selection"]) EXPECT_FALSE(c.is_null());
  // A limit at what the solve needs changes nothing.
  const Result same =
      file.run_budget({"--solver", "mason-incremental", "--json", "--max-moves", std::to_string(needed)});
  EXPECT_EQ(same.out, full.out);
  // Text output says so too.
  const Result text = file.run_budget({"--solver", "mason-incremental", "--max-moves", "50"});
  EXPECT_NE(text.out.find("(truncated: stopped at its limit)"), std::string::npos) << text.out;
}

TEST(BudgetCli, LimitOptionsAreChecked) {
  const InstanceFile file(kT2);
  const Result greedy = file.run_budget({"--solver", "mason-greedy", "--max-moves", "5"});
  EXPECT_EQ(greedy.code, 2);
  EXPECT_NE(greedy.err.find("--max-moves: applies to the incremental solvers only"), std::string::npos) << greedy.err;
  for (const char* bad : {"-1", "x", "1.5", "", "99999999999999999999999"}) {
    const Result r = file.run_budget({"--solver", "mason-incremental", "--max-moves", bad});
    EXPECT_EQ(r.code, 2) << bad << r.out;
  }
  const Result none = file.run_budget({"--solver", "mason-incremental", "--json", "--max-moves", "0"});
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(nlohmann::json::parse(none.out)["selection"], nlohmann::json::parse("[0,0,0]"));
  const Result bad_time = file.run_budget({"--solver", "mason-incremental", "--time-limit-ms", "nan"});
  EXPECT_EQ(bad_time.code, 2);
  EXPECT_NE(bad_time.err.find("--time-limit-ms"), std::string::npos) << bad_time.err;
  const Result neg_time = file.run_budget({"--solver", "mason-incremental", "--time-limit-ms", "-1"});
  EXPECT_EQ(neg_time.code, 2);
  // An explicit, generous time limit on a small instance: converges as without one.
  const Result timed = file.run_budget({"--solver", "mason-incremental", "--json", "--time-limit-ms", "10000"});
  ASSERT_EQ(timed.code, 0) << timed.err;
  const auto j = nlohmann::json::parse(timed.out);
  EXPECT_EQ(j["selection"], nlohmann::json::parse("[1,1,1]"));
  EXPECT_FALSE(j["truncated"].get<bool>());
}

// One subset of 50 000 candidates, none dominated: mason-full's rescans (and exact, which starts
// from its answer) would take seconds to minutes, quadratic in them; refused at once naming the
// subset, while the linear greedy solves it.
TEST(BudgetCli, QuadraticRescansAreRefusedForHugeSubsets) {
  std::string items;
  for (int i = 1; i <= 50'000; ++i)
    items += (i > 1 ? "," : "") + std::string("{\"profit\": ") + std::to_string(i) +
             ", \"cost\": " + std::to_string(i) + "}";
  const std::string instance = R"({"capacity": 1e12, "subsets": [[{"profit": 1, "cost": 1}], [)" + items + "]]}";
  for (const char* solver : {"mason-full", "exact"}) {
    const auto started = std::chrono::steady_clock::now();
    const Result r = budget(instance, solver, false);
    EXPECT_EQ(r.code, 2) << solver << r.err;
    EXPECT_NE(r.err.find("quadratic in them (subset 1 has 50000 after dominated items are dropped); use "
                         "mason-greedy or mason-incremental"),
              std::string::npos)
        << r.err;
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(20)) << solver;
  }
  EXPECT_EQ(budget(instance, "mason-greedy", false).code, 0);
}

}  // namespace
}  // namespace gazelod::cli
