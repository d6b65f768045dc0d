// The `gazelod budget` command: the contract's JSON output, exit codes and error messages.
#include "plugin/cli/command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

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
                              [{"profit": 9999, "cost": 100}]]})", "funkhouser");
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
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}], [{"profit": 1, "cost": 1}, {"profit": 2, "cost": -1}]]})",
               "subsets[1][1].cost: must be a finite number >= 0");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": "a", "cost": 1}]]})", "subsets[0][0].profit: must be a finite number");
  expect_error(R"({"capacity": 5, "subsets": [[]]})", "subsets[0]: must be a non-empty array");
  expect_error(R"({"capacity": -1, "subsets": [[{"profit": 1, "cost": 1}]]})", "capacity: must be a finite number >= 0");
  expect_error(R"({"subsets": [[{"profit": 1, "cost": 1}]]})", "capacity: missing");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1, "x": 2}]]})", "subsets[0][0].x: unknown key");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]], "groups": [{"subsets": [3]}]})",
               "groups[0].subsets[0]: must be a subset index in [0, 1)");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]], "groups": [{"subsets": [0]}, {"subsets": [0]}]})",
               "groups[1].subsets[0]: subset 0 is already in groups[0]");
  expect_error(R"({"capacity": 5, "subsets": [[{"profit": 1, "cost": 1}]] )", "JSON parse error at byte");
  const Result unknown = budget(kT2, "simplex");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("unknown solver 'simplex'"), std::string::npos);
  std::ostringstream out, err;
  EXPECT_EQ(run({"budget", "--instance", "/nonexistent/x.json", "--solver", "exact"}, out, err), 2);
  EXPECT_NE(err.str().find("cannot open"), std::string::npos);
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

}  // namespace
}  // namespace gazelod::cli
